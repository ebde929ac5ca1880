// `tritri hunt`: search out one algorithm's failures beyond the corpus (search.hpp), judge every
// candidate with the `exact` algorithm in batch, confirm each failure with the CGAL oracle, group
// the failures by a signature and shrink one witness per group (shrink.hpp).
//
// Deterministic for a seed when the budget is a number of pairs: batch k is drawn from
// stream_seed(seed, "hunt", k) alone, and shrinking takes no time limit unless one is given. With
// a budget in seconds the pairs tried depend on the machine's speed; each batch is still the same.
#pragma once

#include "harness/hunt/search.hpp"
#include "harness/hunt/shrink.hpp"
#include "harness/run/isolation.hpp"
#include "tritri/algorithm.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace tritri::hunt {

struct HuntOptions {
  std::uint64_t seed = 1;
  double seconds = 60;                // the search's budget, unless `pairs` is set
  std::optional<std::size_t> pairs;   // a budget in pairs: deterministic
  Level level = Level::overlap;       // the level judged: overlap, or relation
  std::size_t batch = 4096;           // candidates per batch
  // A shard of a hunt in pairs (`--shard K/N`): batches [first_batch, end_batch) of the whole
  // run's. Pair positions (first_pairs, first_failure_pairs) stay the whole run's, so the shards'
  // results merge into the one run's (tritri merge).
  std::size_t first_batch = 0;
  std::optional<std::size_t> end_batch;
  int shrink_rounds = 64;             // per witness
  // The shrinking's budget over all groups, from the search's end: groups shrink in order of
  // discovery, and those the budget does not reach keep their found pair (Group::shrink_cut).
  // Unset: no limit (a budget in pairs stays deterministic).
  std::optional<double> shrink_seconds;
  IsolationOptions isolation;         // max_faults counts over the whole hunt
  std::set<std::string> known;        // signatures of a baseline: reported, not shrunk, not new
  // Called after every batch: pairs tried, groups, confirmed failures, seconds.
  std::function<void(std::size_t, std::size_t, std::size_t, double)> progress;
};

// What a failure looks like: the oracle's relation, the answer, the configuration and the
// transformation of a base candidate that broke it (`none` when the base itself failed).
struct Signature {
  std::string level;      // "overlap" or "relation"
  std::string answer;     // the judged word ("1", "0", a relation, "dim:point"), or crash/timeout
  std::string oracle;     // the oracle's relation
  std::string plane;      // coplanar, parallel, near_parallel (normals within 2^-20 rad), general
  std::string shared;     // none, vertex, edge (T2's vertices equal to T1's)
  std::string scale;      // tiny (largest |coordinate| < 2^-20), unit, huge (> 2^20)
  std::string transform;  // to_string(Transform)
  std::string key() const;  // "level=.. answer=.. oracle=.. plane=.. shared=.. scale=.. transform=.."
};

struct Group {
  Signature signature;
  std::size_t count = 0;           // confirmed failures with this signature
  double first_seconds = 0;        // search time at its first failure
  std::size_t first_pairs = 0;     // pairs tried before its batch (in the whole run, for a shard)
  std::string source;              // the generator of its first failure
  std::string detail;              // a crash's or timeout's description
  bool known = false;              // in the baseline
  TrianglePair found;              // its cheapest failure (pair_cost) as found: where shrinking starts
  TrianglePair witness;            // shrunk (the found pair for faults and known groups)
  int shrink_steps = 0;
  bool shrink_cut = false;         // the shrinking's time budget ran out before this witness was done
  bool confirmed_witness = true;   // the oracle agrees the witness fails (shrinking judged by exact)
};

struct HuntResult {
  std::string algorithm;
  std::size_t pairs = 0;           // candidates tried
  std::size_t batches = 0;
  std::size_t failures = 0;        // confirmed by the oracle, faults included
  std::size_t faults = 0;          // crashes and timeouts
  std::size_t unconfirmed = 0;     // exact said wrong, the oracle said right: exact's bug, listed
  double seconds = 0;              // the search
  double shrink_seconds = 0;
  std::optional<double> first_failure_seconds;
  std::optional<std::size_t> first_failure_pairs;
  bool stopped = false;            // at the fault limit
  std::vector<Group> groups;       // in order of discovery
  std::vector<TrianglePair> exact_oracle_disagreements;  // should stay empty
};

// Throws std::invalid_argument when options.level is relation and `algorithm` does not answer it
// (check_level); overlap is judged for every algorithm, as check derives it (overlap_of).
void check_level(const Algorithm& algorithm, Level level);
HuntResult run_hunt(const Algorithm& algorithm, const HuntOptions& options);

// Part k of n of a hunt in pairs (options.pairs set): contiguous batches, set in `options`.
// Returns the part's pairs [first, end) of the whole run's.
std::pair<std::size_t, std::size_t> take_shard(HuntOptions& options, std::size_t k, std::size_t n);

// The signature's configuration fields of a pair (plane, shared, scale) with the oracle's relation.
Signature signature_of(const TrianglePair& pair, Relation oracle, Level level, std::string answer, Transform t);

}  // namespace tritri::hunt
