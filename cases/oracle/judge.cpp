#include "cases/oracle/judge.hpp"

#include "algorithms/exact/exact.hpp"
#include "cases/util/parallel.hpp"
#include "cases/util/random.hpp"

#include <atomic>
#include <limits>

namespace tritri {
namespace {

// What `exact` says about a pair, as a record: what check and the judges of answers read.
OracleRecord exact_record(const RelationAnswer& a) {
  OracleRecord r;
  r.degenerate = a.relation == Relation::degenerate;
  r.dimension = r.degenerate ? a.dimension : dimension_of(a.relation);
  r.overlap = r.dimension != Dimension::none;
  r.relation = a.relation;
  r.separation = std::numeric_limits<double>::quiet_NaN();
  return r;
}

std::string case_where(const Case& c) { return c.source + ":" + std::to_string(c.line) + ": case '" + c.name + "'"; }

OracleRecord oracle_of(const Case& c) {
  try {
    return oracle_label(c.pair);
  } catch (const std::exception& e) {
    throw std::runtime_error(case_where(c) + ": " + e.what());
  }
}

void confirm(const Case& c, const OracleRecord& exact, const OracleRecord& oracle) {
  if (exact.overlap == oracle.overlap && exact.relation == oracle.relation && exact.dimension == oracle.dimension)
    return;
  throw JudgeDisagreement(
      case_where(c) + ": THE TWO EXACT JUDGES DISAGREE (a bug in one of them): exact says overlap " +
      std::to_string(exact.overlap) + ", relation " + std::string(to_string(exact.relation)) + ", oracle says overlap " +
      std::to_string(oracle.overlap) + ", relation " + std::string(to_string(oracle.relation)) + "; the case: " +
      format_case(c, NumberStyle::hex));
}

// One range of cases, exact first; returns how many the oracle judged and cross-checked.
std::pair<std::uint64_t, std::uint64_t> judge_range(const std::vector<Case>& cases, std::size_t begin, std::size_t end,
                                                    std::size_t first_index, const JudgeOptions& options,
                                                    std::vector<OracleRecord>& records) {
  std::vector<TrianglePair> pairs(end - begin);
  for (std::size_t i = begin; i < end; ++i) pairs[i - begin] = cases[i].pair;
  std::vector<RelationAnswer> answers(pairs.size());
  exact::relation_batch(pairs.data(), pairs.size(), answers.data());
  std::uint64_t by_oracle = 0, checked = 0;
  for (std::size_t i = begin; i < end; ++i) {
    const RelationAnswer& a = answers[i - begin];
    const OracleRecord mine = exact_record(a);
    const bool declined = a.relation == Relation::unsupported;
    const bool wants_geometry = options.geometry && (mine.dimension == Dimension::point ||
                                                     mine.dimension == Dimension::segment);
    const bool sampled = cross_checked(options.seed, options.sample_one_in, first_index + i);
    if (!declined && !wants_geometry && !sampled) {
      records[i] = mine;
      continue;
    }
    records[i] = oracle_of(cases[i]);
    if (declined) {
      ++by_oracle;
      continue;
    }
    confirm(cases[i], mine, records[i]);
    if (wants_geometry) ++by_oracle;
    else ++checked;
  }
  return {by_oracle, checked};
}

}  // namespace

const char* to_string(JudgeKind kind) { return kind == JudgeKind::oracle ? "oracle" : "exact-first"; }

JudgeKind judge_kind_of(const std::string& word) {
  if (word == "exact-first") return JudgeKind::exact_first;
  if (word == "oracle") return JudgeKind::oracle;
  throw std::invalid_argument("unknown judge '" + word + "' (exact-first or oracle)");
}

bool cross_checked(std::uint64_t seed, std::uint64_t sample_one_in, std::size_t index) {
  return sample_one_in && splitmix(seed ^ splitmix(index)) % sample_one_in == 0;
}

std::vector<OracleRecord> judge_cases(const std::vector<Case>& cases, std::size_t first_index,
                                      const JudgeOptions& options, JudgeCounts& counts) {
  std::vector<OracleRecord> records(cases.size());
  if (options.kind == JudgeKind::oracle) {
    parallel_chunks(cases.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) records[i] = oracle_of(cases[i]);
    }, {.chunk = 256});
    counts.oracle += cases.size();
    return records;
  }
  std::atomic<std::uint64_t> by_oracle{0}, checked{0};
  parallel_chunks(cases.size(), [&](std::size_t begin, std::size_t end) {
    const auto [o, c] = judge_range(cases, begin, end, first_index, options, records);
    by_oracle += o;
    checked += c;
  }, {.chunk = 1024});
  counts.oracle += by_oracle;
  counts.exact += cases.size() - by_oracle;
  counts.cross_checked += checked;
  return records;
}

}  // namespace tritri
