// Process plug-ins: an algorithm in any language, spoken to over a line protocol.
//
// tritri starts the command (through /bin/sh) and, for each case, writes one line to its
// standard input:
//     name ax ay az bx by bz cx cy cz px py pz qx qy qz rx ry rz
// (the shortest decimals that read back to the exact doubles), and reads one line back:
//     name overlap [relation]
// where overlap is 0, 1 or unsupported, and relation, if the plug-in gives it, is a word of the
// relation vocabulary (disjoint, cross, touch-point, ..., parallel, unsupported). Every answer
// must carry a relation or none must. The plug-in may write anything to standard error.
//
// If the process exits, or answers nothing within the time limit, that case is recorded as a
// crash or a timeout, the process is started again, and the run goes on with the next case.
// An answer that breaks the protocol stops the run with a message that quotes it.
#pragma once

#include "harness/run/isolation.hpp"
#include "tritri/algorithm.hpp"

#include <string>
#include <vector>

namespace tritri {

struct ProcessPluginOptions {
  std::string command;
  double timeout_seconds = 5.0;  // per case
  std::size_t max_faults = 0;    // stop after this many crashes or timeouts (IsolationOptions); 0: never
};

struct ProcessAnswers {
  std::vector<Overlap> overlap;
  std::vector<RelationAnswer> relation;
  bool answers_relation = false;
  std::vector<Fault> faults;  // cases that crashed or timed out
  std::size_t stopped_at = 0;  // the number of pairs, or the first not run at the fault limit
};

// Throws InputError (the user's command) on a protocol error; std::runtime_error when no pipe or
// process can be made.
ProcessAnswers run_process_plugin(const ProcessPluginOptions& options, const std::vector<std::string>& names,
                                  const std::vector<TrianglePair>& pairs);

}  // namespace tritri

namespace tritri {

// Starts the command once on a probe case to learn whether it answers the relation level, then
// adds it to the registry as `name`, answering its levels elsewhere (Algorithm::answered_elsewhere):
// through the runner (runner.hpp), which finds it with find_process_plugin. Throws
// InputError if it does not answer the probe.
const Algorithm& add_process_algorithm(const std::string& command, const std::string& name,
                                       double timeout_seconds);

// How to run the process plug-in added as `name`; nullptr when `name` is not one.
const ProcessPluginOptions* find_process_plugin(const std::string& name);

}  // namespace tritri
