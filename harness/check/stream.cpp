#include "harness/check/stream.hpp"

#include "cases/util/progress.hpp"

#include <algorithm>

namespace tritri {
namespace {

constexpr const char* kNotRun = "not run: the run stopped at the fault limit (--max-faults)";

}  // namespace

RunState start_run(const Algorithm& algorithm, const IsolationOptions& isolation) {
  RunState run;
  run.faults_left = isolation.max_faults;
  run.account.algorithm = algorithm.name;
  return run;
}

std::vector<Answers> answer_chunk(const Algorithm& algorithm, const std::vector<Case>& chunk,
                                  const IsolationOptions& isolation, RunState& state) {
  std::vector<Answers> answers(chunk.size());
  if (state.stopped) {
    for (std::size_t i = 0; i < chunk.size(); ++i) {
      if (!algorithm.accepts_degenerate && has_degenerate_triangle(chunk[i].pair)) answers[i].declined = true;
      else answers[i].fate = Fate::not_run, answers[i].fault = kNotRun;
    }
  } else {
    IsolationOptions limited = isolation;
    if (isolation.max_faults) limited.max_faults = state.faults_left;
    answers = answer_cases(algorithm, chunk, limited);
  }
  state.account.cases += chunk.size();
  for (std::size_t i = 0; i < chunk.size(); ++i) {
    const Answers& a = answers[i];
    if (a.fate == Fate::not_run) {
      ++state.account.not_run;
      state.stopped = true;
    } else if (a.fate != Fate::ok) {
      if (state.account.faults++ < 3) state.account.first += " " + chunk[i].name + " (" + a.fault + ")";
      if (isolation.max_faults && --state.faults_left == 0) state.stopped = true;
    }
  }
  return answers;
}

CheckResult check_files(const std::vector<const Algorithm*>& algorithms, const std::vector<std::string>& files,
                        const StreamOptions& options) {
  CheckResult result;
  result.algorithms = algorithms;
  result.groupings = options.groupings;
  result.judge = options.judge.kind;
  std::vector<RunState> runs;
  for (const Algorithm* a : algorithms) runs.push_back(start_run(*a, options.isolation));
  // Failures are gathered per algorithm and joined at the end, in run_check's order.
  std::vector<std::vector<Failure>> failures(algorithms.size());
  CaseStream stream(files, options.range);
  std::vector<Case> chunk;
  Progress progress("checking", options.range.end - options.range.first < std::size_t(1) << 40
                                    ? options.range.end - options.range.first : 0);
  while (stream.next(chunk, options.chunk)) {
    const std::size_t first = stream.first();
    result.case_count += chunk.size();
    for (const Case& c : chunk)
      for (const std::string& group : groups_of(c, result.groupings))
        if (std::find(result.groups.begin(), result.groups.end(), group) == result.groups.end())
          result.groups.push_back(group);
    const auto records = judge_cases(chunk, first, options.judge, result.judged);
    for (std::size_t k = 0; k < algorithms.size(); ++k) {
      const auto answers = answer_chunk(*algorithms[k], chunk, options.isolation, runs[k]);
      std::swap(result.failures, failures[k]);
      score(*algorithms[k], chunk, records, answers, result, first);
      std::swap(result.failures, failures[k]);
    }
    if (options.on_chunk) options.on_chunk(chunk);
    progress.update(result.case_count);
  }
  progress.finish();
  for (std::size_t k = 0; k < algorithms.size(); ++k) {
    result.failures.insert(result.failures.end(), std::make_move_iterator(failures[k].begin()),
                           std::make_move_iterator(failures[k].end()));
    if (runs[k].account.not_run) result.stopped.push_back(runs[k].account);
  }
  result.names = stream.take_names();
  return result;
}

}  // namespace tritri
