// Shen, Heng & Tang 2003, "A Fast Triangle-Triangle Overlap Test Using Signed Distances",
// journal of graphics tools 8(1):3–15, 2003 (pages as given in the published file header).
//
// A port of the authors' published routine tri_tri_intersect (jgt-code,
// Volume_08/Number_1/Shen2003/tri_tri.c, "updated 2001-11-22"), with USE_EPSILON_TEST on as
// published. The same floating-point operations on the same operands in the same order, and a
// branch exactly where the published code branches: wherever the published code is defined
// the answer is its answer bit for bit (checked against the published C, compiled for double).
//
// The published arithmetic (V = T1 = pair.t1, U = T2 = pair.t2; note the planes are taken in
// the opposite order from Möller's code, which this routine started from):
//   1. N1 = (U1 − U0)×(U2 − U0), d1 = −N1·U0; dv_i = N1·V_i + d1 (summed x + y, + z, + d1).
//      Snap |dv_i| < 1e-7 → +0. Reject if dv0·dv1 > 0 and dv0·dv2 > 0.
//   2. N2 = (V1 − V0)×(V2 − V0), d2 = −N2·V0; du_i likewise; snap; reject.
//   3. dv all zero: coplanar → Möller's coplanar_tri_tri(N1, V, U) (N1 is U's normal here).
//   4. Rotate V so that its vertex alone on its side of π_U comes first (VV0, VV1, VV2 with
//      distances tdv0, tdv1), and U likewise (UU0.., tdu0, tdu1); "alone" is the published
//      SIGN01_DIF_SIGN2 test, tried for vertex 0, 1, 2 in turn.
//   5. Two signed line–line "distances", unnormalised: for edges e (of V) and f (of U),
//      ((e)×(f))·(UU0 − VV0). Which edges, and which side is rejected, depend on the signs of
//      tdu0, tdu1, tdv0, tdv1 (four cases). Reject when the first is > 1e-7 (resp. < −1e-7) or
//      the second < −1e-7 (resp. > 1e-7); otherwise they overlap.
//
// Tolerance: EPSILON = 1e-7, absolute, applied to (a) the unnormalised plane distances N·X + d
// (snapped to 0 when |·| < 1e-7) and (b) the unnormalised line–line values of step 5 (a
// triple product of two edge vectors and a vertex difference: degree 3 in the coordinates).
// Neither is a length; the tolerance does not scale with the input.
//
// Undefined behaviour in the published code, and what this port does instead:
// - Step 3 tests only dv. When all three du snap to 0 but not all three dv (the two sets are
//   scaled by |N2| and |N1|, which differ; e.g. V much smaller than U), no vertex of U passes
//   the "alone" test and the published code reads the uninitialised pointers UU0, UU1, UU2 and
//   the distances tdu0, tdu1. This port takes the coplanar branch there too: coplanar_tri_tri
//   (N1, V, U), the call the published code makes when dv vanish.
// - A NaN distance makes every "alone" test false as well (same uninitialised read in the
//   published code). This port treats a NaN like the all-zero case; NaN input is outside the
//   harness's domain.
//
// Choices: Boundary closed, with the tolerance's slack. Degenerate triangles: not handled.
#pragma once

#include "algorithms/moller97/moller97.hpp"  // coplanar_tri_tri: the published file carries a copy of Möller's

#include "tritri/answers.hpp"

#include <cmath>
#include <type_traits>

