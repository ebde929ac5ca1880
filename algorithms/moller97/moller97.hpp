// Möller 1997, "A Fast Triangle-Triangle Intersection Test", journal of graphics tools 2(2):25–30.
// doi:10.1080/10867651.1997.10487472
//
// A port of the author's published code (jgt-code, Volume_02/Number_2/Moller1997b):
//   overlap<T, true>                 tri_tri_intersect in tritri_isectline.c (the paper's test)
//   overlap_division_free<T, true>   NoDivTriTriIsect in opttritri.c (the 1999 division-free code)
//   segment<T, true>                 tri_tri_intersect_with_isectline (2001, returns the segment)
//   overlap_with_segment<T, true>    that function's own 0/1 answer
// Snap = false is the same code without the EPSILON snap (variant moller97-nosnap).
//
// "Port" means: the same floating-point operations, on the same operands, in the same order,
// and a branch exactly where the published code branches, so that wherever the published code
// has defined behaviour the answer is the same bit for bit (checked against the published C,
// compiled for double, on millions of random, integer-grid and near-degenerate pairs). What is
// ours is the structure: each step is a small function, and the six-way case analysis of the
// interval computation is written once (`with_lone_vertex`) and shared by the three variants.
//
// The published arithmetic, step by step (V = T1 = pair.t1, U = T2 = pair.t2):
//   1. N1 = (V1 − V0)×(V2 − V0), d1 = −N1·V0. du_i = N1·U_i + d1 (dot products summed
//      x + y, then + z, then + d1). Snap: |du_i| < 1e-6 → +0. Reject if du0·du1 > 0 and
//      du0·du2 > 0 (products, not signs: this is what decides, underflow included).
//   2. The same with N2 = (U1 − U0)×(U2 − U0), d2 = −N2·U0 for the dv_i of V's vertices.
//   3. D = N1×N2; the axis of its largest |component| (first on ties); the vertices' coordinates
//      on that axis stand in for their projections on the intersection line.
//   4. For each triangle (V first, then U), the vertex alone on its side (see with_lone_vertex)
//      and the two points where its edges cross the other plane, on that axis:
//        overlap:       p_k + ((p_a − p_k)·d_k) / (d_k − d_a)
//        segment:       t = d_k / (d_k − d_a); p_k + (p_a − p_k)·t   (and the 3-D point
//                       V_k + t·(V_a − V_k))
//        division-free: the numerators and denominators, cross-multiplied (see below)
//      All distances of a triangle zero: coplanar → coplanar_tri_tri(N1, V, U).
//   5. Sort each interval (swap if lo > hi) and report overlap unless hi1 < lo2 or hi2 < lo1.
//
// Undefined behaviour in the published code, and what this port does instead:
// - tri_tri_intersect_with_isectline ignores the "coplanar" result of U's interval computation
//   (it checks only V's): when the snap zeroes all three du but not all three dv (possible: the
//   two sets of distances are scaled by |N1| and |N2|, which differ), it goes on with U's
//   interval and points unset. This port takes the coplanar branch there, as tri_tri_intersect
//   and NoDivTriTriIsect do (their macro returns from either interval computation): the answer is
//   coplanar_tri_tri's, and the segment level reports SegmentKind::coplanar (or empty).
//
// Choices the published code leaves to the caller:
// - Coplanar pairs: the segment level reports the coplanar flag and the boolean (kind coplanar
//   when they meet, empty otherwise), never a segment, as published.
// - The segment's two ends are copied from the published selection, ties included; a point
//   contact is reported as SegmentKind::point when the two ends are equal.
// - float: the published snap compares fabs(d) (a double) with the double EPSILON; the float
//   instantiation does the same (it converts |d| to double for that one comparison).
// - Degenerate (zero-area) triangles: not handled; the harness does not pass them.
#pragma once

#include "tritri/answers.hpp"
#include "tritri/inline.hpp"
#include "algorithms/moller97/coplanar.hpp"  // coplanar_tri_tri, step 4's coplanar exit

#include <cmath>
#include <type_traits>
#include <utility>

