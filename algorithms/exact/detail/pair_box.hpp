// The pair's six points two coordinates at a time (SSE2 / NEON registers through GCC's vector
// extension): the boxes of its triangles, the one-pair filter's bound B from their extents, two
// comparisons as two bits, the finiteness of its 18 coordinates, and both triangles' plane values
// in two lanes. Used by one_pair.hpp's filter and `finish`; the bound is proved in
// algorithms/exact/README.md ("Shared bounds"), the box exit and the lanes in "One pair per call".
#pragma once

#include "algorithms/exact/detail/predicates.hpp"

#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace tritri::exact::detail {

// Two doubles in one SSE2 / NEON register (GCC vector extension): x and y of a point.
using Double2 = double __attribute__((vector_size(16)));
// Two 64-bit integers in one register: the lane masks of Double2 comparisons (all bits set = true).
using Long2 = long long __attribute__((vector_size(16)));

// Bit k set where a_k < b_k (lt2) or a_k <= b_k (le2), false for NaN as the scalar comparisons:
// one comparison and one movmskpd on SSE2. GCC's vector extension compiled the mask's lanes out of
// the register one by one (moves, masks, negations) before it would take their bits.
inline unsigned lt2(Double2 a, Double2 b) {
#if defined(__SSE2__)
  return static_cast<unsigned>(_mm_movemask_pd(_mm_cmplt_pd(reinterpret_cast<__m128d>(a), reinterpret_cast<__m128d>(b))));
#else
  return static_cast<unsigned>(a[0] < b[0]) | static_cast<unsigned>(a[1] < b[1]) << 1;
#endif
}
inline unsigned le2(Double2 a, Double2 b) {
#if defined(__SSE2__)
  return static_cast<unsigned>(_mm_movemask_pd(_mm_cmple_pd(reinterpret_cast<__m128d>(a), reinterpret_cast<__m128d>(b))));
#else
  return static_cast<unsigned>(a[0] <= b[0]) | static_cast<unsigned>(a[1] <= b[1]) << 1;
#endif
}

// max(a, b) lane by lane as `a > b ? a : b` (b where either is NaN): maxpd on SSE2, where GCC
// compiled the vector ternary as a comparison and three logical operations.
inline Double2 max2(Double2 a, Double2 b) {
#if defined(__SSE2__)
  return reinterpret_cast<Double2>(_mm_max_pd(reinterpret_cast<__m128d>(a), reinterpret_cast<__m128d>(b)));
#else
  return a > b ? a : b;
#endif
}

// The two lanes of a comparison mask (all ones or zero per lane) as two bits: one movmskpd on SSE2.
inline unsigned mask_bits2(Long2 m) {
#if defined(__SSE2__)
  return static_cast<unsigned>(_mm_movemask_pd(reinterpret_cast<__m128d>(m)));
#else
  return static_cast<unsigned>(m[0] & 1) | static_cast<unsigned>(m[1] & 1) << 1;
#endif
}

// Both lanes of a comparison mask true.
inline bool all2(Long2 m) { return mask_bits2(m) == 3u; }

// Either lane of an equality mask true: one cmpeqpd and one movmskpd on SSE2, where two scalar
// comparisons with zero cost a parity test each. (GCC 12 reads a `<` or `<=` mask of the vector
// extension out lane by lane before a movmskpd: lt2 / le2 take those.)
inline bool any2(Long2 m) { return mask_bits2(m) != 0u; }

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

// Coordinate i of both triangles in one register: lane 0 T1's (c[i]), lane 1 T2's (c[9 + i]).
inline Double2 both_at(const double* c, int i) { return Double2{c[i], c[9 + i]}; }

// The lanes exchanged (one shufpd on SSE2).
inline Double2 swapped(Double2 a) { return __builtin_shufflevector(a, a, 1, 0); }

// Both triangles' boxes: box_of's x and y, and z of both in one register (both_at), where each
// box's z had been two scalar minima and maxima with a move per vertex; the same `<` / `>` lane by
// lane (minpd and maxpd: `a < b ? a : b`), so the same values, NaN kept as box_of keeps it.
inline void boxes_of(const double* c, Box& b1, Box& b2) {
  b1 = box_of(c), b2 = box_of(c + 9);  // their z is overwritten below (and not computed)
  Double2 lo = both_at(c, 2), hi = lo;
  for (int v = 1; v < 3; ++v) {
    const Double2 p = both_at(c, 3 * v + 2);
    lo = p < lo ? p : lo;
    hi = p > hi ? p : hi;
  }
  b1.lo_z = lo[0], b2.lo_z = lo[1], b1.hi_z = hi[0], b2.hi_z = hi[1];
}

// The box of both: minima and maxima by `<` / `>` (an unordered comparison keeps a's value).
inline Box union_of(const Box& a, const Box& b) {
  return {b.lo < a.lo ? b.lo : a.lo, b.hi > a.hi ? b.hi : a.hi, b.lo_z < a.lo_z ? b.lo_z : a.lo_z,
          b.hi_z > a.hi_z ? b.hi_z : a.hi_z};
}

// B from the extents (x, y) = e and z = ez, each at most kMax3: dmax(e, kMin3) for x and y at once
// (e finite here): max2 is e > least ? e : least lane by lane.
inline double bound_of_extents(Double2 e, double ez) {
  const Double2 least = {bound::kMin3, bound::kMin3};
  const Double2 m = max2(e, least);
  return bound::kRel3 * m[0] * m[1] * dmax(ez, bound::kMin3) + bound::kAbs3;
}

