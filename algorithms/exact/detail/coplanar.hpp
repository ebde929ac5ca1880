// Coplanar proper pairs in the one-pair path (one_pair.hpp's `finish`, which the batch's scalar
// pass runs too): T1's three exact signs against π2 are zero, and the pair is decided in 2-D from
// the filter's values, without the classification's second evaluation of both normals and its 18
// per-call filters.
//
//   projection  drop the axis k of T1's largest computed normal component; both triangles'
//               orientations there (T1's n_k, T2's) must be exactly non-zero, which proves both
//               proper and the pair coplanar; otherwise the caller classifies (degenerate input);
//   18 values   each vertex against each edge line of the other triangle, in det2_value's shape,
//               all under one det2 bound from the extents of the six projected points; a value
//               within it gets its exact sign from plain double on the grid, else from the
//               pair's shared integer conversion (128-bit), else the per-call dynamic bound and
//               the integer engine;
//   decision    classify.hpp's `coplanar_from_signs`.
// algorithms/exact/README.md, "Coplanar pairs, one pair per call", proves it.
#pragma once

#include "algorithms/exact/detail/classify.hpp"

namespace tritri::exact::detail {

// The pair (18 coordinates at c, finite) when T1's exact signs against π2 are all zero: true and
// `out` set when both triangles are proper (then they are coplanar), false when a triangle's
// orientation in the chosen projection is zero (a degenerate triangle, or a normal whose largest
// computed component is exactly zero: the caller classifies). `Grid` is one_pair.hpp's LazyGrid:
// on(), the grid test; converted() and x, the pair's shared integer conversion.
template <bool kRelation, class Grid>
bool coplanar_known(const double* c, Grid& g, Relation& out) {
  const double ux = c[3] - c[0], uy = c[4] - c[1], uz = c[5] - c[2];
  const double vx = c[6] - c[0], vy = c[7] - c[1], vz = c[8] - c[2];
  const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  const double ax = std::fabs(nx), ay = std::fabs(ny), az = std::fabs(nz);
  const int k = (ax >= ay) & (ax >= az) ? 0 : (ay >= az ? 1 : 2);
  const int i = k == 2 ? 0 : k + 1, j = k == 0 ? 2 : k - 1;  // (k+1, k+2) mod 3
  double pi[6], pj[6];
  for (int v = 0; v < 6; ++v) pi[v] = c[3 * v + i], pj[v] = c[3 * v + j];
  double lo_i = pi[0], hi_i = pi[0], lo_j = pj[0], hi_j = pj[0];
  for (int v = 1; v < 6; ++v) {
    lo_i = pi[v] < lo_i ? pi[v] : lo_i, hi_i = pi[v] > hi_i ? pi[v] : hi_i;
    lo_j = pj[v] < lo_j ? pj[v] : lo_j, hi_j = pj[v] > hi_j ? pj[v] : hi_j;
  }
  // on the grid every value below is exact: threshold 0, and a value within it is exactly 0
  const bool grid = g.on();
  const double t = grid ? 0.0 : det2_bound(hi_i - lo_i, hi_j - lo_j);
  // the exact sign of o2(a, b, v) given its value in det2_value's shape
  const auto sign = [&](double value, int a, int b, int v) {
    if (value > t) return 1;
    if (value < -t) return -1;
    if (grid) return 0;
    if (g.converted()) return intexact::det2_pair_sign(g.x, i, j, a, b, v);
    return Filtered::dynamic2(c + 3 * a, c + 3 * b, c + 3 * v, i, j);
  };
  const double n1 = k == 0 ? nx : (k == 1 ? ny : nz);
  const double n2 = (pi[4] - pi[3]) * (pj[5] - pj[3]) - (pj[4] - pj[3]) * (pi[5] - pi[3]);
  const int o1 = sign(n1, 0, 1, 2);
  if (o1 == 0) return false;
  const int o2 = sign(n2, 3, 4, 5);
  if (o2 == 0) return false;
  CoplanarSigns o;
  for (int side = 0; side < 2; ++side) {
    const int own = 3 * side, other = 3 - own;  // first point of the edges' triangle, of the other
    const int orient = side == 0 ? o1 : o2;
    for (int e = 0; e < 3; ++e) {
      const int a = own + e, b = own + (e == 2 ? 0 : e + 1);
      const double ei = pi[b] - pi[a], ej = pj[b] - pj[a];
      for (int v = 0; v < 3; ++v) {
        const int w = other + v;
        const double value = ei * (pj[w] - pj[a]) - ej * (pi[w] - pi[a]);
        o[side][e][v] = sign(value, a, b, w) * orient;
      }
    }
  }
  const Tri t1{{c, c + 3, c + 6}}, t2{{c + 9, c + 12, c + 15}};
  out = coplanar_from_signs<kRelation>(t1, t2, o);
  return true;
}

}  // namespace tritri::exact::detail
