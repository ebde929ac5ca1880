// The check JSON (schema kCheckSchema, harness/README.md): what `tritri check --json` writes
// and `tritri merge` (merge.hpp) reads back and writes again.
#include "harness/check/check_output.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

namespace tritri {
namespace {

nlohmann::json algorithm_json(const Algorithm& a) {
  nlohmann::json levels = nlohmann::json::array();
  for (Level l : {Level::overlap, Level::relation, Level::segment})
    if (a.answers(l)) levels.push_back(std::string(to_string(l)));
  nlohmann::json tolerance = nullptr;
  if (!a.tolerance.none())
    tolerance = {{"value", a.tolerance.value},
                 {"quantity", a.tolerance.quantity},
                 {"relative", a.tolerance.relative}};
  return {{"name", a.name},
          {"citation", a.citation},
          {"summary", a.summary},
          {"levels", levels},
          {"boundary", a.boundary == Boundary::closed ? "closed" : "open"},
          {"tolerance", tolerance},
          {"accepts_degenerate", a.accepts_degenerate},
          {"folder", a.folder}};
}

// The groupings as they were given on the command line: "subsuite=symmetry,@base".
std::string grouping_text(const Grouping& g) {
  std::string text;
  for (const auto& [key, value] : g.keys) text += (text.empty() ? "" : ",") + key + (value ? "=" + *value : "");
  return text;
}

nlohmann::json number_or_null(double x) { return std::isnan(x) ? nlohmann::json(nullptr) : nlohmann::json(x); }

nlohmann::json tally_json(const Algorithm& a, const std::string& group, const Tally& t) {
  nlohmann::json confusion = nullptr;
  if (a.answers(Level::relation)) {
    confusion = nlohmann::json::array();
    for (const auto& [key, count] : t.confusion)
      confusion.push_back({{"answer", key.first}, {"oracle", key.second}, {"count", count}});
  }
  nlohmann::json segment = nullptr;
  if (a.answers(Level::segment)) segment = segment_json(t.segment);
  return {{"algorithm", a.name},
          {"family", group},
          {"cases", t.cases},
          {"false_positives", t.false_positives},
          {"false_negatives", t.false_negatives},
          {"misclassified", a.answers(Level::relation) ? nlohmann::json(t.misclassified) : nullptr},
          {"unsupported", t.unsupported},
          {"crashes", t.crashes},
          {"timeouts", t.timeouts},
          {"not_run", t.not_run},
          {"confusion", confusion},
          {"segment", segment}};
}

nlohmann::json failure_json(const Failure& f, const std::vector<Grouping>& groupings) {
  const Case& c = *f.subject;
  return {{"algorithm", f.algorithm},
          {"case", c.name},
          {"index", f.case_index},
          {"family", c.family()},
          {"groups", groups_of(c, groupings)},
          {"level", std::string(to_string(f.level))},
          {"answer", f.answer},
          {"oracle", f.expected},
          {"detail", f.detail},
          {"oracle_relation", std::string(to_string(f.oracle_relation))},
          {"line", format_case(c)}};
}

nlohmann::json judge_json(const CheckResult& result, const JudgeOptions& options) {
  nlohmann::json j = {{"kind", to_string(result.judge)},
                      {"exact", result.judged.exact},
                      {"oracle", result.judged.oracle},
                      {"cross_checked", result.judged.cross_checked}};
  if (result.judge == JudgeKind::exact_first)
    j["sample"] = {{"seed", options.seed}, {"one_in", options.sample_one_in}};
  return j;
}

}  // namespace

nlohmann::json segment_json(const SegmentTally& s) {
  return {{"answered", s.answered},
          {"measured", s.errors.count()},
          {"median_error", number_or_null(s.median_error())},
          {"max_error", number_or_null(s.max_error())},
          {"errors", s.errors.to_json()},
          {"kind_mismatches", s.kind_mismatches},
          {"not_computed", s.not_computed}};
}

nlohmann::json check_json(const CheckResult& result, const CheckJsonContext& context) {
  nlohmann::json doc;
  doc["schema"] = kCheckSchema;
  doc["oracle"] = oracle_description();
  doc["judge"] = judge_json(result, context.judge);
  doc["inputs"] = context.inputs;
  doc["corpus"] = corpus_json(context.corpus);
  doc["case_count"] = result.case_count;
  doc["complete"] = is_complete(result);  // false: an algorithm stopped at the fault limit
  doc["algorithms"] = nlohmann::json::array();
  for (const Algorithm* a : result.algorithms) doc["algorithms"].push_back(algorithm_json(*a));
  doc["group_by"] = nlohmann::json::array();
  for (const Grouping& g : result.groupings) doc["group_by"].push_back(grouping_text(g));
  doc["families"] = result.groups;  // the key of tritri-check/1; "group_by" says what the names are
  doc["tallies"] = nlohmann::json::array();
  for (const Algorithm* a : result.algorithms)
    for (const auto& group : result.groups)
      if (auto it = result.tallies.find({a->name, group}); it != result.tallies.end())
        doc["tallies"].push_back(tally_json(*a, group, it->second));
  doc["failures_cap"] = context.failure_cap ? nlohmann::json(*context.failure_cap) : nullptr;
  doc["failures"] = nlohmann::json::array();
  for (const Failure& f : context.failure_cap ? capped_failures(result.failures, *context.failure_cap) : result.failures)
    doc["failures"].push_back(failure_json(f, result.groupings));
  if (context.shard)
    doc["shard"] = {{"index", context.shard->index}, {"count", context.shard->count},
                    {"first_case", context.shard->first}, {"end_case", context.shard->end},
                    {"total_cases", context.shard->total}};
  if (!context.scorecards.empty()) doc["scorecards"] = scorecards_json(context.scorecards);
  return doc;
}

}  // namespace tritri
