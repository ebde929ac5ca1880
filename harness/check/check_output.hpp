// What `tritri check` shows and writes: the table, paste-ready failures, JSON, baselines.
#pragma once

#include "cases/corpus_identity.hpp"
#include "harness/check/check.hpp"
#include "harness/check/scorecard.hpp"

#include <nlohmann/json_fwd.hpp>

#include <iosfwd>
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
void print_failures(std::ostream& out, const CheckResult& result, const std::vector<Case>& cases,
                    std::size_t limit);

// The JSON document described in harness/README.md (schema "tritri-check/2"). With groupings,
// "families" and each tally's "family" name groups (grouping.hpp), and "group_by" lists them.
// With scorecards (tritri check --scorecard), "scorecards" holds them (scorecard.hpp).
// "corpus" is the identity of the input files (cases/corpus_identity.hpp), as tritri bench
// records it too.
void write_check_json(std::ostream& out, const CheckResult& result, const std::vector<Case>& cases,
                      const std::vector<OracleRecord>& oracle, const std::vector<std::string>& inputs,
                      const std::vector<Scorecard>& scorecards = {}, const CorpusIdentity& corpus = {});

// The JSON form of a corpus identity, the same in check's and bench's documents.
nlohmann::json corpus_json(const CorpusIdentity& corpus);

// A baseline: the disagreements with the oracle that are known and recorded, one per row:
//   algorithm <TAB> case <TAB> level <TAB> answer <TAB> oracle
using BaselineRow = std::tuple<std::string, std::string, std::string, std::string, std::string>;
using Baseline = std::set<BaselineRow>;

Baseline read_baseline(const std::string& path);  // throws CaseFileError-style messages
Baseline baseline_of(const CheckResult& result, const std::vector<Case>& cases);
void write_baseline(std::ostream& out, const Baseline& baseline);

struct BaselineComparison {
  std::vector<BaselineRow> new_failures;  // in this run, not in the baseline
  std::vector<BaselineRow> fixed;         // in the baseline, not in this run
};

// Only rows of algorithms and cases that are part of this run take part: a baseline may cover
// more algorithms and case files than one run checks.
BaselineComparison compare_with_baseline(const Baseline& recorded, const CheckResult& result,
                                         const std::vector<Case>& cases);

}  // namespace tritri
