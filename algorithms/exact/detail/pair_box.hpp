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

// The axis-aligned box of one triangle's three vertices: x and y in one Double2, z apart (minima
// and maxima by `<` / `>`: an unordered comparison keeps the running value).
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

// The box of both: minima and maxima by `<` / `>` (an unordered comparison keeps a's value).
inline Box union_of(const Box& a, const Box& b) {
  return {b.lo < a.lo ? b.lo : a.lo, b.hi > a.hi ? b.hi : a.hi, b.lo_z < a.lo_z ? b.lo_z : a.lo_z,
          b.hi_z > a.hi_z ? b.hi_z : a.hi_z};
}

// The kernel's B for one pair (pair_bound3's value) from the box of its six points, +inf unless
// every extent is at most kMax3. An infinite coordinate leaves its axis' minimum at -inf or
// maximum at +inf (a NaN is skipped, or leaves NaN), so the extent is +inf or NaN and B = +inf,
// unless a NaN was skipped; a NaN makes every value it enters NaN. Either way no comparison with
// B below is true (algorithms/exact/README.md, "One pair per call").
inline double bound_of_box(const Box& u) {
  const Double2 e = u.hi - u.lo;
  const double ex = e[0], ey = e[1], ez = u.hi_z - u.lo_z;
  if (!(ex <= bound::kMax3 && ey <= bound::kMax3 && ez <= bound::kMax3)) return __builtin_inf();
  return bound::kRel3 * dmax(ex, bound::kMin3) * dmax(ey, bound::kMin3) * dmax(ez, bound::kMin3) + bound::kAbs3;
}

// The largest |coordinate| per axis of a box of finite coordinates: max(hi, -lo), exact.
inline void box_magnitudes(const Box& u, double (&m)[3]) {
  const Double2 a = -u.lo, h = u.hi;
  const Double2 x = a > h ? a : h;
  m[0] = x[0], m[1] = x[1], m[2] = dmax(-u.lo_z, u.hi_z);
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
