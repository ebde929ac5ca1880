// Möller 1997, "A Fast Triangle-Triangle Intersection Test", journal of graphics tools 2(2):25–30.
//
// A port of the published test and of the two later variants by the same author that the
// paper's code page carried: the division-free interval computation and the version that
// returns the intersection segment. Step numbers are the paper's §3 list:
//   1. plane of T2   2. reject if T1 strictly on one side   3. plane of T1
//   4. reject if T2 strictly on one side   5. line direction, projected on its largest axis
//   6. the intervals of each triangle on that line   7. intersect the intervals
//
// Choices the paper leaves open, and what this port does:
// - Order of the planes: the paper's step list (plane of T2 first, T1's vertices tested
//   against it). The published C code names its arguments the other way round; the tests are
//   mirror images and answer alike.
// - Snap: the published code defines EPSILON = 1e-6 and sets any unnormalised plane distance
//   N·V + d with |d| < EPSILON to 0 (Snap = true). It is absolute: it does not scale with the
//   triangles, so large triangles are snapped onto each other's planes from far away and tiny
//   ones always look coplanar. Snap = false is the same test with every comparison exact-zero.
// - Coplanar (all three distances of either triangle zero after the snap; the published code
//   tests this in the interval computation of each triangle, and the snap can zero one
//   triangle's distances and not the other's): project onto the axis plane that drops the
//   largest component of N1; the 9 edge pairs with the segment test of Antonio
//   (Graphics Gems III), then a strict point-in-triangle test of one vertex each way. The edge
//   test never reports a collinear pair (its denominator is zero), but that loses no contact:
//   where collinear edges overlap, an edge adjacent to one of them starts at the end of the
//   shared stretch and meets the other edge there, endpoints counting.
// - Degenerate (zero-area) triangles: not handled by the paper; the harness does not pass them.
#pragma once

#include "tritri/answers.hpp"

#include <cmath>
#include <utility>

namespace tritri::moller97 {

inline constexpr double kEpsilon = 1e-6;  // the published EPSILON

template <class T>
struct Plane {
  Vec3<T> normal;  // unnormalised: (b - a) × (c - a)
  T offset;        // N·X + offset = 0 on the plane
};

template <class T>
Plane<T> plane_of(const TriangleT<T>& t) {
  const Vec3<T> e1 = t[1] - t[0];
  const Vec3<T> e2 = t[2] - t[0];
  Plane<T> p{e1.cross(e2), T(0)};
  p.offset = -p.normal.dot(t[0]);
  return p;
}

// The three signed distances (scaled by |N|) of a triangle's vertices to a plane, snapped.
template <class T>
struct Distances {
  T d[3];
  T d0d1, d0d2;

