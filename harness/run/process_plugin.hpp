// Process plug-ins: an algorithm in any language, spoken to over a line protocol.
//
// The wire format. tritri starts the command through /bin/sh, with TRITRI_PROTOCOL=2 in its
// environment, and writes cases to its standard input, one a line:
//     name ax ay az bx by bz cx cy cz px py pz qx qy qz rx ry rz
// (the shortest decimals that read back to the exact doubles). It reads one answer a line, in
// the order of the cases:
//     name overlap [relation]
// where overlap is 0, 1 or unsupported, and relation, if the plug-in gives it, is a word of the
// relation vocabulary (disjoint, cross, touch-point, ..., parallel, unsupported). Every answer
// must carry a relation or none must. Many cases are in flight at once (tritri writes ahead
// while it reads answers), so a plug-in must answer in order and flush its output at least
// whenever it has read all the input there is. It may write anything to standard error.
//
// Protocol 2 adds, for a plug-in that reads TRITRI_PROTOCOL (a line beginning '#' is never a
// case: the case-file format makes it a comment):
//   - a greeting, the first line it writes, before any answer, every time it starts:
//         #tritri 2 [degenerate] [timing]
//     `degenerate`: it accepts zero-area triangles, and tritri passes it such pairs (otherwise
//     never); `timing`: it times itself, below. A plug-in that does not greet speaks protocol 1
//     (the case and answer lines alone), which is all that tritri 1's plug-ins spoke.
//   - timing in its own runtime: tritri writes
//         #time N REPETITIONS MIN_SECONDS
//     followed by N case lines, the pool. The plug-in reads them all into its own arrays, runs
//     its test over the pool once (its answers are the ones it then writes), warms up (whole
//     passes over the pool for MIN_SECONDS, untimed: a JIT compiles meanwhile), then
//     REPETITIONS times runs whole passes until MIN_SECONDS have passed on its runtime's
//     monotonic clock, and answers the N answer lines followed by
//         #timed NS_1 ... NS_REPETITIONS
//     the nanoseconds per pair of each repetition (its elapsed time / (passes x N)). tritri
//     checks the answers on the pool like any others and reports the times as timed in-process
//     by the plug-in (harness/bench; `tritri bench`).
//
// If the process exits, or answers nothing within the time limit, the first case it has not
// answered is recorded as a crash or a timeout, the process is started again, and the run goes
// on with the next case. An answer that breaks the protocol stops the run with a message that
// quotes it.
#pragma once

#include "harness/run/isolation.hpp"
#include "tritri/algorithm.hpp"

#include <string>
#include <vector>

namespace tritri {

struct ProcessPluginOptions {
  std::string command;
  double timeout_seconds = 5.0;  // per answer
  std::size_t max_faults = 0;    // stop after this many crashes or timeouts (IsolationOptions); 0: never
};

// What a plug-in's greeting offered (protocol 2); all false for a protocol-1 plug-in.
struct ProcessFeatures {
  bool greeted = false;
  bool degenerate = false;
  bool timing = false;
};

struct ProcessAnswers {
  std::vector<Overlap> overlap;
  std::vector<RelationAnswer> relation;
  bool answers_relation = false;
  ProcessFeatures features;
  std::vector<Fault> faults;  // cases that crashed or timed out
  std::size_t stopped_at = 0;  // the number of pairs, or the first not run at the fault limit
};

// Throws InputError (the user's command) on a protocol error; std::runtime_error when no pipe or
// process can be made.
ProcessAnswers run_process_plugin(const ProcessPluginOptions& options, const std::vector<std::string>& names,
                                  const std::vector<TrianglePair>& pairs);

// The plug-in's answers on the pool and its own times of its loop over it (the '#time' request
// above). Throws InputError when it does not offer timing, breaks the protocol, exits or does not
// finish in time.
struct SelfTimed {
  ProcessAnswers answers;
  std::vector<double> ns_per_pair;  // one per repetition, as the plug-in measured them
};
SelfTimed time_process_plugin(const ProcessPluginOptions& options, const std::vector<std::string>& names,
                              const std::vector<TrianglePair>& pairs, int repetitions, double min_seconds);

}  // namespace tritri

namespace tritri {

// Starts the command once on a probe case to learn whether it answers the relation level and
// what its greeting offers, then adds it to the registry as `name`, answering its levels
// elsewhere (Algorithm::answered_elsewhere): through the runner (runner.hpp), which finds it with
// find_process_plugin. Throws InputError if it does not answer the probe.
const Algorithm& add_process_algorithm(const std::string& command, const std::string& name,
                                       double timeout_seconds);

// What the process plug-in or process peer `name` offers in its greeting: learned from the probe
// for one added here, from a probe case run once for a registered one (a fault there offers
// nothing). All false for an algorithm that is neither.
ProcessFeatures process_features(const std::string& name);

// How to run the process plug-in added as `name`, or the registered algorithm `name` that runs as
// a process (Algorithm::process); nullptr when `name` is neither.
const ProcessPluginOptions* find_process_plugin(const std::string& name);

}  // namespace tritri
