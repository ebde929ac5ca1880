// The predicate policies the exact classification (classify.hpp) is written against.
// Each gives exact signs of
//   d3(A0,A1,B0,B1,C0,C1) = det[A1-A0, B1-B0, C1-C0]       (o3(a,b,c,d) = d3(a,b,a,c,a,d))
//   o2(a,b,c,i,j)         = (b-a)_i (c-a)_j - (b-a)_j (c-a)_i
// on a set of inputs stated per policy:
//   Plain     evaluates in double and takes the sign: exact on a pair that passes grid_exact()
//             (every coordinate a multiple of 2^q and below 2^(q+15) in magnitude: every
//             intermediate is then an integer multiple of 2^q, 2^2q or 2^3q below 2^53).
//   Filtered  evaluates in double with a semi-static error bound per call; the sign is
//             returned when |value| exceeds the bound, else the integer engine decides
//             (intexact.hpp).
//   IntExact  the integer engine always (tests).
// (The tests add a fourth, independent policy on floating-point expansions and GMP,
// algorithms/exact/tests/expansions.hpp, to cross-check the integer engine.)
// The error bounds are derived in algorithms/exact/README.md ("Error bounds"); the constants are here.
#pragma once

#include "algorithms/exact/detail/intexact.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace tritri::exact {

using P = const double*;

namespace bound {
inline constexpr double kU = 0x1p-53;  // unit roundoff of double
// det3 in the form u·(v×w) of three computed differences, with X,Y,Z upper bounds (computed)
// of the |x|, |y|, |z| components of the differences: |error| < kRel3·X·Y·Z + kAbs3, valid when
// max(X,Y,Z) <= kMax3, and the bound itself computed as fl(fl(fl(kRel3·X)·Y)·Z) + kAbs3.
inline constexpr double kRel3 = 49.0 * kU;
inline constexpr double kAbs3 = 0x1p-737;
inline constexpr double kMax3 = 0x1p333;
// X, Y, Z are raised to at least kMin3 before the product (still upper bounds): no partial
// product of the bound can then underflow and be magnified by a later factor.
inline constexpr double kMin3 = 0x1p-330;
// det2 (b-a)_i (c-a)_j - (b-a)_j (c-a)_i: |error| < kRel2·X_i·X_j + kAbs2 when max <= kMax2.
inline constexpr double kRel2 = 9.0 * kU;
inline constexpr double kAbs2 = 0x1p-1070;
inline constexpr double kMax2 = 0x1p500;
inline constexpr double kMin2 = 0x1p-480;  // X_i, X_j raised to at least this (as kMin3)
// Second, dynamic stage (per call, when the semi-static bound does not decide): with P the
// computed permanent (the same sum with every product taken in absolute value),
// |error| < kPerm3·P + kAbs3 (det3, under kMax3) and kPerm2·P + kAbs2 (det2, under kMax2).
inline constexpr double kPerm3 = 9.0 * kU;
inline constexpr double kPerm2 = 5.0 * kU;
}  // namespace bound

// ---- the evaluated expressions (identical in every policy and in the error analysis) ----

// max without dmax's library call; a NaN operand yields the other one or NaN, and every
// use below only needs an upper bound of finite-or-infinite magnitudes (never NaN).
inline double dmax(double a, double b) { return a > b ? a : b; }

struct Det3 {
  double value, x, y, z;  // value, and the largest |component| of the differences per axis
  double perm;            // the permanent: sum of |u_k|·(|v_i w_j| + |v_j w_i|)
};

// Always inlined: most callers read only `value`, and the rest is then dead code (out of line,
// every call would compute the permanent and the maxima too).
[[gnu::always_inline]] inline Det3 det3_eval(P a0, P a1, P b0, P b1, P c0, P c1) {
  const double ux = a1[0] - a0[0], uy = a1[1] - a0[1], uz = a1[2] - a0[2];
  const double vx = b1[0] - b0[0], vy = b1[1] - b0[1], vz = b1[2] - b0[2];
  const double wx = c1[0] - c0[0], wy = c1[1] - c0[1], wz = c1[2] - c0[2];
  const double p1 = vy * wz, p2 = vz * wy, p3 = vz * wx, p4 = vx * wz, p5 = vx * wy, p6 = vy * wx;
  const double mx = p1 - p2;
  const double my = p3 - p4;
  const double mz = p5 - p6;
  Det3 d;
  d.value = (ux * mx + uy * my) + uz * mz;
  d.perm = (std::fabs(ux) * (std::fabs(p1) + std::fabs(p2)) + std::fabs(uy) * (std::fabs(p3) + std::fabs(p4))) +
           std::fabs(uz) * (std::fabs(p5) + std::fabs(p6));
  d.x = dmax(std::fabs(ux), dmax(std::fabs(vx), std::fabs(wx)));
  d.y = dmax(std::fabs(uy), dmax(std::fabs(vy), std::fabs(wy)));
  d.z = dmax(std::fabs(uz), dmax(std::fabs(vz), std::fabs(wz)));
  return d;
}