  bool strictly_one_side() const { return d0d1 > T(0) && d0d2 > T(0); }
};

template <class T, bool Snap>
Distances<T> distances(const Plane<T>& plane, const TriangleT<T>& t) {
  using std::abs;
  Distances<T> r;
  for (int i = 0; i < 3; ++i) {
    r.d[i] = plane.normal.dot(t[i]) + plane.offset;
    if constexpr (Snap) {
      if (abs(r.d[i]) < T(kEpsilon)) r.d[i] = T(0);
    }
  }
  r.d0d1 = r.d[0] * r.d[1];
  r.d0d2 = r.d[0] * r.d[2];
  return r;
}

// Index of the largest |component| (the first on ties, as published).
template <class T>
int largest_axis(const Vec3<T>& v) {
  using std::abs;
  int index = 0;
  T max = abs(v[0]);
  if (abs(v[1]) > max) max = abs(v[1]), index = 1;
  if (abs(v[2]) > max) index = 2;
  return index;
}

// Which vertex is alone on its side of the other plane (the paper's case analysis in step 6).
// Returns -1 when all three distances are zero: the triangles are coplanar.
template <class T>
int lone_vertex(const Distances<T>& s) {
  if (s.d0d1 > T(0)) return 2;  // 0 and 1 on one side, 2 on the other or on the plane
  if (s.d0d2 > T(0)) return 1;
  if (s.d[1] * s.d[2] > T(0) || s.d[0] != T(0)) return 0;
  if (s.d[1] != T(0)) return 1;
  if (s.d[2] != T(0)) return 2;
  return -1;
}

// ---- the coplanar branch ----

template <class T>
struct Projection {
  int i0, i1;  // the two axes kept
};

// Drop the axis of N's largest component, with the published tie-breaking.
template <class T>
Projection<T> coplanar_projection(const Vec3<T>& n) {
  using std::abs;
  const T a0 = abs(n[0]), a1 = abs(n[1]), a2 = abs(n[2]);
  if (a0 > a1) return a0 > a2 ? Projection<T>{1, 2} : Projection<T>{0, 1};
  return a2 > a1 ? Projection<T>{0, 1} : Projection<T>{0, 2};
}

// Antonio's segment test: does edge (v0, v0 + a) meet edge (u0, u1)? Endpoints count.
template <class T>
bool edges_meet(const Projection<T>& p, const Vec3<T>& v0, T ax, T ay, const Vec3<T>& u0,
                const Vec3<T>& u1) {
  const T bx = u0[p.i0] - u1[p.i0], by = u0[p.i1] - u1[p.i1];
  const T cx = v0[p.i0] - u0[p.i0], cy = v0[p.i1] - u0[p.i1];
  const T f = ay * bx - ax * by;
  const T d = by * cx - bx * cy;
  if ((f > T(0) && d >= T(0) && d <= f) || (f < T(0) && d <= T(0) && d >= f)) {
    const T e = ax * cy - ay * cx;
    if (f > T(0)) return e >= T(0) && e <= f;
    return e <= T(0) && e >= f;
  }
  return false;  // f == 0: parallel or collinear edges are never reported
}

template <class T>
bool edge_meets_triangle_edges(const Projection<T>& p, const Vec3<T>& v0, const Vec3<T>& v1,
                               const TriangleT<T>& u) {
  const T ax = v1[p.i0] - v0[p.i0], ay = v1[p.i1] - v0[p.i1];
  return edges_meet(p, v0, ax, ay, u[0], u[1]) || edges_meet(p, v0, ax, ay, u[1], u[2]) ||
         edges_meet(p, v0, ax, ay, u[2], u[0]);
}

// Strictly inside: the three edge-line values have one sign and none is zero.
template <class T>
bool point_strictly_in_triangle(const Projection<T>& p, const Vec3<T>& v, const TriangleT<T>& u) {
  T s[3];
  for (int k = 0; k < 3; ++k) {
    const Vec3<T>& from = u[k];
    const Vec3<T>& to = u[(k + 1) % 3];
    const T a = to[p.i1] - from[p.i1];
    const T b = -(to[p.i0] - from[p.i0]);
    const T c = -a * from[p.i0] - b * from[p.i1];
    s[k] = a * v[p.i0] + b * v[p.i1] + c;
  }
  return s[0] * s[1] > T(0) && s[0] * s[2] > T(0);
}

template <class T>
bool coplanar_overlap(const Vec3<T>& n1, const TriangleT<T>& t1, const TriangleT<T>& t2) {
  const auto p = coplanar_projection(n1);
  // every edge of T1 against every edge of T2
  for (int k = 0; k < 3; ++k)
    if (edge_meets_triangle_edges(p, t1[k], t1[(k + 1) % 3], t2)) return true;
  // then containment, one vertex each way
  return point_strictly_in_triangle(p, t1[0], t2) || point_strictly_in_triangle(p, t2[0], t1);
}

// ---- the published test, with divisions ----

template <class T>
struct Interval {
  T lo, hi;
};

// Step 6 for one triangle, given its lone vertex: where its two edges from the lone vertex
// cross the other plane, as projections on the line.
template <class T>
Interval<T> interval_with_division(const T (&proj)[3], const Distances<T>& s, int lone) {
  const int a = (lone + 1) % 3, b = (lone + 2) % 3;
  const T t0 = proj[lone] + (proj[a] - proj[lone]) * s.d[lone] / (s.d[lone] - s.d[a]);
  const T t1 = proj[lone] + (proj[b] - proj[lone]) * s.d[lone] / (s.d[lone] - s.d[b]);
  return t0 <= t1 ? Interval<T>{t0, t1} : Interval<T>{t1, t0};
}

// Steps 1–5 shared by the variants. Returns false when a plane test rejects.
template <class T, bool Snap>
struct Setup {
  Plane<T> plane1, plane2;
  Distances<T> of1, of2;  // T1's distances to plane 2; T2's distances to plane 1
  T proj1[3], proj2[3];   // vertices projected on the largest axis of the line direction
  int lone1, lone2;

