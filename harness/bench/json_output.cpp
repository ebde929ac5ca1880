#include "harness/bench/report.hpp"

#include "cases/util/atomic_file.hpp"
#include "cases/util/stats.hpp"
#include "harness/check/check_output.hpp"

#include "tritri/isa.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>

namespace tritri::bench {
namespace {

using nlohmann::json;

json finite_or_null(double x) { return std::isfinite(x) ? json(x) : json(); }

// Google Benchmark writes NaN for statistics of constant-zero counters (their cv): not JSON.
std::string nan_to_null(std::string text) {
  for (const char* bad : {"-NaN", "NaN", "-Infinity", "Infinity", "-inf", "inf", "-nan", "nan"}) {
    const std::string from = std::string(": ") + bad;
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) {
      const char next = at + from.size() < text.size() ? text[at + from.size()] : '\n';
      if (next == ',' || next == '\n' || next == ' ' || next == '}') text.replace(at, from.size(), ": null");
      else at += from.size();
    }
  }
  return text;
}

// The axes of an entry: algorithm, level (null for a stage), stage (null for a level), workload, mode.
json axes_json(const Entry& e) {
  return {{"name", e.name()},
          {"algorithm", e.algo},
          {"level", e.level ? json(to_string(*e.level)) : json()},
          {"stage", e.stage ? json(e.stage->name) : json()},
          {"workload", e.pool->name()},
          {"mode", e.mode ? json(to_string(*e.mode)) : json()}};
}

json result_json(const Entry& e, const Summary& summary) {
  json s = axes_json(e);
  s.update({{"pool_size", e.pool->size()}, {"wrong", e.score.wrong}, {"unsupported", e.score.unsupported},
            {"ns_per_pair", e.ns_per_pair}});
  if (!e.ns_per_pair.empty()) {
    s["ns_per_pair_median"] = median(e.ns_per_pair);
    if (const double r = summary.relative(e); std::isfinite(r)) s["relative_to_reference"] = r;
    if (std::isfinite(spread(e.ns_per_pair))) s["spread"] = spread(e.ns_per_pair);
  }
  if (!e.counters.empty()) {
    json counters;
    for (const auto& [name, count] : e.counters) counters[name] = count;
    s["path_counters"] = counters;
  }
  if (e.ops) {
    const double n = static_cast<double>(e.pool->size());
    s["ops_per_pair"] = {{"add", e.ops->add / n}, {"mul", e.ops->mul / n}, {"div", e.ops->div / n},
                         {"cmp", e.ops->cmp / n}, {"sqrt", e.ops->sqrt / n}};
  }
  return s;
}

json pool_json(const Pool& p) {
  json stages;
  const auto mix = p.stage_mix();
  for (Stage st : {Stage::plane2, Stage::plane1, Stage::coplanar, Stage::interval})
    stages[std::string(to_string(st))] = mix[static_cast<std::size_t>(st)];
  return {{"name", p.name()}, {"size", p.size()}, {"intersecting", p.intersecting()}, {"seed", hex64(p.seed)},
          {"stages", stages}};
}

json untimed_json(const Entry& e) {
  json faults = json::array();
  for (const Fault& f : e.faults)
    faults.push_back({{"pair", f.index}, {"fate", to_string(f.fate)}, {"detail", f.detail},
                      {"line", format_case(Case{e.pool->name() + "#" + std::to_string(f.index), e.pool->pairs[f.index], {}, "", 0})}});
  json u = axes_json(e);
  u.update({{"reason", e.not_timed.empty() ? "crashed or hung when checked" : e.not_timed},
            {"wrong", e.score.wrong}, {"unsupported", e.score.unsupported}, {"faults", faults}});
  return u;
}

json harness_json(const Summary& summary) {
  json shares = json::array();
  for (const auto& fs : summary.floor_shares)
    shares.push_back({{"floor", fs.floor},
                      {"test", fs.row},
                      {"mode", to_string(fs.mode)},
                      {"published", fs.published},
                      {"full_size_pools", finite_or_null(fs.share_full)},
                      {"worst_full_size_pool", fs.where_full},
                      {"all_pools", finite_or_null(fs.share)}});
  return {{"floors", summary.floors},
          {"floor_share", shares},
          {"floor_share_limit", kFloorShareLimit},
          {"spread_median", summary.spreads.empty() ? json() : json(median(summary.spreads))},
          {"spread_worst", finite_or_null(summary.worst_spread)}};
}

}  // namespace

void write_json(const std::string& path, const std::string& google_json, const RunContext& context,
                const Entries& entries, const std::vector<PlannedPool>& pools, const Summary& summary,
                const CorpusIdentity& corpus) {
  std::string text = nan_to_null(google_json);
  json doc = json::parse(text, nullptr, false);
  if (!doc.is_discarded()) {
    for (const auto& [key, value] : context) doc["context"][key] = value;
    json results = json::array(), pool_list = json::array(), untimed = json::array();
    for (const auto& e : entries.timed) results.push_back(result_json(*e, summary));
    for (const auto& p : pools) pool_list.push_back(pool_json(p.pool));
    for (const auto& e : entries.untimed) untimed.push_back(untimed_json(*e));
    // Beside the results, not among them: Google Benchmark did not time these.
    json self_timed = json::array();
    for (const auto& e : entries.self_timed) {
      json r = result_json(*e, summary);
      r["timed_by"] = "plug-in";
      self_timed.push_back(std::move(r));
    }
    json modes = json::array();
    for (Mode m : summary.modes) modes.push_back(to_string(m));
    doc["tritri"] = {{"schema", kBenchSchema},
                     {"reference", summary.reference},
                     {"reference_level", summary.reference_row.substr(summary.reference.size() + 1)},
                     {"modes", modes},
                     {"cpu_model", cpu_model()},
                     {"isa", to_string(requested_isa())},
                     {"isa_machine", to_string(machine_isa())},
                     {"not_timed", untimed},
                     {"self_timed", self_timed},
                     {"pools", pool_list},
                     {"results", results},
                     {"harness", harness_json(summary)},
                     {"corpus", corpus_json(corpus)}};
    text = doc.dump(2);
  } else {
    std::cerr << "tritri bench: warning: could not parse Google Benchmark's JSON; writing it unchanged\n";
  }
  write_file_atomically(path, [&](std::ostream& f) { f << text << '\n'; });
}

}  // namespace tritri::bench
