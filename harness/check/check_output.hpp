// What `tritri check` shows and writes: the table, paste-ready failures, JSON, baselines.
#pragma once

#include "cases/corpus_identity.hpp"
#include "harness/check/check.hpp"
#include "harness/check/scorecard.hpp"

#include <nlohmann/json_fwd.hpp>

#include <iosfwd>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace tritri {

void print_check_table(std::ostream& out, const CheckResult& result);

// For each algorithm whose run stopped at the fault limit (IsolationOptions::max_faults): one
// line naming it, its first faulting cases and how many cases were not run. True when any did:
// the run is incomplete (the JSON's "complete" is false) and check exits 1.
bool report_incomplete(std::ostream& out, const CheckResult& result);
bool is_complete(const CheckResult& result);

// Per algorithm × family, the relation (or dimension) answered against the oracle's, as
// "answered->oracle count" cells: only the off-diagonal (wrong) cells, or every cell with
// `all_cells`. Nothing is printed when no chosen algorithm answers the relation level.
void print_confusion(std::ostream& out, const CheckResult& result, bool all_cells);

// Per algorithm × family, for algorithms answering the segment level: cases answered, error
// measured (Hausdorff distance to the exact intersection over the pair's bounding-box diagonal)
// with its median and maximum, kind mismatches and coplanar contacts given without geometry.
void print_segment_errors(std::ostream& out, const CheckResult& result);

// Up to `limit` failures, each as a comment line and the case in two paste-ready forms
// (%.17g and hex float), so it can go straight into a regression case file.
void print_failures(std::ostream& out, const CheckResult& result, std::size_t limit);

// Which part of a campaign a result is (`tritri check --shard K/N`): cases [first, end) of total.
struct ShardInfo {
  std::size_t index = 0, count = 1;
  std::size_t first = 0, end = 0, total = 0;
};

// What the JSON says beside the result: the inputs as given and their identity
// (cases/corpus_identity.hpp, as tritri bench records it too), the scorecards (scorecard.hpp),
// the shard, and the cap on failures per algorithm x family x level (--json-max-failures).
struct CheckJsonContext {
  std::vector<std::string> inputs;
  CorpusIdentity corpus;
  std::vector<Scorecard> scorecards;
  std::optional<ShardInfo> shard;
  std::optional<std::size_t> failure_cap;
  JudgeOptions judge;
};

// The JSON document described in harness/README.md (schema kCheckSchema). With groupings,
// "families" and each tally's "family" name groups (grouping.hpp), and "group_by" lists them.
inline constexpr const char* kCheckSchema = "tritri-check/3";
nlohmann::json check_json(const CheckResult& result, const CheckJsonContext& context);
void write_check_json(std::ostream& out, const CheckResult& result, const CheckJsonContext& context);
// The one way a check document is written, so that `tritri merge` writes the same bytes.
void dump_check_json(std::ostream& out, const nlohmann::json& doc);
// A tally's "segment" object: counts, median and maximum error, and the errors' summary.
nlohmann::json segment_json(const SegmentTally& segment);

// The first `cap` failures of each algorithm x family x level, in order (--json-max-failures).
std::vector<Failure> capped_failures(const std::vector<Failure>& failures, std::size_t cap);

// The JSON form of a corpus identity, the same in check's and bench's documents.
nlohmann::json corpus_json(const CorpusIdentity& corpus);

// A baseline: the disagreements with the oracle that are known and recorded, one per row:
//   algorithm <TAB> case <TAB> level <TAB> answer <TAB> oracle
using BaselineRow = std::tuple<std::string, std::string, std::string, std::string, std::string>;
using Baseline = std::set<BaselineRow>;

Baseline read_baseline(const std::string& path);  // throws CaseFileError-style messages
Baseline baseline_of(const CheckResult& result);
void write_baseline(std::ostream& out, const Baseline& baseline);

struct BaselineComparison {
  std::vector<BaselineRow> new_failures;  // in this run, not in the baseline
  std::vector<BaselineRow> fixed;         // in the baseline, not in this run
};

// Only rows of algorithms and cases that are part of this run (result.names) take part: a
// baseline may cover more algorithms and case files than one run checks.
BaselineComparison compare_with_baseline(const Baseline& recorded, const CheckResult& result);

}  // namespace tritri
