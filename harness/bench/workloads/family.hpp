// The family workload: one pool per family of a set of cases.
//
//   family:F  the cases of family F (Case::family()): of case files given with --cases, or else of
//             the corpus generator (cases/generator). What singular and near-singular input
//             costs. Its default set is every family of those cases ("*").
#pragma once

#include "harness/bench/workload.hpp"

#include <vector>

namespace tritri::bench {

// One pool per family (Case::family()) of `cases`, e.g. read from case files or made by the
// corpus generator: duplicates and degenerate pairs dropped (the timed algorithms need not accept
// zero-area triangles), shuffled once with the seed. A family smaller than options.size stays as
// it is (it is never replayed to fill the pool); the caller warns about small pools.
std::vector<Pool> family_pools(const std::vector<Case>& cases, const PoolOptions& options);

// Where the family pools come from when no case files are given: "tritri corpus [--quick] --seed S
// (cases/generator)".
std::string generator_source(const WorkloadInput& input);

}  // namespace tritri::bench