namespace tritri::shen03 {

inline constexpr double kTolerance = 1e-7;  // the published EPSILON

namespace detail {

// The float original compares float values with the double EPSILON, i.e. in double.
template <class T>
inline bool above(const T& x, double limit) {
  if constexpr (std::is_same_v<T, float>) return static_cast<double>(x) > limit;
  else return x > T(limit);
}
template <class T>
inline bool below(const T& x, double limit) {
  if constexpr (std::is_same_v<T, float>) return static_cast<double>(x) < limit;
  else return x < T(limit);
}

// |d| < EPSILON, with the published FABS (x >= 0 ? x : −x: the same comparisons as fabs).
template <class T>
inline T snap(const T& d) {
  using std::abs;
  return below(abs(d), kTolerance) ? T(0) : d;
}

// The published file computes its planes as Möller's does, operation for operation.
using moller97::detail::Plane;
using moller97::detail::plane_through;

template <class T>
inline T height(const Plane<T>& p, const T* x) {
  return snap(p.n[0] * x[0] + p.n[1] * x[1] + p.n[2] * x[2] + p.d);
}

template <class T>
inline bool one_side(const T& d0, const T& d1, const T& d2) {
  return d0 * d1 > T(0) && d0 * d2 > T(0);
}

// The published SIGN01_DIF_SIGN2(a, b, c): a and b on one side (zero allowed on one side of the
// comparison), c on the other.
template <class T>
inline bool alone(const T& a, const T& b, const T& c) {
  return (a >= T(0) && b >= T(0) && c < T(0)) || (a <= T(0) && b <= T(0) && c > T(0)) ||
         (a > T(0) && b > T(0) && c <= T(0)) || (a < T(0) && b < T(0) && c >= T(0));
}

// Step 4 for one triangle: its vertices rotated so the lone one is first, and the first two
// distances. False when no vertex passes (the published undefined case).
template <class T>
struct Rotated {
  const T *x0, *x1, *x2;
  T d0, d1;
};

template <class T>
inline bool rotate(const T* x0, const T* x1, const T* x2, const T& d0, const T& d1, const T& d2,
                   Rotated<T>& r) {
  if (alone(d1, d2, d0)) r = {x0, x1, x2, d0, d1};
  else if (alone(d2, d0, d1)) r = {x1, x2, x0, d1, d2};
  else if (alone(d0, d1, d2)) r = {x2, x0, x1, d2, d0};
  else return false;
  return true;
}

// ((a1 − a0)×(b1 − b0))·w, the published unnormalised line–line value.
template <class T>
inline T line_line(const T* a1, const T* a0, const T* b1, const T* b0, const T (&w)[3]) {
  const T ex = a1[0] - a0[0], ey = a1[1] - a0[1], ez = a1[2] - a0[2];
  const T fx = b1[0] - b0[0], fy = b1[1] - b0[1], fz = b1[2] - b0[2];
  const T nx = ey * fz - ez * fy, ny = ez * fx - ex * fz, nz = ex * fy - ey * fx;
  return nx * w[0] + ny * w[1] + nz * w[2];
}

}  // namespace detail

template <class T>
bool overlap(const PairT<T>& pair) {
  using namespace detail;
  const T *v0 = pair.t1[0].data(), *v1 = pair.t1[1].data(), *v2 = pair.t1[2].data();
  const T *u0 = pair.t2[0].data(), *u1 = pair.t2[1].data(), *u2 = pair.t2[2].data();
  // step 1: V against U's plane
  const Plane<T> pu = plane_through(u0, u1, u2);
  const T dv0 = height(pu, v0), dv1 = height(pu, v1), dv2 = height(pu, v2);
  if (one_side(dv0, dv1, dv2)) return false;
  // step 2: U against V's plane
  const Plane<T> pv = plane_through(v0, v1, v2);
  const T du0 = height(pv, u0), du1 = height(pv, u1), du2 = height(pv, u2);
  if (one_side(du0, du1, du2)) return false;
  // pu.n by value: given its address, the compiler would keep pu in memory from step 1 on
  const auto coplanar = [&] {
    return moller97::detail::coplanar_tri_tri_out_of_line(pu.n[0], pu.n[1], pu.n[2], v0, v1, v2, u0, u1, u2);
  };
  // step 3
  if (dv0 == T(0) && dv1 == T(0) && dv2 == T(0)) return coplanar();
  // step 4
  Rotated<T> vv, uu;
  if (!rotate(v0, v1, v2, dv0, dv1, dv2, vv)) return coplanar();  // NaN only
  if (!rotate(u0, u1, u2, du0, du1, du2, uu)) return coplanar();  // published: undefined
  // step 5
  const T w[3] = {uu.x0[0] - vv.x0[0], uu.x0[1] - vv.x0[1], uu.x0[2] - vv.x0[2]};
  const bool u_down = uu.d0 >= T(0) && uu.d1 <= T(0);
  const bool v_down = vv.d0 >= T(0) && vv.d1 <= T(0);
  // edges of V: a = VV0−VV2 (the edge into VV0), b = VV1−VV0 (out of it); of U likewise
  if (u_down) {
    if (v_down) {
      if (above(line_line(vv.x0, vv.x2, uu.x0, uu.x2, w), kTolerance)) return false;
      if (below(line_line(vv.x1, vv.x0, uu.x1, uu.x0, w), -kTolerance)) return false;
    } else {
      if (above(line_line(vv.x1, vv.x0, uu.x0, uu.x2, w), kTolerance)) return false;
      if (below(line_line(vv.x0, vv.x2, uu.x1, uu.x0, w), -kTolerance)) return false;
    }
  } else {
    if (v_down) {
      if (above(line_line(vv.x0, vv.x2, uu.x1, uu.x0, w), kTolerance)) return false;
      if (below(line_line(vv.x1, vv.x0, uu.x0, uu.x2, w), -kTolerance)) return false;
    } else {
      if (above(line_line(vv.x1, vv.x0, uu.x1, uu.x0, w), kTolerance)) return false;
      if (below(line_line(vv.x0, vv.x2, uu.x0, uu.x2, w), -kTolerance)) return false;
    }
  }
  return true;
}

}  // namespace tritri::shen03
