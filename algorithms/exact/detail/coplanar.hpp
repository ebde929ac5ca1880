// Coplanar proper pairs in the one-pair path (one_pair.hpp's `finish`, which the batch's scalar
// pass runs too): T1's three exact signs against π2 are zero, and the pair is decided in 2-D
// without the classification's second evaluation of both normals and its 18 per-call filters.
//
//   flat        the six points share one coordinate exactly: T1's signs against π2 are zero
//               without arithmetic (and the filter's values are then exact zeros);
//   projection  (x, y) where every o2 there is exact (the 3-D grid, or (x, y) on the 2-D grid),
//               else drop the axis k of T1's largest computed normal component; both triangles'
//               orientations there (T1's n_k, T2's) must be exactly non-zero, which proves both
//               proper and the pair coplanar; otherwise the caller classifies (degenerate input);
//   values      the 18 edge values (each vertex against each edge line of the other triangle)
//               and both orientations, two at a time (projected.hpp's `coplanar_values`);
//   decision    where every value is exact (the pair on the 3-D grid, or its projection on the
//               2-D grid): no edge line with its three values negative means a meet; elsewhere
//               an edge line with its three values certainly negative (beyond the det2 bound of
//               the projected extents) separates, and every edge line with a value certainly
//               positive means the interiors meet; only what is left takes each value's exact
//               sign (the pair's shared integer conversion, else the per-call dynamic bound and
//               the integer engine) and classify.hpp's `coplanar_from_signs`.
// algorithms/exact/README.md, "Coplanar pairs, one pair per call", proves it.
#pragma once

#include "algorithms/exact/detail/classify.hpp"

#include <cstdint>
#include <cstring>

