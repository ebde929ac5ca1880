// Running any algorithm on a batch of pairs, one entry point for check and bench alike: its batch
// entry points in a child process (isolation.hpp), or a process plug-in over its line protocol.
#pragma once

#include "harness/run/isolation.hpp"
#include "tritri/algorithm.hpp"

#include <string>
#include <vector>

namespace tritri {

struct RunAnswers {
  // One answer per pair at each level asked for that the algorithm answers; empty otherwise.
  std::vector<Overlap> overlap;
  std::vector<RelationAnswer> relation;
  std::vector<SegmentAnswer> segment;
  std::vector<Fault> faults;  // pairs it crashed or hung on; their answers are the defaults
  // The number of pairs, or the first pair not run: the run stopped after
  // IsolationOptions::max_faults faults, and the pairs from here on have no answer.
  std::size_t stopped_at = 0;
};

// Answers `pairs` at the levels of `levels` the algorithm answers. `names` name the pairs for an
// algorithm reached over a protocol that quotes them (harness/run/process_plugin.hpp), which
// answers every level it can at once. Throws what the protocol throws.
RunAnswers run_algorithm(const Algorithm& algorithm, const std::vector<std::string>& names,
                         const std::vector<TrianglePair>& pairs, LevelSet levels,
                         const IsolationOptions& isolation = {});

}  // namespace tritri
