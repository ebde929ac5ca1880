// `tritri check`: every chosen algorithm against the oracle, tallied per algorithm × family.
#pragma once

#include "cases/casefile.hpp"
#include "cases/label.hpp"
#include "harness/check/error_summary.hpp"
#include "harness/check/grouping.hpp"
#include "harness/run/isolation.hpp"
#include "cases/case_stream.hpp"
#include "cases/oracle/judge.hpp"
#include "cases/oracle/oracle.hpp"
#include "tritri/algorithm.hpp"

#include <iosfwd>
#include <optional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace tritri {

// One algorithm's answers to one case, at every level it serves.
struct Answers {
  bool declined = false;  // the harness did not call it: a degenerate case it does not accept
  Fate fate = Fate::ok;   // crash or timeout: the algorithm died or hung on this case
  std::string fault;      // what happened: "SIGSEGV", "no progress for 2 s", ...
  Overlap overlap = Overlap::unsupported;
  RelationAnswer relation;
  SegmentAnswer segment;
};

// Runs one algorithm on every case (harness/run/runner.hpp). Degenerate cases are passed only to
// algorithms that accept them.
// Built-in and shared-library algorithms run in a child process (isolation.hpp) unless
// isolation is switched off: a crash or hang becomes that case's fate, and the rest is kept.
std::vector<Answers> answer_cases(const Algorithm& algorithm, const std::vector<Case>& cases,
                                  const IsolationOptions& isolation = {});

// What the answers say about overlap: the overlap level's answer, else what the relation decides,
// else what the segment implies (the judge's rules, harness/check/judge.hpp).
Overlap overlap_of(const Algorithm& algorithm, const Answers& answers);

// A disagreement with the oracle. `answer` and `expected` are the vocabulary's words. A failure
// carries its case, so results need no list of every case (a streamed check keeps none).
struct Failure {
  std::string algorithm;
  std::size_t case_index = 0;  // the case's place in the whole input (the files in order)
  Level level = Level::overlap;
  std::string answer;
  std::string expected;
  std::string detail;  // for a crash or timeout: what happened
  std::shared_ptr<const Case> subject;  // the case; shared by the failures of one case
  Relation oracle_relation = Relation::disjoint;
};

// The segment level against the exact intersection, for algorithms that answer it.
struct SegmentTally {
  std::size_t answered = 0;        // cases with a segment-level answer (not declined/unsupported)
  std::size_t kind_mismatches = 0; // the answer's dimension (empty/point/segment/area) is not the oracle's
  std::size_t not_computed = 0;    // answered `coplanar`: contact found, no intersection given
  // Where both the answer and the exact intersection are a point or a segment: the Hausdorff
  // distance between them divided by the pair's bounding-box diagonal.
  ErrorSummary errors;

  double median_error() const;  // NaN when nothing was measured
  double max_error() const;
};

// (answered, oracle) -> cases. Words as in failures: relation names, or "dim:<dimension>" when
// the algorithm states only the dimension (or the case is degenerate).
using Confusion = std::map<std::pair<std::string, std::string>, std::size_t>;

struct Tally {
  std::size_t cases = 0;
  std::size_t false_positives = 0;  // overlap 1 where the oracle says 0
  std::size_t false_negatives = 0;  // overlap 0 where the oracle says 1
  std::size_t misclassified = 0;    // relation (or dimension) differs from the oracle's
  std::size_t unsupported = 0;      // declined by the algorithm or, for degenerate input, the harness
  std::size_t crashes = 0;          // the algorithm crashed (signal, exception) on the case
  std::size_t timeouts = 0;         // the algorithm made no progress within the time limit
  std::size_t not_run = 0;          // its run stopped at the fault limit before this case
  Confusion confusion;              // relation level only; every scored case, diagonal included
  SegmentTally segment;             // segment level only
};

// into += t: every count, the confusion cells and the segment errors.
void add_tally(SegmentTally& into, const SegmentTally& t);
void add_tally(Tally& into, const Tally& t);

// The Hausdorff distance between two point sets, each a point (a == b) or a segment [a, b].
double hausdorff_distance(const Vec3<double>& a0, const Vec3<double>& a1, const Vec3<double>& b0,
                          const Vec3<double>& b1);

// The diagonal of the pair's axis-aligned bounding box: the scale segment errors are relative to.
double pair_size(const TrianglePair& pair);

// An algorithm's run that stopped at the fault limit (IsolationOptions::max_faults): its faults,
// the cases not run, of how many, and the first faulting cases as "name (detail)" words.
struct StoppedRun {
  std::string algorithm;
  std::size_t faults = 0, not_run = 0, cases = 0;
  std::string first;
};
std::optional<StoppedRun> stopped_run(const Algorithm& algorithm, const std::vector<Case>& cases,
                                      const std::vector<Answers>& answers);
// One line: the algorithm, its faults, the cases not run, the first faulting cases.
void print_stopped(std::ostream& out, const StoppedRun& run);

struct CheckResult {
  std::vector<const Algorithm*> algorithms;
  std::vector<Grouping> groupings;    // none: tallied per family (grouping.hpp)
  // The groups tallied, in order of first appearance: each case's family without groupings
  // (groups_of, grouping.hpp), else the label groups ("subsuite=scale tilt=2^-30").
  std::vector<std::string> groups;
  std::map<std::pair<std::string, std::string>, Tally> tallies;  // (algorithm, group)
  std::vector<Failure> failures;
  std::vector<StoppedRun> stopped;  // the runs stopped at the fault limit: the check is incomplete
  std::size_t case_count = 0;       // the cases checked
  JudgeKind judge = JudgeKind::oracle;
  JudgeCounts judged;               // which judge decided how many of them (cases/oracle/judge.hpp)
  CaseNames names;                  // the cases' names (sealed): which baseline rows are in this run
};

// Scores one algorithm's answers against the oracle and adds them to `result`, each case to the
// tally of each of its groups (`result.groupings`).
// `first_index` is the place of cases[0] in the whole input, when `cases` is a chunk of it.
void score(const Algorithm& algorithm, const std::vector<Case>& cases,
           const std::vector<OracleRecord>& oracle, const std::vector<Answers>& answers,
           CheckResult& result, std::size_t first_index = 0);

CheckResult run_check(const std::vector<const Algorithm*>& algorithms, const std::vector<Case>& cases,
                      const std::vector<OracleRecord>& oracle, const IsolationOptions& isolation = {},
                      const std::vector<Grouping>& groupings = {});

}  // namespace tritri
