#include "harness/hunt/output.hpp"

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"
#include "cases/util/input_error.hpp"
#include "cases/util/stats.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <ostream>

namespace tritri::hunt {
namespace {

constexpr const char* kSchema = "tritri-hunt/1";

Case witness_case(const HuntResult& r, const Group& g, std::size_t n) {
  Case c;
  c.name = "hunt." + r.algorithm + "." + std::to_string(n);
  c.pair = g.witness;
  const Signature& s = g.signature;
  c.labels = {{"expect", s.oracle},   {"algorithm", r.algorithm}, {"answered", s.answer},
              {"level", s.level},     {"plane", s.plane},         {"shared", s.shared},
              {"scale", s.scale},     {"transform", s.transform}, {"count", std::to_string(g.count)}};
  return c;
}

nlohmann::json witness_json(const Group& g) {
  const WitnessSize size = witness_size(g.witness);
  return {{"cost", size.cost},
          {"max_significant_bits", size.max_significant_bits},
          {"max_abs", size.max_abs},
          {"integers", size.integers},
          {"distinct", size.distinct},
          {"small", size.small()},
          {"shrink_steps", g.shrink_steps},
          {"shrink_cut", g.shrink_cut},
          {"confirmed", g.confirmed_witness}};
}

nlohmann::json group_json(const HuntResult& r, const Group& g, std::size_t n) {
  const Signature& s = g.signature;
  Case found = witness_case(r, g, n);
  found.pair = g.found;
  return {{"signature", s.key()},  {"level", s.level},     {"answer", s.answer},
          {"oracle", s.oracle},     {"plane", s.plane},     {"shared", s.shared},
          {"scale", s.scale},       {"transform", s.transform},
          {"count", g.count},       {"first_seconds", g.first_seconds},
          {"first_pairs", g.first_pairs},                   {"source", g.source},
          {"detail", g.detail},     {"known", g.known},
          {"line", format_case(witness_case(r, g, n), NumberStyle::shortest)},
          {"found", format_case(found, NumberStyle::hex)},  {"found_cost", pair_cost(g.found)},
          {"witness", witness_json(g)}};
}

template <class T>
nlohmann::json or_null(const std::optional<T>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json algorithm_json(const HuntResult& r) {
  nlohmann::json groups = nlohmann::json::array();
  std::vector<double> bits;
  for (std::size_t n = 0; n < r.groups.size(); ++n) {
    groups.push_back(group_json(r, r.groups[n], n + 1));
    bits.push_back(witness_size(r.groups[n].witness).max_significant_bits);
  }
  return {{"name", r.algorithm},
          {"pairs", r.pairs},
          {"batches", r.batches},
          {"seconds", r.seconds},
          {"pairs_per_second", r.seconds > 0 ? r.pairs / r.seconds : 0.0},
          {"shrink_seconds", r.shrink_seconds},
          {"failures", r.failures},
          {"faults", r.faults},
          {"unconfirmed", r.unconfirmed},
          {"first_failure_seconds", or_null(r.first_failure_seconds)},
          {"first_failure_pairs", or_null(r.first_failure_pairs)},
          {"stopped", r.stopped},
          {"groups_new", new_groups(r)},
          {"median_witness_bits", bits.empty() ? nlohmann::json(nullptr) : nlohmann::json(median(bits))},
          {"groups", groups}};
}

}  // namespace

std::size_t new_groups(const HuntResult& result) {
  std::size_t n = 0;
  for (const Group& g : result.groups) n += !g.known;
  return n;
}

void write_witnesses(std::ostream& out, const std::vector<HuntResult>& results, const HuntRun& run) {
  out << "# tritri hunt witnesses (seed " << run.seed << ", level " << run.level
      << "): one line a group of failures, shrunk; expect= is the oracle's relation, answered= what\n"
         "# the algorithm said, count= how many failures the group had.\n";
  for (const HuntResult& r : results)
    for (std::size_t n = 0; n < r.groups.size(); ++n)
      out << format_case(witness_case(r, r.groups[n], n + 1), NumberStyle::shortest) << '\n';
}

nlohmann::json hunt_json(const std::vector<HuntResult>& results, const HuntRun& run) {
  nlohmann::json algorithms = nlohmann::json::array();
  nlohmann::json disagreements = nlohmann::json::array();
  bool complete = true;
  for (const HuntResult& r : results) {
    algorithms.push_back(algorithm_json(r));
    complete = complete && !r.stopped;
    for (const TrianglePair& p : r.exact_oracle_disagreements) {
      Case c;
      c.name = "exact-vs-oracle";
      c.pair = p;
      disagreements.push_back(format_case(c, NumberStyle::hex));
    }
  }
  nlohmann::json doc = {{"schema", kSchema},
          {"oracle", oracle_description()},
          {"judge", "exact (batch); every failure confirmed by the oracle"},
          {"seed", run.seed},
          {"level", run.level},
          {"budget",
           {{"seconds", or_null(run.seconds)}, {"pairs", or_null(run.pairs)}, {"shrink_seconds", or_null(run.shrink_seconds)}}},
          {"batch", run.batch},
          {"baselines", run.baselines},
          {"complete", complete},
          {"algorithms", algorithms},
          {"exact_oracle_disagreements", disagreements}};
  // The fields tritri merge checks (harness/check/merge.hpp), in candidate pairs.
  if (run.shard)
    doc["shard"] = {{"index", run.shard->index},
                    {"count", run.shard->count},
                    {"first_case", run.shard->first},
                    {"end_case", run.shard->end},
                    {"total_cases", run.shard->total}};
  return doc;
}

std::map<std::string, std::set<std::string>> read_hunt_baseline(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open for reading");
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path + ": not valid JSON (" + e.what() + ")");
  }
  if (!doc.is_object() || doc.value("schema", "") != kSchema || !doc.contains("algorithms"))
    throw InputError(path + ": not a 'tritri hunt' result (schema " + std::string(kSchema) + ")");
  std::map<std::string, std::set<std::string>> known;
  for (const auto& a : doc["algorithms"]) {
    auto& keys = known[a.at("name").get<std::string>()];
    for (const auto& g : a.at("groups")) keys.insert(g.at("signature").get<std::string>());
  }
  return known;
}

}  // namespace tritri::hunt
