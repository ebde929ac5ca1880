// Timing on Google Benchmark: the harness's floor, the timed loops, registration and the run.
//
// One iteration is one pass over the pool in order, in the entry's mode (bench.hpp, Mode): one
// opaque indirect call per pair, or one per batch of kBatch pairs; no allocation in the timed
// loop. Every answer is folded into a checksum that goes through benchmark::DoNotOptimize once
// per kBatch pairs.
#pragma once

#include "harness/bench/entry.hpp"

#include <string>

namespace tritri::bench {

// The harness's floor, timed when no `null` algorithm is registered and beside it when one is:
// reads every coordinate with integer XORs and returns one bit of them.
const Algorithm& harness_floor();

// Hands Google Benchmark its flags (repetitions, interleaving, times, filter, list only).
void init_google_benchmark(const Options& options);

// One benchmark per timed entry, named Entry::name().
void register_benchmarks(const EntryList& timed, int repetitions);

// Runs the benchmarks (the console shows the medians) and fills every entry's ns_per_pair.
struct TimingRun {
  std::string json;  // Google Benchmark's JSON of the run
  int errors = 0;    // benchmarks that reported an error
};
TimingRun run_benchmarks(const EntryList& timed, int repetitions);

// Prints the registered benchmarks' names (--list).
void list_benchmarks();

}  // namespace tritri::bench
