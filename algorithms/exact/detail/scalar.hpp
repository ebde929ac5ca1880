// One pair, exactly, without SIMD: the second pass of the batch kernels and the reference of
// the tests. Non-finite input is declined (unsupported).
#pragma once

#include "algorithms/exact/detail/classify.hpp"
#include "tritri/geometry.hpp"

namespace tritri::exact::detail {

// What decided a pair in the scalar path (for the statistics): the one-pair filter, the
// shared-vertex shortcuts (one_pair.hpp), or the classification with a predicate policy.
enum class Route : std::uint8_t { filter, shared, grid, filtered, declined };

inline void gather(const TrianglePair& pair, Tri& t1, Tri& t2, double (&c)[18]) {
  for (int i = 0; i < 3; ++i) {
    t1.v[i] = pair.t1[i].data();
    t2.v[i] = pair.t2[i].data();
    for (int k = 0; k < 3; ++k) {
      c[3 * i + k] = pair.t1[i][k];
      c[9 + 3 * i + k] = pair.t2[i][k];
    }
  }
}

template <bool kRelation>
RelationAnswer solve(const TrianglePair& pair, Route* route = nullptr) {
  Tri t1, t2;
  double c[18];
  gather(pair, t1, t2, c);
  if (!all_finite(c, 18)) {
    if (route) *route = Route::declined;
    return {Relation::unsupported, Dimension::unknown};
  }
  if (grid_exact(c, 18)) {
    if (route) *route = Route::grid;
    return classify<Plain, kRelation>(t1, t2);
  }
  if (route) *route = Route::filtered;
  return classify<Filtered, kRelation>(t1, t2);
}


}  // namespace tritri::exact::detail