inline double det2_value(P a, P b, P c, int i, int j) {
  const double bi = b[i] - a[i], bj = b[j] - a[j], ci = c[i] - a[i], cj = c[j] - a[j];
  return bi * cj - bj * ci;
}

inline int sgn(double v) { return (v > 0.0) - (v < 0.0); }

// The semi-static det2 bound from upper bounds ei, ej of the |differences| along i and j (e.g.
// the extents max - min of the points involved): +inf when out of range.
inline double det2_bound(double ei, double ej) {
  if (!(dmax(ei, ej) <= bound::kMax2)) return __builtin_inf();
  ei = dmax(ei, bound::kMin2), ej = dmax(ej, bound::kMin2);
  return bound::kRel2 * ei * ej + bound::kAbs2;
}

// 0: uncertain (the bound does not decide); else the certain sign.
// The semi-static det3 bound from upper bounds x, y, z of the |differences| per axis.
inline double det3_bound(double x, double y, double z) {
  if (!(dmax(x, dmax(y, z)) <= bound::kMax3)) return __builtin_inf();
  x = dmax(x, bound::kMin3), y = dmax(y, bound::kMin3), z = dmax(z, bound::kMin3);
  return bound::kRel3 * x * y * z + bound::kAbs3;
}

inline int det3_filtered_sign(const Det3& d) {
  const double b = det3_bound(d.x, d.y, d.z);
  return (d.value > b) - (d.value < -b);
}

// The bound of the batch kernel (kernel.inc) for one pair: 18 coordinates a1 b1 c1 a2 b2 c2.
// Valid for every det3 of four of the six points evaluated as det3_eval evaluates it (the
// kernel's plane tests (x-a)·((b-a)×(c-a)) and Guigue–Devillers' G1, G2 are of that form).
// +inf when the extents exceed kMax3. Written out in scalar for the tests.
inline double pair_bound3(const double* c) {
  double e[3];
  for (int k = 0; k < 3; ++k) {
    double lo = c[k], hi = c[k];
    for (int v = 1; v < 6; ++v) {
      lo = c[3 * v + k] < lo ? c[3 * v + k] : lo;
      hi = c[3 * v + k] > hi ? c[3 * v + k] : hi;
    }
    e[k] = hi - lo;
  }
  return det3_bound(e[0], e[1], e[2]);
}

// ---- policies ----

// o2_with(value, bound, ...): the sign of o2(a,b,c,i,j) given its value as computed by
// det2_value and a bound valid for it (algorithms/exact/README.md: kRel2·Ei·Ej + kAbs2 with Ei, Ej upper bounds
// of the |differences| along i and j, when both are at most kMax2; +inf otherwise).

struct Plain {
  static int d3(P a0, P a1, P b0, P b1, P c0, P c1) { return sgn(det3_eval(a0, a1, b0, b1, c0, c1).value); }
  static int o3(P a, P b, P c, P d) { return d3(a, b, a, c, a, d); }
  static int o2(P a, P b, P c, int i, int j) { return sgn(det2_value(a, b, c, i, j)); }
  static int o2_with(double value, double, P, P, P, int, int) { return sgn(value); }
  static int o3_with(double value, double, P, P, P, P) { return sgn(value); }
};

// Every sign exact, from an engine's det3_sign(p[6]) and det2_sign(a, b, c, i, j).
template <int (*Det3)(const double* const[6]), int (*Det2)(P, P, P, int, int)>
struct ExactSigns {
  static int d3(P a0, P a1, P b0, P b1, P c0, P c1) {
    const double* p[6] = {a0, a1, b0, b1, c0, c1};
    return Det3(p);
  }
  static int o3(P a, P b, P c, P d) { return d3(a, b, a, c, a, d); }
  static int o2(P a, P b, P c, int i, int j) { return Det2(a, b, c, i, j); }
  static int o2_with(double, double, P a, P b, P c, int i, int j) { return o2(a, b, c, i, j); }
  static int o3_with(double, double, P a, P b, P c, P d) { return o3(a, b, c, d); }
};

// The algorithm's exact engine (intexact.hpp).
using IntExact = ExactSigns<intexact::det3_sign, intexact::det2_sign>;

