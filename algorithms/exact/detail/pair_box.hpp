// The pair's six points two coordinates at a time (SSE2 / NEON registers through GCC's vector
// extension): the boxes of its triangles, the one-pair filter's bound B from their extents, and
// the finiteness of its 18 coordinates. Used by one_pair.hpp's filter and `finish`; the bound is
// proved in algorithms/exact/README.md ("Shared bounds"), the box exit in "One pair per call".
#pragma once

#include "algorithms/exact/detail/predicates.hpp"

#include <cstring>

namespace tritri::exact::detail {

// Two doubles in one SSE2 / NEON register (GCC vector extension): x and y of a point.
using Double2 = double __attribute__((vector_size(16)));
// Two 64-bit integers in one register: the lane masks of Double2 comparisons (all bits set = true).
using Long2 = long long __attribute__((vector_size(16)));

// The kernel's B for one pair (pair_bound3's value), +inf unless every extent is at most kMax3.
// Minima and maxima by `<` / `>` (an unordered comparison keeps the running value): an infinite
// coordinate leaves its axis' minimum at -inf or maximum at +inf, or both NaN (a NaN first
// coordinate), so the extent is +inf or NaN and B = +inf; a NaN coordinate met later is skipped,
// but makes every value it enters NaN. Either way no comparison with B below is true.
inline double one_pair_bound(const double* c) {
  Double2 lo, hi;
  std::memcpy(&lo, c, sizeof lo);
  hi = lo;
  double lo_z = c[2], hi_z = c[2];
  for (int v = 1; v < 6; ++v) {
    Double2 p;
    std::memcpy(&p, c + 3 * v, sizeof p);
    lo = p < lo ? p : lo;
    hi = p > hi ? p : hi;
    lo_z = c[3 * v + 2] < lo_z ? c[3 * v + 2] : lo_z;
    hi_z = c[3 * v + 2] > hi_z ? c[3 * v + 2] : hi_z;
  }
  const Double2 e = hi - lo;
  const double ex = e[0], ey = e[1], ez = hi_z - lo_z;
  if (!(ex <= bound::kMax3 && ey <= bound::kMax3 && ez <= bound::kMax3)) return __builtin_inf();
  return bound::kRel3 * dmax(ex, bound::kMin3) * dmax(ey, bound::kMin3) * dmax(ez, bound::kMin3) + bound::kAbs3;
}

// The axis-aligned box of one triangle's three vertices: x and y in one Double2, z apart (minima
// and maxima by `<` / `>`, as one_pair_bound).
struct Box {
  Double2 lo, hi;
  double lo_z, hi_z;
};
inline Box box_of(const double* t) {
  Box b;
  std::memcpy(&b.lo, t, sizeof b.lo);
  b.hi = b.lo;
  b.lo_z = b.hi_z = t[2];
  for (int v = 1; v < 3; ++v) {
    Double2 p;
    std::memcpy(&p, t + 3 * v, sizeof p);
    b.lo = p < b.lo ? p : b.lo;
    b.hi = p > b.hi ? p : b.hi;
    b.lo_z = t[3 * v + 2] < b.lo_z ? t[3 * v + 2] : b.lo_z;
    b.hi_z = t[3 * v + 2] > b.hi_z ? t[3 * v + 2] : b.hi_z;
  }
  return b;
}

// The pair's bound from its two boxes: one_pair_bound's value (the union's extents), +inf unless
// every extent is at most kMax3.
inline double bound_of_boxes(const Box& a, const Box& b) {
  const Double2 lo = b.lo < a.lo ? b.lo : a.lo, hi = b.hi > a.hi ? b.hi : a.hi;
  const Double2 e = hi - lo;
  const double ex = e[0], ey = e[1];
  const double ez = (b.hi_z > a.hi_z ? b.hi_z : a.hi_z) - (b.lo_z < a.lo_z ? b.lo_z : a.lo_z);
  if (!(ex <= bound::kMax3 && ey <= bound::kMax3 && ez <= bound::kMax3)) return __builtin_inf();
  return bound::kRel3 * dmax(ex, bound::kMin3) * dmax(ey, bound::kMin3) * dmax(ez, bound::kMin3) + bound::kAbs3;
}

// The boxes are disjoint along some axis (comparisons only, hence exact for finite coordinates).
inline bool boxes_apart(const Box& a, const Box& b) {
  const Long2 apart = (a.hi < b.lo) | (b.hi < a.lo);
  return ((apart[0] | apart[1]) != 0) | (a.hi_z < b.lo_z) | (b.hi_z < a.lo_z);
}

// The 18 coordinates as 9 Double2 (in memory order: the pairing does not matter to the callers).
inline void load9(const double* c, Double2 (&v)[9]) {
  for (int i = 0; i < 9; ++i) std::memcpy(&v[i], c + 2 * i, sizeof v[i]);
}

// All 18 coordinates finite: x - x is 0 for finite x and NaN otherwise, and a sum with a NaN is NaN.
inline bool finite18(const double* c) {
  Double2 v[9];
  load9(c, v);
  Double2 z = v[0] - v[0];
  for (int i = 1; i < 9; ++i) z += v[i] - v[i];
  return (z[0] + z[1]) == 0.0;
}

}  // namespace tritri::exact::detail