// The kernel's B for one pair (pair_bound3's value) from the box of its six points, +inf unless
// every extent is at most kMax3. An infinite coordinate leaves its axis' minimum at -inf or
// maximum at +inf (a NaN is skipped, or leaves NaN), so the extent is +inf or NaN and B = +inf,
// unless a NaN was skipped; a NaN makes every value it enters NaN. Either way no comparison with
// B below is true (algorithms/exact/README.md, "One pair per call").
inline double bound_of_box(const Box& u) {
  const Double2 e = u.hi - u.lo, most = {bound::kMax3, bound::kMax3};
  const double ez = u.hi_z - u.lo_z;
  // `<=` is false for NaN: a NaN extent fails as before; all three tested in one branch
  if ((le2(e, most) | static_cast<unsigned>(ez <= bound::kMax3) << 2) != 7u) return __builtin_inf();
  return bound_of_extents(e, ez);
}

// bound_of_box when the z extent is non-zero and B finite; false (b unset) when the z extent is
// zero or B would be +inf: the one-pair filter's test for six points in one plane z = h folded
// into the bound's own branch, so that the pairs that do not take it pay no branch of their own.
inline bool bound_unless_flat(const Box& u, double& b) {
  const Double2 e = u.hi - u.lo, most = {bound::kMax3, bound::kMax3};
  const double ez = u.hi_z - u.lo_z;
  // ez is hi_z - lo_z, so not below zero: the least subnormal at most ez means ez non-zero; both
  // of ez's tests in one comparison, false for NaN
  const Double2 zlo = {0x1p-1074, ez}, zhi = {ez, bound::kMax3};
  if ((le2(e, most) | le2(zlo, zhi) << 2) != 15u) return false;
  b = bound_of_extents(e, ez);
  return true;
}

// Either lane's three values all above `hi` or all below `lo` (lt2's comparisons, false for NaN):
// the masks combined in the register and one movmskpd, where six movmskpd and five logical
// operations on their bits had been compiled.
inline bool either_one_sided(Double2 hi, Double2 lo, const Double2 (&s)[3]) {
#if defined(__SSE2__)
  const auto lt = [](Double2 a, Double2 b) { return _mm_cmplt_pd(reinterpret_cast<__m128d>(a), reinterpret_cast<__m128d>(b)); };
  const __m128d pos = _mm_and_pd(_mm_and_pd(lt(hi, s[0]), lt(hi, s[1])), lt(hi, s[2]));
  const __m128d neg = _mm_and_pd(_mm_and_pd(lt(s[0], lo), lt(s[1], lo)), lt(s[2], lo));
  return _mm_movemask_pd(_mm_or_pd(pos, neg)) != 0;
#else
  return ((lt2(hi, s[0]) & lt2(hi, s[1]) & lt2(hi, s[2])) | (lt2(s[0], lo) & lt2(s[1], lo) & lt2(s[2], lo))) != 0u;
#endif
}

// The largest |coordinate| per axis of a box of finite coordinates: max(hi, -lo), exact.
inline void box_magnitudes(const Box& u, double (&m)[3]) {
  const Double2 x = max2(-u.lo, u.hi);
  m[0] = x[0], m[1] = x[1], m[2] = dmax(-u.lo_z, u.hi_z);
}

// The boxes are disjoint along some axis (comparisons only, hence exact for finite coordinates).
inline bool boxes_apart(const Box& a, const Box& b) {
  // z of both boxes in one register, so that the six comparisons make one mask and one branch
  const Double2 hz = {a.hi_z, b.hi_z}, lz = {b.lo_z, a.lo_z};
  return (lt2(a.hi, b.lo) | lt2(b.hi, a.lo) | lt2(hz, lz)) != 0u;
}

// All 18 coordinates finite: x - x is 0 for finite x and NaN otherwise, and a sum with a NaN is NaN.
inline bool finite18(const double* c) {
  Double2 z = {0.0, 0.0};
  for (int i = 0; i < 9; ++i) {  // one register at a time: an array of nine went through the stack
    Double2 v;
    std::memcpy(&v, c + 2 * i, sizeof v);
    z += v - v;
  }
  return (z[0] + z[1]) == 0.0;
}

// (x - a)·((b - a)×(c - a)) for the vertices x of one triangle and the plane abc of the other, as
// det3_eval evaluates o3 (the kernel's plane_distances), both planes at once: lane 0 of s[k] T1's
// vertex k against π2, lane 1 T2's against π1; two normals for the instructions of one, and each
// lane the scalar evaluation's operations, so the same values bit for bit.
inline void plane_values(const double* c, Double2 (&s)[3]) {
  const auto at = [c](int i) { return both_at(c, i); };  // vertex i / 3's coordinate i % 3, T1 | T2
  const Double2 ux = at(3) - at(0), uy = at(4) - at(1), uz = at(5) - at(2);
  const Double2 vx = at(6) - at(0), vy = at(7) - at(1), vz = at(8) - at(2);
  // each triangle's normal in its own lane, then exchanged: lane 0 π2's, lane 1 π1's
  const Double2 nx = swapped(uy * vz - uz * vy), ny = swapped(uz * vx - ux * vz), nz = swapped(ux * vy - uy * vx);
  const Double2 ax = swapped(at(0)), ay = swapped(at(1)), az = swapped(at(2));
  for (int k = 0; k < 3; ++k) s[k] = ((at(3 * k) - ax) * nx + (at(3 * k + 1) - ay) * ny) + (at(3 * k + 2) - az) * nz;
}

}  // namespace tritri::exact::detail
