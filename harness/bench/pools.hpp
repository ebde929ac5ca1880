// The pools of `tritri bench`, and the machinery every workload builds them with: pools of
// distinct triangle pairs, built and labelled by the oracle before anything is timed, shuffled
// once, then streamed in order by every benchmark.
//
// Why pools and not a few pairs replayed: a small pool, or one sorted by outcome, lets the branch
// predictor learn the answers and the cache hold the input, and then the ranking of the tests is
// decided by the machine rather than by the tests (the `size` workload shows how much). Every
// pool is built from a recorded seed, has no duplicate pair, and the same seed gives the same
// bytes. The workloads themselves (ratio, type, family, stage, size) are in workloads/.
#pragma once

#include "cases/casefile.hpp"
#include "cases/label.hpp"
#include "cases/util/random.hpp"
#include "cases/util/text.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

namespace tritri::bench {

inline constexpr std::size_t kDefaultPoolSize = 65536;
inline constexpr std::uint64_t kDefaultSeed = 20240601;

struct Pool {
  std::string workload;  // "ratio", "type", "family", "size"
  std::string value;     // "0.50", "point", "shared-vertex", "4096"
  std::uint64_t seed = 0;
  std::vector<TrianglePair> pairs;
  std::vector<Truth> truth;  // one per pair
  // The one level the pool's query asks (a scene's: overlap for its contacts, segment for a self
  // scene's intersection curve): each algorithm is timed there only (entries.cpp). None: at
  // every level asked for.
  std::optional<Level> query;

  std::string name() const { return workload + ":" + value; }
  std::size_t size() const { return pairs.size(); }
  std::size_t intersecting() const;
  // How many pairs an ideal plane-rejecting test decides at each stage, indexed by Stage.
  std::array<std::size_t, 5> stage_mix() const;
  std::string stage_mix_text() const;  // "plane2=123 plane1=45 coplanar=6 interval=78"
};

struct PoolOptions {
  std::size_t size = kDefaultPoolSize;
  std::uint64_t seed = kDefaultSeed;
};

// The seed of one named piece of a workload ("ratio", "type:point"), derived from the run's seed.
inline std::uint64_t sub_seed(std::uint64_t seed, const std::string& tag) { return splitmix(seed ^ fnv1a(tag)); }

// A labelled pair, before it goes into a pool.
struct Candidate {
  TrianglePair pair;
  Truth truth;
};

std::uint64_t pair_hash(const TrianglePair& p);

// Draws `count` pairs with `make` (each scrambled: random vertex and triangle order), labels them
// with the oracle, and returns the non-degenerate ones not `seen` before, in generation order,
// so the result depends on the seed only. Long draws show a progress meter named `what`.
std::vector<Candidate> draw(std::size_t count, Rng& rng, const std::function<TrianglePair(Rng&)>& make,
                            std::unordered_set<std::uint64_t>& seen, const std::string& what);

// A pool of the candidates, shuffled once with `seed`.
Pool make_pool(std::string workload, std::string value, std::uint64_t seed, std::vector<Candidate> candidates);

// A pool of the labelled `pairs` at `rows`, in that order, leaving out the degenerate ones (a
// scene's candidates and a paper's driver come labelled as a whole, and are timed in their order).
Pool pool_of_rows(std::string workload, std::string value, std::uint64_t seed, const std::vector<TrianglePair>& pairs,
                  const std::vector<Truth>& truth, const std::vector<std::size_t>& rows);

// 64-bit FNV-1a over the bytes of every pair of every pool, in order: the "corpus hash".
std::uint64_t hash_pools(const std::vector<const Pool*>& pools);

}  // namespace tritri::bench