namespace tritri::moller97 {

inline constexpr double kEpsilon = 1e-6;  // the published EPSILON, absolute, on N·X + d

namespace detail {

// ---- plane tests (steps 1–2) ----

template <class T>
struct Plane {
  T n[3];  // (b − a)×(c − a), unnormalised
  T d;     // −n·a
};

template <class T>
inline Plane<T> plane_through(const T* a, const T* b, const T* c) {
  const T e1x = b[0] - a[0], e1y = b[1] - a[1], e1z = b[2] - a[2];
  const T e2x = c[0] - a[0], e2y = c[1] - a[1], e2z = c[2] - a[2];
  Plane<T> p;
  p.n[0] = e1y * e2z - e1z * e2y;
  p.n[1] = e1z * e2x - e1x * e2z;
  p.n[2] = e1x * e2y - e1y * e2x;
  p.d = -(p.n[0] * a[0] + p.n[1] * a[1] + p.n[2] * a[2]);
  return p;
}

// |d| < EPSILON, compared as the published code compares it (fabs returns a double).
template <class T>
inline bool within_epsilon(const T& d) {
  using std::abs;
  if constexpr (std::is_same_v<T, float>) {
    return static_cast<double>(abs(d)) < kEpsilon;
  } else {
    return abs(d) < T(kEpsilon);
  }
}

// The unnormalised signed distances of three points to a plane, snapped, and the two products
// the published code decides with.
template <class T>
struct Heights {
  T d[3];
  T d0d1, d0d2;

  // All three strictly on one side (as products: an underflowing product does not reject).
  bool one_side() const { return d0d1 > T(0) && d0d2 > T(0); }
};

// One snapped distance. +0 when snapped, as published; written as a select rather than a
// conditional store (a branch here is unpredictable, and a store cannot be if-converted).
template <class T, bool Snap>
inline T height(const Plane<T>& p, const T* x) {
  const T d = p.n[0] * x[0] + p.n[1] * x[1] + p.n[2] * x[2] + p.d;
  if constexpr (Snap) {
    return within_epsilon(d) ? T(0) : d;
  } else {
    return d;
  }
}

template <class T, bool Snap>
inline Heights<T> heights(const Plane<T>& p, const T* x0, const T* x1, const T* x2) {
  Heights<T> h;
  h.d[0] = height<T, Snap>(p, x0);
  h.d[1] = height<T, Snap>(p, x1);
  h.d[2] = height<T, Snap>(p, x2);
  h.d0d1 = h.d[0] * h.d[1];
  h.d0d2 = h.d[0] * h.d[2];
  return h;
}

// Step 3: the axis of the largest |component| of D = N1×N2 (the first one on ties).
template <class T>
inline int line_axis(const T (&n1)[3], const T (&n2)[3]) {
  using std::abs;
  const T dx = n1[1] * n2[2] - n1[2] * n2[1];
  const T dy = n1[2] * n2[0] - n1[0] * n2[2];
  const T dz = n1[0] * n2[1] - n1[1] * n2[0];
  T largest = abs(dx);
  int axis = 0;
  const T ay = abs(dy), az = abs(dz);
  if (ay > largest) largest = ay, axis = 1;
  if (az > largest) largest = az, axis = 2;
  return axis;
}

// ---- step 4: the case analysis shared by the three variants ----

// Which vertex K is alone on its side of the other plane, and its two partners A < B. The
// published order of the tests matters: with zero distances several vertices could serve, and
// the one chosen decides the rounding (and which of the two end points comes first).
template <int K, int A, int B>
struct Lone {};

// Calls f(Lone<K, A, B>{}) for the published choice; false (f not called) when all three
// distances are zero, i.e. the triangle lies in the other plane.
template <class T, class F>
TRITRI_FORCE_INLINE bool with_lone_vertex(const Heights<T>& h, F&& f) {
  if (h.d0d1 > T(0)) {  // 0 and 1 strictly on one side: 2 alone (on the other side or on it)
    f(Lone<2, 0, 1>{});
  } else if (h.d0d2 > T(0)) {  // 0 and 2 on one side: 1 alone
    f(Lone<1, 0, 2>{});
  } else if (h.d[1] * h.d[2] > T(0) || h.d[0] != T(0)) {  // 1 and 2 on one side, or 0 off
    f(Lone<0, 1, 2>{});
  } else if (h.d[1] != T(0)) {
    f(Lone<1, 0, 2>{});
  } else if (h.d[2] != T(0)) {
    f(Lone<2, 0, 1>{});
  } else {
    return false;
  }
  return true;
}

template <class T>
inline void sort2(T& lo, T& hi) {
  if (lo > hi) std::swap(lo, hi);
}

// Step 4 of tri_tri_intersect for lone vertex k and partners a, b.
template <int K, int A, int B, class T>
inline void ends_with_division(Lone<K, A, B>, const T (&p)[3], const Heights<T>& h, T (&out)[2]) {
  out[0] = p[K] + (p[A] - p[K]) * h.d[K] / (h.d[K] - h.d[A]);
  out[1] = p[K] + (p[B] - p[K]) * h.d[K] / (h.d[K] - h.d[B]);
}

// Step 4 of NoDivTriTriIsect: each end is a + b/x0 (resp. a + c/x1), kept as a fraction.
template <class T>
struct Fraction {
  T a, b, c, x0, x1;
};

template <int K, int A, int B, class T>
inline void fraction(Lone<K, A, B>, const T (&p)[3], const Heights<T>& h, Fraction<T>& out) {
  out.a = p[K];
  out.b = (p[A] - p[K]) * h.d[K];
  out.c = (p[B] - p[K]) * h.d[K];
  out.x0 = h.d[K] - h.d[A];
  out.x1 = h.d[K] - h.d[B];
}

// Steps 1–3, shared. Returns false when a plane test rejects.
template <class T, bool Snap>
struct Planes {
  const T* v[3];
  const T* u[3];
  Plane<T> p1, p2;
  Heights<T> du, dv;  // U against plane 1; V against plane 2
  T vp[3], up[3];     // coordinates on the axis of the line

