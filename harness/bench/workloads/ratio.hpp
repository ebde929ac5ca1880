// The ratio workload, and the pieces of it the size workload and the tests use.
//
//   ratio:R   random pairs of triangles of mixed sizes (so that every exit stage of a
//             plane-rejecting test occurs: plane2, plane1, coplanar, interval) with exactly
//             round(R·n) intersecting per the oracle. The intersecting and the disjoint pairs
//             are drawn from one labelled candidate set per seed, so the pools differ only in
//             their ratio: the mixture within each class is the same at every R.
#pragma once

#include "harness/bench/pools.hpp"

#include <string>
#include <vector>

namespace tritri::bench {

// The ratio values of the papers' plots: 0, 0.1, ..., 1.
std::vector<double> default_ratios();
std::string ratio_text(double r);  // "0.50"

// The labelled candidates of the ratio pools, each class in generation order: the first k of
// `yes` and the first n - k of `no` make a pool of n at ratio k/n, whatever the other pools.
struct RatioCandidates {
  std::vector<Candidate> yes, no;
};
// At least `need_yes` intersecting and `need_no` disjoint candidates, drawn from the run's seed;
// `what` names them on the progress meter.
RatioCandidates ratio_candidates(std::size_t need_yes, std::size_t need_no, std::uint64_t seed,
                                 const std::string& what);
// The pool of n pairs at ratio r from the candidates, named workload:value, shuffled with `seed`.
Pool ratio_pool(const RatioCandidates& candidates, double r, std::size_t n, std::string workload, std::string value,
                std::uint64_t seed);
// round(r·n): the intersecting pairs of a pool of n at ratio r.
std::size_t intersecting_of(double r, std::size_t n);

// Pools for each ratio in `ratios` (each in [0, 1]).
std::vector<Pool> ratio_pools(const std::vector<double>& ratios, const PoolOptions& options);

}  // namespace tritri::bench
