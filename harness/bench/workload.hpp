// The workloads of `tritri bench`: what the pools are made of. A workload has a kind ("ratio"),
// values ("0.50"), a default set of values (what the bare kind asks for), and builds its pools.
// Benchmarks are named algo/level/kind:value.
//
// To add a workload: write harness/bench/workloads/<kind>.cpp defining
//   std::unique_ptr<Workload> make_<kind>_workload();
// and add its kind to the list in harness/bench/CMakeLists.txt. Nothing else changes.
#pragma once

#include "cases/corpus_identity.hpp"
#include "harness/bench/pools.hpp"
#include "tritri/algorithm.hpp"

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tritri::bench {

// What a workload builds its pools from.
struct WorkloadInput {
  PoolOptions pool;                // the default pool size, and the run's seed
  bool quick = false;              // CI: family draws from the corpus generator's quick corpus
  // family: the case files given (--cases) and how to read them; no files: the generator's.
  CorpusIdentity corpus;
  std::function<std::vector<Case>()> read_cases;
  // paper:shen03: a jgt-code checkout holding the authors' data files (--authors-code); "": none.
  std::string authors_code;
};

struct WorkloadPools {
  std::vector<Pool> pools;
  std::vector<std::pair<std::string, std::string>> context;  // extra JSON context keys
};

class Workload {
 public:
  // kind: "ratio"; usage: "ratio[:R]", for the lists of known workloads.
  Workload(std::string kind, std::string usage) : kind_(std::move(kind)), usage_(std::move(usage)) {}
  virtual ~Workload() = default;

  const std::string& kind() const { return kind_; }
  const std::string& usage() const { return usage_; }

  // The values the bare kind stands for, in the order their pools are built.
  virtual std::vector<std::string> default_values() const = 0;
  // The canonical text of one value ("0.5" -> "0.50"); throws std::invalid_argument, saying
  // what it accepts, on a value it does not know.
  virtual std::string parse_value(const std::string& value) const = 0;
  // Whether a run with no --workload includes it.
  virtual bool in_default_set(const std::vector<const Algorithm*>& /*algorithms*/) const { return true; }

  // The workload whose pools this one's benchmarks run on: its own by default. `stage` times
  // the stages on the ratio workload's pools, so it is timed on the same pairs as ratio:0.50.
  virtual std::string pools_from() const { return kind(); }
  // What is timed on its pools: every algorithm's levels, or else their registered stages.
  virtual bool times_stages() const { return false; }
  // Both: its pools time the levels and the registered stages (the paper drivers' pools).
  virtual bool times_levels_and_stages() const { return false; }
  // What its pools depend on beyond its values and the input's seed, size and cases (the
  // content of files it reads), for the pool cache's key; "" when nothing.
  virtual std::string cache_identity(const WorkloadInput& /*input*/) const { return ""; }

  // Builds the pools of `values` (canonical and distinct). Only called on the workloads that
  // other workloads' pools_from() names, or that name themselves.
  virtual WorkloadPools build(const std::vector<std::string>& values, const WorkloadInput& input) const = 0;

 private:
  std::string kind_, usage_;
};

// The texts of a list of values, text(value) each: a default_values() from the values' own list.
template <class List, class Text>
std::vector<std::string> texts_of(const List& values, Text text) {
  std::vector<std::string> out;
  for (const auto& v : values) out.push_back(text(v));
  return out;
}

// Every workload, in the order of the list in harness/bench/CMakeLists.txt.
const std::vector<std::unique_ptr<Workload>>& workloads();
const Workload* find_workload(const std::string& kind);
std::string known_workloads();  // "ratio[:R], type[:T], ..."

// The workloads of a run and their values: `specs` as given ("ratio", "ratio:0.30", "size:4096";
// empty: the default set). Throws std::invalid_argument on an unknown kind or value.
struct Selected {
  const Workload* workload = nullptr;
  std::vector<std::string> values;
};
std::vector<Selected> select_workloads(const std::vector<std::string>& specs,
                                       const std::vector<const Algorithm*>& algorithms);

// A pool, and what is timed on it: the levels (a workload of its own kind asked for it) and the
// stages (a workload timing stages did).
struct PlannedPool {
  Pool pool;
  bool levels = false;
  bool stages = false;
};
struct Planned {
  std::vector<PlannedPool> pools;
  std::vector<std::pair<std::string, std::string>> context;
  std::string cache_key;  // what the pools depend on (pool_cache.hpp); "" when not cached
};
Planned build_pools(const std::vector<Selected>& selected, const WorkloadInput& input);

}  // namespace tritri::bench
