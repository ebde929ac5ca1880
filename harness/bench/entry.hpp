// What `tritri bench` times: one entry per algorithm x level (or stage) x pool, checked against
// the oracle and counted before anything is timed. Internal to harness/bench.
#pragma once

#include "harness/bench/bench.hpp"
#include "harness/bench/check_cache.hpp"
#include "harness/bench/workload.hpp"

#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tritri::bench {

struct Entry {
  std::string algo;
  const Algorithm* algorithm = nullptr;
  std::optional<Level> level;          // the level timed; unset for a stage
  const StageEntry* stage = nullptr;   // the stage timed, when it is one
  std::optional<Mode> mode;            // unset while it is only checked (and when it is not timed)
  const Pool* pool = nullptr;
  std::vector<TrianglePair> prepared;  // a stage's input when it has a prepare step
  bool floor = false;
  Score score;
  std::vector<Fault> faults;    // pairs it crashed or hung on when checked: then it is not timed
  std::string not_timed;        // why it is checked but not timed, when it is not for a fault
  std::optional<OpCounts> ops;  // totals over the pool
  CounterList counters;         // the algorithm's path counters over one pass (PathCounters)
  std::vector<double> ns_per_pair;  // one per repetition (CPU time; the plug-in's clock when timed_by_plugin)
  // Timed in-process by a process plug-in, in its own runtime (harness/run/process_plugin.hpp,
  // '#time'), not by Google Benchmark: its answers on the pool were checked all the same.
  bool timed_by_plugin = false;

  // "overlap", or "stage:NAME" for a stage: the second part of the name.
  std::string what() const { return stage ? "stage:" + stage->name : std::string(to_string(*level)); }
  std::string row() const { return algo + "/" + what(); }
  // algo/level/workload:value/mode; the check, made before the modes are set, is named without it.
  std::string name() const {
    return row() + "/" + pool->name() + (mode ? "/" + std::string(to_string(*mode)) : "");
  }
  const TrianglePair* input() const { return prepared.empty() ? pool->pairs.data() : prepared.data(); }
};
using EntryList = std::vector<std::unique_ptr<Entry>>;

// The algorithms of a run, the floors first, then the reference, then the rest.
struct Lineup {
  std::vector<const Algorithm*> algorithms;
  std::vector<const Algorithm*> floors;
  const Algorithm* reference = nullptr;
  Level reference_level = Level::overlap;  // its overlap level, or else its first answered one

  bool is_floor(const Algorithm* a) const;
  std::string reference_row() const;  // "moller97/overlap"
};

struct Entries {
  EntryList timed;
  EntryList untimed;  // checked and reported, not timed (a fault, or a process plug-in)
  EntryList self_timed;  // process plug-ins that timed themselves (Entry::timed_by_plugin)
};

// Checks every algorithm on every pool (each in a child process unless isolation is off) and
// counts the operations of its counting instantiation, per what the pool is planned for; a check
// that `checks` holds is taken from it, a new clean one is added to it.
Entries make_entries(const std::vector<PlannedPool>& pools, const Lineup& lineup, const std::vector<Level>& levels,
                     const Options& options, CheckCache& checks);

// "not timed: ..." lines, with the first pair that crashed or hung, paste-ready.
// (The self-timed entries are printed by print_self_timed, report.hpp.)
void report_untimed(const EntryList& untimed, std::ostream& out);

}  // namespace tritri::bench