  // The normal by value: a call given the address of a member would keep all of this in memory,
  // stored before the plane tests reject (it cost moller97-segment 9% at ratio 0).
  TRITRI_FORCE_INLINE bool coplanar() const {
    return coplanar_tri_tri_out_of_line(p1.n[0], p1.n[1], p1.n[2], v[0], v[1], v[2], u[0], u[1], u[2]);
  }
};

template <class T, bool Snap>
TRITRI_FORCE_INLINE bool planes(const PairT<T>& pair, Planes<T, Snap>& s) {
  s.v[0] = pair.t1[0].data(), s.v[1] = pair.t1[1].data(), s.v[2] = pair.t1[2].data();
  s.u[0] = pair.t2[0].data(), s.u[1] = pair.t2[1].data(), s.u[2] = pair.t2[2].data();
  s.p1 = plane_through(s.v[0], s.v[1], s.v[2]);
  s.du = heights<T, Snap>(s.p1, s.u[0], s.u[1], s.u[2]);
  if (s.du.one_side()) return false;
  s.p2 = plane_through(s.u[0], s.u[1], s.u[2]);
  s.dv = heights<T, Snap>(s.p2, s.v[0], s.v[1], s.v[2]);
  if (s.dv.one_side()) return false;
  const int axis = line_axis(s.p1.n, s.p2.n);
  s.vp[0] = s.v[0][axis], s.vp[1] = s.v[1][axis], s.vp[2] = s.v[2][axis];
  s.up[0] = s.u[0][axis], s.up[1] = s.u[1][axis], s.up[2] = s.u[2][axis];
  return true;
}

}  // namespace detail

// Möller's coplanar test on a normal and two triangles (used by other ports and the oracle).
template <class T>
bool coplanar_overlap(const Vec3<T>& n, const TriangleT<T>& t1, const TriangleT<T>& t2) {
  return detail::coplanar_tri_tri(n.data(), t1[0].data(), t1[1].data(), t1[2].data(), t2[0].data(),
                                  t2[1].data(), t2[2].data());
}

// ---- tri_tri_intersect ----

template <class T, bool Snap = true>
bool overlap(const PairT<T>& pair) {
  using namespace detail;
  Planes<T, Snap> s;
  if (!planes(pair, s)) return false;
  // Step 4: the ends on the line, with the product divided last, as published.
  T i1[2], i2[2];
  if (!with_lone_vertex(s.dv, [&](auto lone) TRITRI_INLINE_LAMBDA { ends_with_division(lone, s.vp, s.dv, i1); }))
    return s.coplanar();
  if (!with_lone_vertex(s.du, [&](auto lone) TRITRI_INLINE_LAMBDA { ends_with_division(lone, s.up, s.du, i2); }))
    return s.coplanar();
  sort2(i1[0], i1[1]);  // step 5
  sort2(i2[0], i2[1]);
  return !(i1[1] < i2[0] || i2[1] < i1[0]);
}

// ---- NoDivTriTriIsect ----

// Each end is A + B/X: keep A (the lone vertex's coordinate), the numerators B, C and the
// denominators X0, X1, and compare both intervals multiplied through by X0·X1·Y0·Y1.
template <class T, bool Snap = true>
bool overlap_division_free(const PairT<T>& pair) {
  using namespace detail;
  Planes<T, Snap> s;
  if (!planes(pair, s)) return false;
  Fraction<T> f, g;
  if (!with_lone_vertex(s.dv, [&](auto lone) TRITRI_INLINE_LAMBDA { fraction(lone, s.vp, s.dv, f); }))
    return s.coplanar();
  if (!with_lone_vertex(s.du, [&](auto lone) TRITRI_INLINE_LAMBDA { fraction(lone, s.up, s.du, g); }))
    return s.coplanar();
  const T xx = f.x0 * f.x1, yy = g.x0 * g.x1, xxyy = xx * yy;
  T base = f.a * xxyy;
  T i1[2] = {base + f.b * f.x1 * yy, base + f.c * f.x0 * yy};
  base = g.a * xxyy;
  T i2[2] = {base + g.b * xx * g.x1, base + g.c * xx * g.x0};
  sort2(i1[0], i1[1]);
  sort2(i2[0], i2[1]);
  return !(i1[1] < i2[0] || i2[1] < i1[0]);
}

// ---- tri_tri_intersect_with_isectline ----

namespace detail {

// One triangle's interval as the segment variant computes it: the edge parameter first
// (t = d_k / (d_k − d_x)), then the coordinate on the line and, only when asked for, the point.
// The points are computed after the overlap is known, from the same t: same values, less work.
template <class T>
struct SegmentEnds {
  const T* from;     // the lone vertex
  const T* to[2];    // its partners, in the published order
  T t[2];            // edge parameters
  T on_line[2];      // coordinates on the line's axis, unsorted
  bool swapped;      // the published `smallest` flag: on_line was out of order and got swapped

