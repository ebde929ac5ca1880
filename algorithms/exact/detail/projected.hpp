// A pair's six points in one projection (i, j), two at a time (SSE2 / NEON registers through
// GCC's vector extension): the det2 bound of their extents and the 20 values of the coplanar
// test, each evaluated as det2_value evaluates o2. The classification's coplanar branch
// (classify.hpp) and the one-pair coplanar step (coplanar.hpp) share them; algorithms/exact/
// README.md, "Coplanar pairs, one pair per call", says why the bound serves every value.
#pragma once

#include "algorithms/exact/detail/pair_box.hpp"
#include "algorithms/exact/detail/predicates.hpp"

#include <algorithm>
#include <cstring>

namespace tritri::exact::detail {

// The pair's six points in the projection (i, j), vertex v of both triangles in one register:
// lane 0 T1's, lane 1 T2's (so that each triangle's edges meet the other's vertices lane by lane).
struct Projected {
  Double2 i[3], j[3];
};
inline Projected project(const P (&a)[3], const P (&b)[3], int i, int j) {
  Projected p;
  for (int v = 0; v < 3; ++v) p.i[v] = Double2{a[v][i], b[v][i]}, p.j[v] = Double2{a[v][j], b[v][j]};
  return p;
}

// The projection dropping axis k, (i, j) = (k + 1, k + 2) mod 3, from the pair's 18 coordinates
// (T1's three points, then T2's): two neighbouring coordinates of a point in one load, then lane 0
// T1's and lane 1 T2's by unpacks; the values of project(T1, T2, i, j), where GCC had built each
// register from two scalar loads. k = 1 takes z and x from two loads (z is not next to x).
inline Projected project_of(const double* c, int k) {
  Projected p;
  const int off = k == 0 ? 1 : 0;  // (y, z) from y on, (x, y) from x on
  for (int v = 0; v < 3; ++v) {
    Double2 a, b;
    std::memcpy(&a, c + 3 * v + off, sizeof a);
    std::memcpy(&b, c + 9 + 3 * v + off, sizeof b);
    if (k == 1) {  // (z, x): x from the load at x, z from the load at y (c + 16 is the last read)
      Double2 ay, by;
      std::memcpy(&ay, c + 3 * v + 1, sizeof ay);
      std::memcpy(&by, c + 9 + 3 * v + 1, sizeof by);
      p.i[v] = __builtin_shufflevector(ay, by, 1, 3), p.j[v] = __builtin_shufflevector(a, b, 0, 2);
    } else {
      p.i[v] = __builtin_shufflevector(a, b, 0, 2), p.j[v] = __builtin_shufflevector(a, b, 1, 3);
    }
  }
  return p;
}

// The det2 bound from the extents of the six projected points (algorithms/exact/README.md,
// "det2", "Shared bounds"): valid for every o2 of them evaluated as det2_value evaluates it;
// +inf beyond kMax2. Finite coordinates.
inline double projected_bound(const Projected& p) {
  Double2 lo_i = p.i[0], hi_i = p.i[0], lo_j = p.j[0], hi_j = p.j[0];
  for (int v = 1; v < 3; ++v) {
    lo_i = p.i[v] < lo_i ? p.i[v] : lo_i, hi_i = p.i[v] > hi_i ? p.i[v] : hi_i;
    lo_j = p.j[v] < lo_j ? p.j[v] : lo_j, hi_j = p.j[v] > hi_j ? p.j[v] : hi_j;
  }
  const double ei = dmax(hi_i[0], hi_i[1]) - std::min(lo_i[0], lo_i[1]);
  const double ej = dmax(hi_j[0], hi_j[1]) - std::min(lo_j[0], lo_j[1]);
  return det2_bound(ei, ej);
}

// The orientations and the 18 edge values of a pair in one projection, each an o2 evaluated as
// det2_value evaluates it (so that projected_bound serves all 20). Lane 0: T1's orientation and
// T1's edges against T2's vertices; lane 1 the same with the triangles exchanged.
struct CoplanarValues {
  Double2 orient;      // o2(v0, v1, v2), v the lane's triangle
  Double2 edge[3][3];  // [e][w]: o2(v_e, v_e+1, u_w), u the other triangle
};
// Column w of the edge values: the other triangle's vertex w against the lane's three edge lines
// (lane 0 T2's vertex w against T1's edges, lane 1 T1's against T2's), det2_value's operations.
inline void coplanar_column(const Projected& p, int w, Double2 (&col)[3]) {
  const Double2 ui = {p.i[w][1], p.i[w][0]}, uj = {p.j[w][1], p.j[w][0]};  // the lanes exchanged
  for (int e = 0; e < 3; ++e) {
    const int f = e == 2 ? 0 : e + 1;
    const Double2 ei = p.i[f] - p.i[e], ej = p.j[f] - p.j[e];
    col[e] = ei * (uj - p.j[e]) - ej * (ui - p.i[e]);
  }
}
inline Double2 coplanar_orient(const Projected& p) {
  return (p.i[1] - p.i[0]) * (p.j[2] - p.j[0]) - (p.j[1] - p.j[0]) * (p.i[2] - p.i[0]);
}
inline CoplanarValues coplanar_values(const Projected& p) {
  CoplanarValues out;
  for (int w = 0; w < 3; ++w) {
    Double2 col[3];
    coplanar_column(p, w, col);
    for (int e = 0; e < 3; ++e) out.edge[e][w] = col[e];
  }
  out.orient = coplanar_orient(p);
  return out;
}

}  // namespace tritri::exact::detail
