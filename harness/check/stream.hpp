// `tritri check` over case files of any size: the cases are read, judged, answered and scored a
// chunk at a time, so memory holds one chunk, the tallies and the failures, never every case.
#pragma once

#include "harness/check/check.hpp"

#include <functional>

namespace tritri {

struct StreamOptions {
  std::vector<Grouping> groupings;
  IsolationOptions isolation;
  JudgeOptions judge;           // exact-first, or the oracle alone (cases/oracle/judge.hpp)
  CaseRange range;              // the cases of the input to check (a shard), all by default
  std::size_t chunk = 1 << 15;  // cases in memory at a time
  // Sees each chunk after it is scored (the scorecard collects its base cases this way).
  std::function<void(const std::vector<Case>&)> on_chunk;
};

// One algorithm's run across chunks (check, answer): what is left of its fault limit, and its
// account so far (StoppedRun: faults, cases not run, the first faulting cases).
struct RunState {
  std::size_t faults_left = 0;  // with a limit: faults it may still have before its run stops
  bool stopped = false;
  StoppedRun account;
};
RunState start_run(const Algorithm& algorithm, const IsolationOptions& isolation);

// answer_cases on one chunk, the fault limit counted across chunks as in one run: once reached,
// the later cases are not run (Fate::not_run).
std::vector<Answers> answer_chunk(const Algorithm& algorithm, const std::vector<Case>& chunk,
                                  const IsolationOptions& isolation, RunState& state);

// The same result as run_check on the cases of `options.range` judged by `options.judge`; each
// failure's case_index is the case's place in the whole input. Every algorithm's fault limit
// (--max-faults) counts across chunks, as in one run: once reached, its later cases are not run.
CheckResult check_files(const std::vector<const Algorithm*>& algorithms, const std::vector<std::string>& files,
                        const StreamOptions& options);

}  // namespace tritri