  void point(int which, T (&out)[3]) const {
    // the published isect2(): diff = t·(to − from); first end diff + from, second from + diff
    const T s = t[which];
    const T* y = to[which];
    out[0] = s * (y[0] - from[0]) + from[0];
    out[1] = s * (y[1] - from[1]) + from[1];
    out[2] = s * (y[2] - from[2]) + from[2];
  }
};

template <int K, int A, int B, class T>
inline void segment_ends(Lone<K, A, B>, const T* const (&x)[3], const T (&p)[3], const Heights<T>& h,
                         SegmentEnds<T>& e) {
  e.from = x[K];
  e.to[0] = x[A];
  e.to[1] = x[B];
  e.t[0] = h.d[K] / (h.d[K] - h.d[A]);
  e.on_line[0] = p[K] + (p[A] - p[K]) * e.t[0];
  e.t[1] = h.d[K] / (h.d[K] - h.d[B]);
  e.on_line[1] = p[K] + (p[B] - p[K]) * e.t[1];
}

// The published SORT2: sort, remembering whether the ends were swapped.
template <class T>
inline void sort_ends(SegmentEnds<T>& e) {
  e.swapped = e.on_line[0] > e.on_line[1];
  if (e.swapped) {
    const T t = e.on_line[0];
    e.on_line[0] = e.on_line[1];
    e.on_line[1] = t;
  }
}

enum class SegmentOutcome { disjoint, coplanar_meet, coplanar_apart, segment };

// The whole published function up to the overlap decision; fills the ends when it says segment.
template <class T, bool Snap>
TRITRI_FORCE_INLINE SegmentOutcome segment_intervals(const PairT<T>& pair, SegmentEnds<T>& a, SegmentEnds<T>& b) {
  Planes<T, Snap> s;
  if (!planes(pair, s)) return SegmentOutcome::disjoint;
  const auto coplanar = [&]() TRITRI_INLINE_LAMBDA {
    return s.coplanar() ? SegmentOutcome::coplanar_meet : SegmentOutcome::coplanar_apart;
  };
  if (!with_lone_vertex(s.dv, [&](auto lone) TRITRI_INLINE_LAMBDA { segment_ends(lone, s.v, s.vp, s.dv, a); }))
    return coplanar();
  // Published: this "coplanar" result is ignored and U's ends are read unset (undefined
  // behaviour). Defined here: the coplanar branch, as in tri_tri_intersect.
  if (!with_lone_vertex(s.du, [&](auto lone) TRITRI_INLINE_LAMBDA { segment_ends(lone, s.u, s.up, s.du, b); }))
    return coplanar();
  sort_ends(a);
  sort_ends(b);
  if (a.on_line[1] < b.on_line[0] || b.on_line[1] < a.on_line[0]) return SegmentOutcome::disjoint;
  return SegmentOutcome::segment;
}

}  // namespace detail

template <class T, bool Snap = true>
SegmentAnswer segment(const PairT<T>& pair) {
  using namespace detail;
  SegmentAnswer out;
  out.kind = SegmentKind::empty;
  SegmentEnds<T> a, b;  // V's (T1's) and U's (T2's)
  switch (segment_intervals<T, Snap>(pair, a, b)) {
    case SegmentOutcome::disjoint:
    case SegmentOutcome::coplanar_apart: return out;
    case SegmentOutcome::coplanar_meet: out.kind = SegmentKind::coplanar; return out;
    case SegmentOutcome::segment: break;
  }
  // The overlap of the two intervals; each end is the point of the interval that bounds it,
  // chosen (ties included) as published. `low`/`high` undo the sort: index of the lower end.
  const auto low = [](const SegmentEnds<T>& e) { return e.swapped ? 1 : 0; };
  const auto high = [](const SegmentEnds<T>& e) { return e.swapped ? 0 : 1; };
  T p[3], q[3];
  if (b.on_line[0] < a.on_line[0]) {
    a.point(low(a), p);
    if (b.on_line[1] < a.on_line[1]) b.point(high(b), q);
    else a.point(high(a), q);
  } else {
    b.point(low(b), p);
    if (b.on_line[1] > a.on_line[1]) a.point(high(a), q);
    else b.point(high(b), q);
  }
  out.p = Vec3<double>(static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2]));
  out.q = Vec3<double>(static_cast<double>(q[0]), static_cast<double>(q[1]), static_cast<double>(q[2]));
  out.kind = out.p == out.q ? SegmentKind::point : SegmentKind::segment;
  return out;
}

// The segment variant's own 0/1 (its interval ends round differently from tri_tri_intersect's:
// t is divided first, then multiplied, so the two booleans can differ in the last bit).
template <class T, bool Snap = true>
bool overlap_with_segment(const PairT<T>& pair) {
  using namespace detail;
  SegmentEnds<T> a, b;
  const SegmentOutcome o = segment_intervals<T, Snap>(pair, a, b);
  return o == SegmentOutcome::segment || o == SegmentOutcome::coplanar_meet;
}

}  // namespace tritri::moller97