// The signs are computed without a branch on their value (a branch on the sign of a random
// determinant is mispredicted half the time); the only branch is "certain?", rarely false.
struct Filtered {
  static int d3(P a0, P a1, P b0, P b1, P c0, P c1) {
    const Det3 d = det3_eval(a0, a1, b0, b1, c0, c1);
    if (const int s = det3_filtered_sign(d); __builtin_expect(s != 0, 1)) return s;
    // the dynamic bound (it cannot decide a computed zero: |0| > b never holds)
    if ((d.value != 0.0) & (dmax(d.x, dmax(d.y, d.z)) <= bound::kMax3)) {
      const double b = bound::kPerm3 * d.perm + bound::kAbs3;
      if (const int s = (d.value > b) - (d.value < -b)) return s;
    }
    return IntExact::d3(a0, a1, b0, b1, c0, c1);
  }
  static int o3(P a, P b, P c, P d) { return d3(a, b, a, c, a, d); }
  static int o2(P a, P b, P c, int i, int j) {
    const double bi = b[i] - a[i], bj = b[j] - a[j], ci = c[i] - a[i], cj = c[j] - a[j];
    const double v = bi * cj - bj * ci;
    const double b2 = det2_bound(dmax(std::fabs(bi), std::fabs(ci)), dmax(std::fabs(bj), std::fabs(cj)));
    const int s = (v > b2) - (v < -b2);
    if (__builtin_expect(s != 0, 1)) return s;
    return dynamic2(a, b, c, i, j);
  }
  // The dynamic det2 bound, then the integer engine.
  static int dynamic2(P a, P b, P c, int i, int j) {
    const double bi = b[i] - a[i], bj = b[j] - a[j], ci = c[i] - a[i], cj = c[j] - a[j];
    const double q1 = bi * cj, q2 = bj * ci;
    const double v = q1 - q2;
    if ((v != 0.0) & (dmax(dmax(std::fabs(bi), std::fabs(ci)), dmax(std::fabs(bj), std::fabs(cj))) <= bound::kMax2)) {
      const double b2 = bound::kPerm2 * (std::fabs(q1) + std::fabs(q2)) + bound::kAbs2;
      if (const int s = (v > b2) - (v < -b2)) return s;
    }
    return intexact::det2_sign(a, b, c, i, j);
  }
  static int o2_with(double value, double bound, P a, P b, P c, int i, int j) {
    const int s = (value > bound) - (value < -bound);
    if (__builtin_expect(s != 0, 1)) return s;
    return dynamic2(a, b, c, i, j);
  }
  // value: o3(a,b,c,d) as det3_eval(a,d,a,b,a,c) evaluates it; bound: valid for it
  static int o3_with(double value, double bound, P a, P b, P c, P d) {
    const int s = (value > bound) - (value < -bound);
    if (__builtin_expect(s != 0, 1)) return s;
    return o3(a, b, c, d);
  }
};

// The exact signs of the three points at `pts` against the plane of the triangle at `pl` when
// that triangle lies in an axis-parallel plane x_k = h (its three points share coordinate k
// exactly): o3(a, b, c, x) = (x_k - h)·o2(a, b, c; k+1, k+2), so each sign is a comparison times
// one o2 sign for the three (algorithms/exact/README.md, "A triangle in an axis-parallel
// plane"). False, and `s` untouched, when the triangle shares no coordinate. Finite input.
inline bool axis_plane_signs(const double* pl, const double* pts, int s[3]) {
  const bool on_x = (pl[0] == pl[3]) & (pl[0] == pl[6]), on_y = (pl[1] == pl[4]) & (pl[1] == pl[7]);
  const bool on_z = (pl[2] == pl[5]) & (pl[2] == pl[8]);
  if (!(on_x | on_y | on_z)) return false;
  const int k = on_x ? 0 : (on_y ? 1 : 2);
  const int i = k == 2 ? 0 : k + 1, j = k == 0 ? 2 : k - 1;  // (k+1, k+2) mod 3
  const int orient = Filtered::o2(pl, pl + 3, pl + 6, i, j);
  const double h = pl[k];
  for (int v = 0; v < 3; ++v) s[v] = orient * ((pts[3 * v + k] > h) - (pts[3 * v + k] < h));
  return true;
}

// ---- the grid test that makes Plain exact ----

inline constexpr int kGridBits = 15;  // |coordinate| < 2^(q + 15), every coordinate a multiple of 2^q

// True when all n coordinates are integer multiples of one power of two 2^q with magnitude
// below 2^(q+15), and 2^(3q) is at least 2^-1074 and the magnitudes at most 2^300: every
// det3/det2 of such coordinates evaluates exactly in double (algorithms/exact/README.md,
// "The grid case (pass 2 and `Plain`)").
inline bool grid_exact(const double* c, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = dmax(m, std::fabs(c[i]));
  if (m == 0.0) return true;
  if (!(m <= 0x1p300)) return false;
  int lead, last;
  intexact::bit_range(m, lead, last);
  const int q = lead + 1 - kGridBits;  // m < 2^(lead+1) = 2^(q+15)
  if (3 * q < -1074) return false;
  for (int i = 0; i < n; ++i) {
    if (c[i] == 0.0) continue;
    intexact::bit_range(c[i], lead, last);
    if (last < q) return false;
  }
  return true;
}

inline bool all_finite(const double* c, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(c[i])) return false;
  return true;
}

}  // namespace tritri::exact