namespace tritri::exact::detail {

// The lanes of v[0..n) are all multiples of 2^q with |x| < 2^(q + bits), q = e - (bits - 1) for
// 2^e <= max|x| = m < 2^(e+1), and m lies in [lo, hi): fl(fl(x + C) - C) = x with C = 1.5·2^(q+52),
// built from m's exponent bits (algorithms/exact/README.md, "The grid case", "The 2-D grid").
// `m` is the caller's max|x| over v[0..n), exactly (the pair's box gives it:
// algorithms/exact/README.md, "Coplanar pairs off the 3-D grid: (x, y) first"). Finite input; hi
// at most 2^(1023 - 53 + bits) so that C is finite.
inline bool on_grid_of(const Double2* v, int n, double m, double lo, double hi, int bits) {
  if (!(m >= lo && m < hi)) return false;
  std::uint64_t b;
  std::memcpy(&b, &m, sizeof b);
  b = ((b & 0x7ff0000000000000ull) + (static_cast<std::uint64_t>(53 - bits) << 52)) | (1ull << 51);
  double big;
  std::memcpy(&big, &b, sizeof big);
  const Double2 c = {big, big};
  Long2 all = (v[0] + c) - c == v[0];
  for (int k = 1; k < n; ++k) all &= (v[k] + c) - c == v[k];
  return all2(all);
}

// The 2-D grid test on the 12 projected coordinates (pass 2's grid2_lanes for one pair): m in
// [2^-500, 2^500), 25 bits; then every o2 of them is exact in double. `mag`: the pair's largest
// |coordinate| per axis (one_pair.hpp's LazyGrid, from the filter's box of the six points).
inline bool on_grid2(const Projected& p, const double (&mag)[3], int i, int j) {
  const Double2 v[6] = {p.i[0], p.i[1], p.i[2], p.j[0], p.j[1], p.j[2]};
  return on_grid_of(v, 6, dmax(mag[i], mag[j]), 0x1p-500, 0x1p500, 25);
}

// The six points share one coordinate exactly (pass 2's flat_lanes for one pair; finite input).
inline bool flat_pair(const double* c) {
  Double2 xy0, xy;
  std::memcpy(&xy0, c, sizeof xy0);
  Long2 same = {-1, -1};
  bool same_z = true;
  for (int v = 1; v < 6; ++v) {
    std::memcpy(&xy, c + 3 * v, sizeof xy);
    same &= xy == xy0;
    same_z &= c[3 * v + 2] == c[2];
  }
  return ((same[0] | same[1]) != 0) | same_z;
}

// Each value with the sign of its triangle's orientation folded in (inside positive): exact, as a
// change of sign. The orientations must be non-zero.
inline void inside_positive(const CoplanarValues& cv, Double2 (&n)[3][3]) {
  const Long2 sign = reinterpret_cast<Long2>(cv.orient) & Long2{INT64_MIN, INT64_MIN};
  for (int e = 0; e < 3; ++e)
    for (int w = 0; w < 3; ++w) n[e][w] = reinterpret_cast<Double2>(reinterpret_cast<Long2>(cv.edge[e][w]) ^ sign);
}

// Per edge line (lane 0 T1's edge e, lane 1 T2's), the largest of its three inside-positive values.
inline void edge_maxima(const Double2 (&n)[3][3], Double2 (&m)[3]) {
  for (int e = 0; e < 3; ++e) {
    const Double2 a = n[e][0] > n[e][1] ? n[e][0] : n[e][1];
    m[e] = a > n[e][2] ? a : n[e][2];
  }
}

// Every value exact: false when an orientation is zero (the caller classifies); else the
// relation by the separating-axis theorem (step 3 of "The decisions"), after the first vertex of
// each triangle against the other's edge lines: one inside the other (closed; strictly at the
// relation level) answers a meet with three values of the 18 (algorithms/exact/README.md, "A
// vertex inside the other triangle, on exact values").
template <bool kRelation>
[[gnu::always_inline]] inline bool coplanar_exact(const double* c, const Projected& p, Relation& out) {
  const Double2 orient = coplanar_orient(p);
  if (any2(orient == 0.0)) return false;
  CoplanarValues cv;
  cv.orient = orient;
  Double2 col[3], first[3];
  coplanar_column(p, 0, col);
  const Long2 sign = reinterpret_cast<Long2>(orient) & Long2{INT64_MIN, INT64_MIN};
  for (int e = 0; e < 3; ++e)  // inside positive
    cv.edge[e][0] = col[e], first[e] = reinterpret_cast<Double2>(reinterpret_cast<Long2>(col[e]) ^ sign);
  // the lane tests by lt2 / le2 (a comparison and a movmskpd each: the vector extension's masks
  // had been read out of the register lane by lane before their movmskpd)
  const Double2 zero = {0.0, 0.0};
  const unsigned in = kRelation ? lt2(zero, first[0]) & lt2(zero, first[1]) & lt2(zero, first[2])
                                : le2(zero, first[0]) & le2(zero, first[1]) & le2(zero, first[2]);
  if (in != 0u) {
    out = Relation::coplanar_overlap;
    return true;
  }
  for (int w = 1; w < 3; ++w) {  // the other two columns
    coplanar_column(p, w, col);
    for (int e = 0; e < 3; ++e) cv.edge[e][w] = col[e];
  }
  Double2 n[3][3], m[3];
  inside_positive(cv, n);
  edge_maxima(n, m);
  if ((lt2(m[0], zero) | lt2(m[1], zero) | lt2(m[2], zero)) != 0u) {
    out = Relation::coplanar_disjoint;
    return true;
  }
  if (!kRelation || (lt2(zero, m[0]) & lt2(zero, m[1]) & lt2(zero, m[2])) == 3u) {  // no edge line separates, not even weakly
    out = Relation::coplanar_overlap;
    return true;
  }
  CoplanarSigns o;
  for (int side = 0; side < 2; ++side)
    for (int e = 0; e < 3; ++e)
      for (int w = 0; w < 3; ++w) o[side][e][w] = sgn(n[e][w][side]);
  out = coplanar_from_signs<kRelation>(Tri{{c, c + 3, c + 6}}, Tri{{c + 9, c + 12, c + 15}}, o);
  return true;
}

// Against a bound t valid for every value: 0 an edge line certainly separates strictly, 1 every
// edge line has a value certainly inside (the interiors meet), -1 undecided (an orientation or a
// deciding value within t).
inline int coplanar_certain(const CoplanarValues& cv, double t) {
  const Double2 hi = {t, t}, lo = -hi;
  if ((lt2(hi, cv.orient) | lt2(cv.orient, lo)) != 3u) return -1;
  Double2 n[3][3], m[3];
  inside_positive(cv, n);
  edge_maxima(n, m);
  if ((lt2(m[0], lo) | lt2(m[1], lo) | lt2(m[2], lo)) != 0u) return 0;
  return (lt2(hi, m[0]) & lt2(hi, m[1]) & lt2(hi, m[2])) == 3u ? 1 : -1;
}

// Each value's exact sign (beyond t its own; within it the pair's shared conversion, else the
// per-call dynamic bound and the integer engine), then coplanar_from_signs. False when an
// orientation is exactly zero. `Grid` is one_pair.hpp's LazyGrid (converted() and x).
template <bool kRelation, class Grid>
bool coplanar_by_signs(const double* c, Grid& g, const CoplanarValues& cv, double t, int i, int j, Relation& out) {
  const auto sign = [&](double value, int a, int b, int v) {
    if (value > t) return 1;
    if (value < -t) return -1;
    if (g.converted()) return intexact::det2_pair_sign(g.x, i, j, a, b, v);
    return Filtered::dynamic2(c + 3 * a, c + 3 * b, c + 3 * v, i, j);
  };
  const int o1 = sign(cv.orient[0], 0, 1, 2);
  if (o1 == 0) return false;
  const int o2 = sign(cv.orient[1], 3, 4, 5);
  if (o2 == 0) return false;
  CoplanarSigns o;
  for (int side = 0; side < 2; ++side) {
    const int own = 3 * side, other = 3 - own;  // first point of the edges' triangle, of the other
    const int orient = side == 0 ? o1 : o2;
    for (int e = 0; e < 3; ++e)
      for (int w = 0; w < 3; ++w)
        o[side][e][w] = sign(cv.edge[e][w][side], own + e, own + (e == 2 ? 0 : e + 1), other + w) * orient;
  }
  out = coplanar_from_signs<kRelation>(Tri{{c, c + 3, c + 6}}, Tri{{c + 9, c + 12, c + 15}}, o);
  return true;
}

// The axis of T1's largest computed normal component (the cross product of T1's two edges from a1,
// as normal_signs evaluates it); ties to the lower axis.
inline int largest_normal_axis(const double* c) {
  const double ux = c[3] - c[0], uy = c[4] - c[1], uz = c[5] - c[2];
  const double vx = c[6] - c[0], vy = c[7] - c[1], vz = c[8] - c[2];
  const double ax = std::fabs(uy * vz - uz * vy), ay = std::fabs(uz * vx - ux * vz), az = std::fabs(ux * vy - uy * vx);
  return ((ax >= ay) & (ax >= az)) ? 0 : (ay >= az ? 1 : 2);
}

// On the 3-D grid every o2 of the pair's points is exact in every projection, and any projection
// with both orientations non-zero decides: (x, y) first, T1's normal only when that fails
// (algorithms/exact/README.md, "Coplanar pairs on the grid: (x, y) first"). False: an orientation
// is zero in the projection of T1's largest normal component too (a degenerate triangle).
template <bool kRelation>
bool coplanar_grid(const double* c, Relation& out) {
  if (coplanar_exact<kRelation>(c, project_of(c, 2), out)) return true;
  return coplanar_exact<kRelation>(c, project_of(c, largest_normal_axis(c)), out);
}

// Six points that share z exactly, with finite coordinates (`box`: theirs, its z extent zero):
// T1's signs against π2 are zero without arithmetic, and with (x, y) on the 2-D grid every o2
// there is exact, so coplanar_exact on (x, y) decides, without the 3-D grid test
// (algorithms/exact/README.md, "Six points in one plane z = h: (x, y) before the 3-D grid test").
// False: (x, y) off the 2-D grid, or an orientation there zero (a degenerate triangle); `finish`
// then goes on as before. Out of line: the pairs that do not take it pay one comparison.
template <bool kRelation>
[[gnu::noinline]] bool coplanar_flat_z(const double* c, const Box& box, Relation& out) {
  double mag[3];
  box_magnitudes(box, mag);
  const Projected xy = project_of(c, 2);
  return on_grid2(xy, mag, 0, 1) && coplanar_exact<kRelation>(c, xy, out);
}

// The pair (18 coordinates at c, finite) when T1's exact signs against π2 are all zero: true and
// `out` set when both triangles are proper (then they are coplanar), false when a triangle's
// orientation in the chosen projection is zero (a degenerate triangle, or a normal whose largest
// computed component is exactly zero: the caller classifies). `Grid` is one_pair.hpp's LazyGrid:
// state 1 when the pair is known to be on the 3-D grid; mag, its largest |coordinate| per axis;
// converted() and x, the pair's shared integer conversion.
template <bool kRelation, class Grid>
bool coplanar_known(const double* c, Grid& g, Relation& out) {
  if (g.state == 1) return coplanar_grid<kRelation>(c, out);
  // six points in one plane z = h have had (x, y) on the 2-D grid tried before `finish`
  // (coplanar_flat_z); off it their projection is T1's largest normal component's, z, as for the
  // others (algorithms/exact/README.md, "Coplanar pairs off the 3-D grid: (x, y) first")
  const int k = largest_normal_axis(c);
  const int i = k == 2 ? 0 : k + 1, j = k == 0 ? 2 : k - 1;  // (k+1, k+2) mod 3
  const Projected p = project_of(c, k);
  // every o2 exact on the 2-D grid
  if (on_grid2(p, g.mag, i, j)) return coplanar_exact<kRelation>(c, p, out);
  const CoplanarValues cv = coplanar_values(p);
  const double t = projected_bound(p);
  if (const int d = coplanar_certain(cv, t); d >= 0) {
    out = d ? Relation::coplanar_overlap : Relation::coplanar_disjoint;
    return true;
  }
  return coplanar_by_signs<kRelation>(c, g, cv, t, i, j, out);
}

}  // namespace tritri::exact::detail
