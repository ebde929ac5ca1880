// Merging check JSON (merge.hpp): the shards' counts added, their errors' summaries joined
// (error_summary.hpp), their failures in the one run's order, each part of the document as
// check_json (check_json.cpp) writes it.
#include "harness/check/check_output.hpp"
#include "harness/check/merge.hpp"

#include "cases/util/input_error.hpp"

#include <algorithm>
#include <map>
#include <tuple>

namespace tritri {
namespace {

using Json = nlohmann::json;

// What must be the same in every shard of one check campaign.
const std::vector<std::string> kSameInEveryShard = {
    "schema", "oracle", "judge.kind", "judge.sample", "inputs", "corpus.hash", "algorithms",
    "group_by", "failures_cap", "shard.count", "shard.total_cases"};

SegmentTally segment_of(const Json& s) {
  SegmentTally t;
  t.answered = s.at("answered").get<std::size_t>();
  t.kind_mismatches = s.at("kind_mismatches").get<std::size_t>();
  t.not_computed = s.at("not_computed").get<std::size_t>();
  const std::size_t measured = s.at("measured").get<std::size_t>();
  t.errors = ErrorSummary::from_json(s.at("errors"), measured, measured ? s.at("max_error").get<double>() : 0.0);
  return t;
}

Json confusion_sum(const Json& a, const Json& b) {
  if (a.is_null()) return a;
  std::map<std::pair<std::string, std::string>, std::size_t> cells;
  for (const Json* side : {&a, &b})
    for (const Json& c : *side) cells[{c.at("answer"), c.at("oracle")}] += c.at("count").get<std::size_t>();
  Json out = Json::array();
  for (const auto& [key, count] : cells) out.push_back({{"answer", key.first}, {"oracle", key.second}, {"count", count}});
  return out;
}

// a + b, key by key: counts add, names stay, confusion cells and segment summaries join.
Json tally_sum(Json a, const Json& b) {
  for (auto& [key, value] : a.items()) {
    if (key == "confusion") {
      value = confusion_sum(value, b.at(key));
    } else if (key == "segment" && !value.is_null()) {
      SegmentTally s = segment_of(value);
      add_tally(s, segment_of(b.at(key)));
      value = segment_json(s);
    } else if (value.is_number_unsigned()) {
      value = value.get<std::size_t>() + b.at(key).get<std::size_t>();
    }
  }
  return a;
}

Json merged_tallies(const std::vector<const MergePart*>& shards, const Json& algorithms, const Json& families) {
  std::map<std::pair<std::string, std::string>, Json> sums;
  for (const MergePart* p : shards)
    for (const Json& t : p->doc.at("tallies")) {
      const auto [it, first] = sums.try_emplace({t.at("algorithm"), t.at("family")}, t);
      if (!first) it->second = tally_sum(it->second, t);
    }
  Json out = Json::array();
  for (const Json& a : algorithms)
    for (const Json& f : families)
      if (auto it = sums.find({a.at("name"), f}); it != sums.end()) out.push_back(it->second);
  return out;
}

// The one run's order (algorithm, then case), and its cap per algorithm x family x level.
Json merged_failures(const std::vector<const MergePart*>& shards, const Json& algorithms, const Json& cap) {
  std::map<std::string, std::size_t> position;
  for (const Json& a : algorithms) position.emplace(a.at("name"), position.size());
  std::vector<const Json*> all;
  for (const MergePart* p : shards)
    for (const Json& f : p->doc.at("failures")) all.push_back(&f);
  std::stable_sort(all.begin(), all.end(), [&](const Json* x, const Json* y) {
    return std::pair(position.at(x->at("algorithm")), x->at("index").get<std::size_t>()) <
           std::pair(position.at(y->at("algorithm")), y->at("index").get<std::size_t>());
  });
  std::map<std::tuple<std::string, std::string, std::string>, std::size_t> seen;
  Json out = Json::array();
  for (const Json* f : all)
    if (cap.is_null() || seen[{f->at("algorithm"), f->at("family"), f->at("level")}]++ < cap.get<std::size_t>())
      out.push_back(*f);
  return out;
}

}  // namespace

Json merge_check(const std::vector<MergePart>& parts) {
  const auto shards = shards_in_order(parts, kCheckSchema, kSameInEveryShard);
  try {
    Json doc = shards[0]->doc;
    doc.erase("shard");
    doc.erase("scorecards");
    Json families = Json::array();
    std::size_t cases = 0;
    bool complete = true;
    for (const MergePart* p : shards) {
      for (const Json& f : p->doc.at("families"))
        if (std::find(families.begin(), families.end(), f) == families.end()) families.push_back(f);
      cases += p->doc.at("case_count").get<std::size_t>();
      complete = complete && p->doc.at("complete").get<bool>();
      if (p->doc.contains("scorecards")) doc["scorecards"] = p->doc["scorecards"];
      if (p != shards[0])
        for (const char* k : {"exact", "oracle", "cross_checked"})
          doc["judge"][k] = doc["judge"][k].get<std::size_t>() + p->doc.at("judge").at(k).get<std::size_t>();
    }
    doc["families"] = families;
    doc["case_count"] = cases;
    doc["complete"] = complete;
    doc["tallies"] = merged_tallies(shards, doc.at("algorithms"), families);
    doc["failures"] = merged_failures(shards, doc.at("algorithms"), doc.at("failures_cap"));
    return doc;
  } catch (const Json::exception& e) {
    throw InputError(std::string("a shard is not a well-formed check result: ") + e.what());
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("a shard's segment errors: ") + e.what());
  }
}

}  // namespace tritri
