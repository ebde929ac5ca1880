// What `tritri bench` reports after timing: the summary (the reference's times, the floors'
// share, the repetitions' spread, the warnings), the console tables and the JSON.
#pragma once

#include "harness/bench/entry.hpp"

#include <iosfwd>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace tritri::bench {

// A floor's share of the fastest real algorithm's time, worst pool first.
struct FloorShare {
  std::string name;
  double share = NAN;  // over every pool
  std::string where;
  double share_full = NAN;  // over the pools of the full size (small ones are learnt)
  std::string where_full;
};

struct Summary {
  std::string reference;      // the algorithm every time is given relative to: "moller97"
  std::string reference_row;  // the level that is timed: "moller97/overlap"
  std::map<const Pool*, double> reference_ns;  // its median per pool, where it was timed
  std::vector<FloorShare> floor_shares;
  std::vector<double> spreads;  // one per benchmark with two or more repetitions
  double worst_spread = NAN;
  std::string spread_where;
  std::vector<std::string> warnings;

  // The median of `e` relative to the reference's on its pool; NaN when there is none.
  double relative(const Entry& e) const;
};

Summary summarize(const EntryList& timed, const std::vector<PlannedPool>& pools, const Lineup& lineup,
                  std::size_t pool_size);

// x with `decimals` decimals, "-" when not finite.
std::string fixed(double x, int decimals);

// Before timing: each pool's size, intersecting pairs and stage mix.
void print_pools(const std::vector<PlannedPool>& pools, std::ostream& out);
// After timing: ns per pair (and relative to the reference) per workload, operation counts.
void print_tables(const EntryList& timed, const Summary& summary, int repetitions, std::ostream& out);
// The harness's own numbers (floors' share, spread) and the warnings.
void print_harness(const Summary& summary, std::ostream& out);

// The JSON context keys of the run: build_context() and the run's provenance.
using RunContext = std::vector<std::pair<std::string, std::string>>;
RunContext run_context(const Options& options, const Planned& planned, const std::string& corpus_hash);

// Google Benchmark's JSON (NaN made null), its "context" completed with the run's `context`, and a
// "tritri" section of our summaries, written atomically. The context is added here, not through
// benchmark::AddCustomContext: that map is process-wide, keeps a key's first value for the rest of
// the process, and is left dangling by benchmark::Shutdown() (Google Benchmark 1.7), so a second
// bench in one process (the tests) read freed memory.
void write_json(const std::string& path, const std::string& google_json, const RunContext& context,
                const Entries& entries, const std::vector<PlannedPool>& pools, const Summary& summary,
                const CorpusIdentity& corpus);

}  // namespace tritri::bench
