// The workloads of `tritri bench`: pools of distinct triangle pairs, built and labelled by the
// oracle before anything is timed, shuffled once, then streamed in order by every benchmark.
//
// Why pools and not a few pairs replayed: a small pool, or one sorted by outcome, lets the branch
// predictor learn the answers and the cache hold the input, and then the ranking of the tests is
// decided by the machine rather than by the tests (../shared/notes/style.md, "Benchmark
// hygiene"). Every pool here is at least as large as asked (default 65,536 pairs), has no
// duplicate pair, and is built from a recorded seed, so the same seed gives the same bytes.
//
//   ratio:R   random pairs of triangles of mixed sizes (so that every exit stage of a
//             plane-rejecting test occurs: plane2, plane1, coplanar, interval) with exactly
//             round(R·n) intersecting per the oracle. The intersecting and the disjoint pairs
//             are drawn from one labelled candidate set per seed, so the pools differ only in
//             their ratio: the mixture within each class is the same at every R.
//   type:T    only pairs whose intersection, per the oracle, has dimension T: disjoint (none),
//             point, segment or area (Sabharwal–Leopold's Table 1). Contacts are constructed
//             exactly in dyadic coordinates, so a "point" pair really touches in one point.
//   family:F  one pool per family of a set of cases (case files, or the corpus generator).
#pragma once

#include "cases/casefile.hpp"
#include "cases/label.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace tritri::bench {

inline constexpr std::size_t kDefaultPoolSize = 65536;
inline constexpr std::uint64_t kDefaultSeed = 20240601;

struct Pool {
  std::string workload;  // "ratio", "type", "family"
  std::string value;     // "0.50", "point", "shared-vertex"
  std::uint64_t seed = 0;
  std::vector<TrianglePair> pairs;
  std::vector<Truth> truth;  // one per pair

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

// The ratio values of the papers' plots: 0, 0.1, ..., 1.
std::vector<double> default_ratios();
std::string ratio_text(double r);  // "0.50"

// Pools for each ratio in `ratios` (each in [0, 1]).
std::vector<Pool> ratio_pools(const std::vector<double>& ratios, const PoolOptions& options);

// The four intersection types, in Sabharwal–Leopold's order.
inline constexpr Dimension kTypes[] = {Dimension::none, Dimension::point, Dimension::segment,
                                       Dimension::area};
std::string type_text(Dimension d);  // "disjoint", "point", "segment", "area"
Pool type_pool(Dimension type, const PoolOptions& options);

// One pool per family (Case::family()) of `cases`, e.g. read from case files or made by the
// corpus generator: duplicates and degenerate pairs dropped (the timed algorithms need not accept
// zero-area triangles), shuffled once with the seed. A family smaller than options.size stays as
// it is (it is never replayed to fill the pool); the caller warns about small pools.
std::vector<Pool> family_pools(const std::vector<Case>& cases, const PoolOptions& options);

// 64-bit FNV-1a over the bytes of every pair of every pool, in order: the "corpus hash".
std::uint64_t hash_pools(const std::vector<const Pool*>& pools);
std::string hex64(std::uint64_t x);

}  // namespace tritri::bench
