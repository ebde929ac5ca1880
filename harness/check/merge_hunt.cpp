// Merging hunt JSON (merge.hpp; the document: harness/hunt/output.cpp, harness/README.md): the
// shards of one hunt in pairs (`tritri hunt --pairs N --shard K/N`) hold contiguous runs of its
// batches, so the one run's result is the shards' added up group by group. A group's first
// appearance is the earliest shard's (groups stay in the order of discovery: by the pair position
// of the batch that found them, then as each shard listed them); its cheapest failure, and with
// it the shrunk witness, is the cheapest over the shards, a tie going to the earlier shard as it
// does in one run. Only the clock's fields differ from one run's: the seconds of the shards are
// added, and the first failure's seconds are the earliest shard's.
#include "harness/check/merge.hpp"

#include "cases/casefile.hpp"
#include "cases/util/input_error.hpp"
#include "cases/util/stats.hpp"

#include <algorithm>
#include <map>
#include <ostream>

namespace tritri {
namespace {

using Json = nlohmann::json;

constexpr const char* kHuntSchema = "tritri-hunt/1";

const std::vector<std::string> kSameInEveryShard = {"schema", "oracle", "judge", "seed", "level", "budget", "batch",
                                                     "baselines", "shard.count", "shard.total_cases"};

std::size_t count_of(const Json& j, const char* key) { return j.at(key).get<std::size_t>(); }

// A case line of the group (its witness, or its failure as found) renamed for its place in the
// merged list, with the merged count.
std::string relabelled(const Json& line, const std::string& algorithm, std::size_t n, std::size_t count,
                       NumberStyle style) {
  Case c = parse_case_line(line.get<std::string>(), "hunt.json", 0);
  c.name = "hunt." + algorithm + "." + std::to_string(n);
  c.set_label("count", std::to_string(count));
  return format_case(c, style);
}

Json merged_groups(const std::vector<const Json*>& parts, const std::string& algorithm) {
  std::vector<Json> groups;
  std::map<std::string, std::size_t> index;  // signature -> position in groups
  for (const Json* a : parts)
    for (const Json& g : a->at("groups")) {
      const auto [it, added] = index.try_emplace(g.at("signature").get<std::string>(), groups.size());
      if (added) {
        groups.push_back(g);
        continue;
      }
      Json& m = groups[it->second];
      m["count"] = count_of(m, "count") + count_of(g, "count");
      if (count_of(g, "found_cost") < count_of(m, "found_cost"))
        for (const char* k : {"found", "found_cost", "line", "witness"}) m[k] = g.at(k);
    }
  std::stable_sort(groups.begin(), groups.end(),
                   [](const Json& x, const Json& y) { return count_of(x, "first_pairs") < count_of(y, "first_pairs"); });
  Json out = Json::array();
  for (std::size_t n = 0; n < groups.size(); ++n) {
    const std::size_t count = count_of(groups[n], "count");
    groups[n]["line"] = relabelled(groups[n].at("line"), algorithm, n + 1, count, NumberStyle::shortest);
    groups[n]["found"] = relabelled(groups[n].at("found"), algorithm, n + 1, count, NumberStyle::hex);
    out.push_back(groups[n]);
  }
  return out;
}

Json merged_algorithm(const std::vector<const Json*>& parts) {
  Json m = *parts[0];
  const std::string name = m.at("name").get<std::string>();
  for (const char* k : {"pairs", "batches", "failures", "faults", "unconfirmed"}) {
    std::size_t sum = 0;
    for (const Json* a : parts) sum += count_of(*a, k);
    m[k] = sum;
  }
  double seconds = 0, shrink_seconds = 0;
  bool stopped = false;
  m["first_failure_seconds"] = m["first_failure_pairs"] = nullptr;
  for (const Json* a : parts) {
    seconds += a->at("seconds").get<double>();
    shrink_seconds += a->at("shrink_seconds").get<double>();
    stopped = stopped || a->at("stopped").get<bool>();
    if (m["first_failure_pairs"].is_null() && !a->at("first_failure_pairs").is_null()) {
      m["first_failure_pairs"] = a->at("first_failure_pairs");
      m["first_failure_seconds"] = a->at("first_failure_seconds");
    }
  }
  m["seconds"] = seconds;
  m["shrink_seconds"] = shrink_seconds;
  m["pairs_per_second"] = seconds > 0 ? count_of(m, "pairs") / seconds : 0.0;
  m["stopped"] = stopped;
  m["groups"] = merged_groups(parts, name);
  std::size_t fresh = 0;
  std::vector<double> bits;
  for (const Json& g : m["groups"]) {
    fresh += !g.at("known").get<bool>();
    bits.push_back(g.at("witness").at("max_significant_bits").get<double>());
  }
  m["groups_new"] = fresh;
  m["median_witness_bits"] = bits.empty() ? Json(nullptr) : Json(median(bits));
  return m;
}

}  // namespace

bool is_hunt(const Json& doc) { return schema_starts_with(doc, "tritri-hunt/"); }

Json merge_hunt(const std::vector<MergePart>& parts) {
  const auto shards = shards_in_order(parts, kHuntSchema, kSameInEveryShard);
  try {
    Json doc = shards[0]->doc;
    doc.erase("shard");
    const Json& algorithms = doc.at("algorithms");
    Json merged = Json::array();
    for (std::size_t i = 0; i < algorithms.size(); ++i) {
      std::vector<const Json*> per_shard;
      for (const MergePart* p : shards) {
        const Json& list = p->doc.at("algorithms");
        if (list.size() != algorithms.size() || list[i].at("name") != algorithms[i].at("name"))
          throw InputError(p->path + ": another choice of algorithms than " + shards[0]->path +
                           ": a shard of another hunt");
        per_shard.push_back(&list[i]);
      }
      merged.push_back(merged_algorithm(per_shard));
    }
    bool complete = true;
    Json disagreements = Json::array();
    for (const MergePart* p : shards) {
      complete = complete && p->doc.at("complete").get<bool>();
      for (const Json& d : p->doc.at("exact_oracle_disagreements")) disagreements.push_back(d);
    }
    doc["algorithms"] = merged;
    doc["complete"] = complete;
    doc["exact_oracle_disagreements"] = disagreements;
    return doc;
  } catch (const Json::exception& e) {
    throw InputError(std::string("a shard is not a well-formed hunt result: ") + e.what());
  }
}

void dump_hunt_json(std::ostream& out, const Json& doc) { out << doc.dump(2) << '\n'; }

}  // namespace tritri
