#include "cases/label.hpp"

#include "cases/util/parallel.hpp"

#include <stdexcept>
#include <string>

namespace tritri {

Truth truth_of(const OracleRecord& r) {
  return {r.overlap, r.degenerate, r.degenerate ? Relation::degenerate : r.relation, r.dimension, r.stage};
}

std::vector<OracleRecord> label_cases(const std::vector<Case>& cases, const LabelProgress& progress) {
  std::vector<OracleRecord> records(cases.size());
  parallel_chunks(cases.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      try {
        records[i] = oracle_label(cases[i].pair);
      } catch (const std::exception& e) {
        throw std::runtime_error(cases[i].source + ":" + std::to_string(cases[i].line) + ": case '" +
                                 cases[i].name + "': " + e.what());
      }
    }
  }, {.chunk = 256, .progress = progress});
  return records;
}

std::vector<Truth> label_pairs(const std::vector<TrianglePair>& pairs, const LabelProgress& progress) {
  std::vector<Truth> truth(pairs.size());
  parallel_chunks(pairs.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) truth[i] = truth_of(oracle_label(pairs[i]));
  }, {.chunk = 512, .progress = progress});
  return truth;
}

}  // namespace tritri