  // Either triangle lies in the other's plane after the snap.
  bool coplanar() const { return lone1 < 0 || lone2 < 0; }
};

template <class T, bool Snap>
bool setup(const PairT<T>& pair, Setup<T, Snap>& s) {
  s.plane2 = plane_of(pair.t2);                        // step 1
  s.of1 = distances<T, Snap>(s.plane2, pair.t1);       // step 2
  if (s.of1.strictly_one_side()) return false;
  s.plane1 = plane_of(pair.t1);                        // step 3
  s.of2 = distances<T, Snap>(s.plane1, pair.t2);       // step 4
  if (s.of2.strictly_one_side()) return false;
  const Vec3<T> direction = s.plane1.normal.cross(s.plane2.normal);  // step 5
  const int axis = largest_axis(direction);
  for (int i = 0; i < 3; ++i) {
    s.proj1[i] = pair.t1[i][axis];
    s.proj2[i] = pair.t2[i][axis];
  }
  s.lone1 = lone_vertex(s.of1);
  s.lone2 = lone_vertex(s.of2);
  return true;
}

template <class T, bool Snap>
bool overlap(const PairT<T>& pair) {
  Setup<T, Snap> s;
  if (!setup(pair, s)) return false;
  if (s.coplanar()) return coplanar_overlap(s.plane1.normal, pair.t1, pair.t2);
  const Interval<T> i1 = interval_with_division(s.proj1, s.of1, s.lone1);  // step 6
  const Interval<T> i2 = interval_with_division(s.proj2, s.of2, s.lone2);
  return !(i1.hi < i2.lo || i2.hi < i1.lo);  // step 7
}

// ---- the division-free variant ----

// Each interval endpoint is proj[lone] + B / X; keep A = proj[lone], B and C (numerators) and
// X0, X1 (denominators), and compare both intervals after multiplying by X0 X1 Y0 Y1.
template <class T>
struct Fraction {
  T a, b, c, x0, x1;
};

template <class T>
Fraction<T> interval_fraction(const T (&proj)[3], const Distances<T>& s, int lone) {
  const int a = (lone + 1) % 3, b = (lone + 2) % 3;
  return {proj[lone], (proj[a] - proj[lone]) * s.d[lone], (proj[b] - proj[lone]) * s.d[lone],
          s.d[lone] - s.d[a], s.d[lone] - s.d[b]};
}

template <class T, bool Snap>
bool overlap_division_free(const PairT<T>& pair) {
  Setup<T, Snap> s;
  if (!setup(pair, s)) return false;
  if (s.coplanar()) return coplanar_overlap(s.plane1.normal, pair.t1, pair.t2);
  const Fraction<T> f = interval_fraction(s.proj1, s.of1, s.lone1);
  const Fraction<T> g = interval_fraction(s.proj2, s.of2, s.lone2);
  const T xx = f.x0 * f.x1, yy = g.x0 * g.x1, xxyy = xx * yy;
  T i1a = f.a * xxyy + f.b * f.x1 * yy, i1b = f.a * xxyy + f.c * f.x0 * yy;
  T i2a = g.a * xxyy + g.b * xx * g.x1, i2b = g.a * xxyy + g.c * xx * g.x0;
  if (i1a > i1b) std::swap(i1a, i1b);
  if (i2a > i2b) std::swap(i2a, i2b);
  return !(i1b < i2a || i2b < i1a);
}

// ---- the variant that returns the segment ----

template <class T>
struct Endpoint {
  T t;          // position on the projected line
  Vec3<T> at;   // the point in space
};

template <class T>
std::pair<Endpoint<T>, Endpoint<T>> interval_points(const TriangleT<T>& tri, const T (&proj)[3],
                                                    const Distances<T>& s, int lone) {
  const int a = (lone + 1) % 3, b = (lone + 2) % 3;
  const T ta = s.d[lone] / (s.d[lone] - s.d[a]);
  const T tb = s.d[lone] / (s.d[lone] - s.d[b]);
  Endpoint<T> ea{proj[lone] + (proj[a] - proj[lone]) * ta, tri[lone] + (tri[a] - tri[lone]) * ta};
  Endpoint<T> eb{proj[lone] + (proj[b] - proj[lone]) * tb, tri[lone] + (tri[b] - tri[lone]) * tb};
  if (eb.t < ea.t) std::swap(ea, eb);
  return {ea, eb};
}

template <class T, bool Snap>
SegmentAnswer segment(const PairT<T>& pair) {
  SegmentAnswer out;
  out.kind = SegmentKind::empty;
  Setup<T, Snap> s;
  if (!setup(pair, s)) return out;
  if (s.coplanar()) {
    // Coplanar: the published function reports the flag and the boolean, never a segment. (For
    // the second triangle it ignores the coplanar result of its interval computation and goes on
    // with values it never set; this port takes the coplanar branch there too.)
    out.kind = coplanar_overlap(s.plane1.normal, pair.t1, pair.t2) ? SegmentKind::coplanar
                                                                    : SegmentKind::empty;
    return out;
  }
  const auto [a_lo, a_hi] = interval_points(pair.t1, s.proj1, s.of1, s.lone1);
  const auto [b_lo, b_hi] = interval_points(pair.t2, s.proj2, s.of2, s.lone2);
  if (a_hi.t < b_lo.t || b_hi.t < a_lo.t) return out;
  // The overlap of the intervals, each end taken from the triangle that bounds it; ties go the
  // way the published code sends them.
  const bool starts_in_t1 = b_lo.t < a_lo.t;
  const Vec3<T>& from = starts_in_t1 ? a_lo.at : b_lo.at;
  const Vec3<T>& to = starts_in_t1 ? (b_hi.t < a_hi.t ? b_hi.at : a_hi.at)
                                   : (b_hi.t > a_hi.t ? a_hi.at : b_hi.at);
  out.p = from.template cast<double>();
  out.q = to.template cast<double>();
  out.kind = out.p == out.q ? SegmentKind::point : SegmentKind::segment;
  return out;
}

// The segment variant's own boolean: it reports an intersection iff it found one.
template <class T, bool Snap>
bool overlap_with_segment(const PairT<T>& pair) {
  return segment<T, Snap>(pair).kind != SegmentKind::empty;
}

}  // namespace tritri::moller97
