// `tritri bench`: every registered algorithm timed on every workload and level it serves, on
// Google Benchmark, with the answers checked against the oracle first and the operations counted.
//
// Names: `algo/level/workload:value/mode`, e.g. `moller97/overlap/ratio:0.50/call`, and for an
// algorithm's stages `yuhe13/stage:transform/ratio:0.50/batch`. One iteration is one pass over
// the pool in order, either one pair per out-of-line call of the algorithm's one-pair entry
// (Mode::call) or in batches of kBatch pairs through its batch entry point (Mode::batch); no
// allocation in the timed loop; every answer is folded into a checksum that goes through
// benchmark::DoNotOptimize once per kBatch pairs. Time per pair comes from items processed (one
// item = one pair) and from the `per_pair` counter. Every time is also given relative to the
// reference algorithm's on the same pool in the same mode, in the same run.
//
// The pieces: workload.hpp and workloads/ (the pools), entries.cpp (checking and counting before
// timing), timing.cpp (Google Benchmark), tables.cpp, summary.cpp, json_output.cpp, context.cpp
// (report.hpp), and run() in bench.cpp, which puts them together.
#pragma once

#include "harness/bench/pool_cache.hpp"
#include "harness/bench/pools.hpp"
#include "cases/casefile.hpp"
#include "cases/corpus_identity.hpp"
#include "harness/run/isolation.hpp"
#include "tritri/algorithm.hpp"
#include "tritri/counting.hpp"

#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace tritri::bench {

inline constexpr std::size_t kBatch = 256;

// How the timed loop hands pairs to the algorithm, an axis of every benchmark like the level and
// the workload:
//   call   one pair per call of its one-pair entry, through a pointer the compiler cannot see
//          through (as a BVH traversal calls a narrow-phase test); a C-ABI plug-in, which has no
//          one-pair entry, through its batch function with n = 1.
//   batch  the pool in batches of kBatch pairs through its batch entry (a SIMD test decides
//          several pairs per instruction). An algorithm's stages are timed in this mode only.
enum class Mode : std::uint8_t { call, batch };
inline constexpr Mode kModes[] = {Mode::call, Mode::batch};
std::string_view to_string(Mode);  // "call", "batch"
std::optional<Mode> parse_mode(std::string_view);

struct Options {
  std::vector<const Algorithm*> algorithms;  // empty: every registered algorithm
  std::vector<Level> levels;                 // empty: every level
  // "ratio", "ratio:0.30", "type", "type:point", "family", "family:NAME", "stage", "size",
  // "size:4096" (workload.hpp lists them); empty: every workload of the default set (ratio, type,
  // family and stage when an algorithm has stages; not size).
  std::vector<std::string> workloads;
  // Every time is also given relative to this algorithm's overlap level (or its first answered
  // level) on the same pool; it is always timed.
  std::string reference = "moller97";
  std::vector<Mode> modes = {Mode::call};  // in this order; `tritri bench --mode`
  std::size_t pool_size = kDefaultPoolSize;
  std::uint64_t seed = kDefaultSeed;
  int repetitions = 9;
  double min_time = 0.1;         // seconds per repetition
  double min_warmup_time = 0.02; // seconds before each repetition
  bool interleave = true;        // random interleaving of the repetitions
  std::string filter;            // regex on the names, as Google Benchmark reads it; empty: all
  std::string json_path;         // empty: no file
  // The case files of the family: workloads (their identity; the JSON records it) and how to
  // read them, called only when a pool is built from them (a cached pool needs only the
  // identity). No files: the corpus generator's cases (cases/generator), the CI corpus when
  // `quick`.
  CorpusIdentity family_corpus;
  std::function<std::vector<Case>()> read_family_cases;
  bool quick = false;
  std::string authors_code;  // a jgt-code checkout: paper:shen03 reads its data files (workloads/paper.hpp)
  bool count_operations = true;
  // Each algorithm is first run on each pool in a child process: one that crashes or hangs there
  // is reported with the pair responsible and not timed (timing runs in this process).
  IsolationOptions isolation;
  bool list_only = false;          // print the benchmark names and exit
  // Labelled pools kept between runs (pool_cache.hpp). Off unless asked for: the command
  // turns it on (--no-cache turns it off), tests and other callers get no files written.
  PoolCacheOptions cache{false, ""};
};

// Options for CI: small pools, few repetitions, short runs (seconds in all).
Options quick_options();

// Builds the pools, checks every algorithm on them, registers and runs the benchmarks, prints
// the tables to `out` and writes the JSON. Returns 0, or 1 when a benchmark failed. Throws
// std::invalid_argument on an unknown workload or reference.
int run(const Options& options, std::ostream& out);

// ---- pieces, exposed for the tests ----

// Wrong answers of one level on a pool (per the judge, harness/check/judge.hpp), and the cases the
// algorithm declined.
struct Score {
  std::size_t wrong = 0;
  std::size_t unsupported = 0;
};
Score score_overlap(const Pool& pool, const std::vector<Overlap>& answers);
Score score_relation(const Pool& pool, const std::vector<RelationAnswer>& answers);
// A segment answer is scored by what it implies about overlap (empty or not).
Score score_segment(const Pool& pool, const std::vector<SegmentAnswer>& answers);

// Operations per pair of the algorithm's counting instantiation at `level` on the pool; nullopt
// when the folder registered none for that level.
std::optional<OpCounts> count_operations(const Algorithm& algorithm, Level level, const Pool& pool);

// The context keys written into the JSON: git SHA and dirty flag, compiler and flags, CGAL, FCL
// and Eigen versions (and the rest of the run's provenance).
std::vector<std::pair<std::string, std::string>> build_context();

// The processor's model name (/proc/cpuinfo), "unknown" when it cannot be read.
std::string cpu_model();

}  // namespace tritri::bench
