// Held 1997, ERIT's triangle–triangle test, RECONSTRUCTED.
//   Martin Held. ERIT — A Collection of Efficient and Reliable Intersection Tests. journal of
//   graphics tools 2(4):25–44, 1997.
// ERIT's source was only "available from the author"; no public copy exists. This port follows
// the descriptions of the test by Möller (1997) and Tropp et al. (2006): segment-in-plane.
// Steps:
//   1. the plane of T1, with its normal normalised (ERIT's distances are lengths)
//   2. classify T2's vertices against it with the tolerance: all strictly on one side → reject;
//      all within the tolerance → coplanar: 2-D triangle–triangle test
//   3. cut T2 by the plane: the segment s, endpoints interpolated on the straddling edges, a
//      vertex within the tolerance taken as it is
//   4. project s and T1 on the coordinate plane that drops T1's dominant normal component; 2-D
//      segment-vs-triangle test (an endpoint inside, or s crossing an edge), tolerance-based
//
// Choices, all reconstructed (none is documented in a public source):
// - Which triangle is cut: T2, by T1's plane. The test is asymmetric; T1's plane is the only
//   plane computed, and T1 is never tested against T2's plane.
// - Tolerance: kZero = 1e-10, absolute, a LENGTH in the input's units. In 3-D it is compared
//   with the Euclidean distance of T2's vertices to T1's plane; in 2-D with the distance of a
//   point to an edge's line in the projection (projected lengths, shortened by at most √3 by
//   the projection). It does not scale with the input: for coordinates around 1e6 it is below
//   the rounding error of the distances themselves.
// - Boundary: closed with slack. Anything within kZero of touching counts as touching.
// - Collinear segment and edge (both endpoints of s within kZero of an edge's line): that edge
//   is skipped; an overlap then shows as an endpoint inside T1 or as a crossing of the
//   neighbouring edge at the shared vertex.
// - Coplanar (every vertex of T2 within kZero of T1's plane): each edge of T2 against T1 with
//   the same segment-vs-triangle test, then one vertex of T1 inside T2.
// - The segment level returns s ∩ T1: s clipped against T1's three edge half-planes (with the
//   same slack), mapped back to 3-D along s. In the coplanar case: the coplanar flag only.
// - Degenerate (zero-area) triangles: not handled (the unit normal divides by zero).
#pragma once

#include "tritri/answers.hpp"

#include <cmath>

namespace tritri::held97 {

inline constexpr double kZero = 1e-10;  // reconstructed; a length

template <class T, bool Tolerant>
T tolerance() {
  return Tolerant ? T(kZero) : T(0);
}

template <class T>
int classify(const T& d, const T& eps) {
  return d > eps ? 1 : (d < -eps ? -1 : 0);
}

// Step 1: T1's plane, through T1[0], with a unit normal.
template <class T>
Vec3<T> unit_normal(const TriangleT<T>& t) {
  using std::sqrt;
  const Vec3<T> n = (t[1] - t[0]).cross(t[2] - t[0]);
  return n / sqrt(n.dot(n));
}

// Step 2: T2's signed distances to T1's plane and their classes.
template <class T>
struct Sides {
  T d[3];
  int s[3];
  bool rejected() const {
    return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
  }
  bool coplanar() const { return s[0] == 0 && s[1] == 0 && s[2] == 0; }
};

template <class T>
Sides<T> sides(const Vec3<T>& n, const Vec3<T>& on, const TriangleT<T>& t, const T& eps) {
  Sides<T> r;
  for (int i = 0; i < 3; ++i) {
    r.d[i] = n.dot(t[i] - on);
    r.s[i] = classify(r.d[i], eps);
  }
  return r;
}

// Step 3: the cut segment [a, b] (a == b when T2 touches the plane in one vertex).
template <class T>
struct Cut {
  Vec3<T> a, b;
};

template <class T>
Cut<T> cut(const TriangleT<T>& t, const Sides<T>& s) {
  Vec3<T> points[2];
  int count = 0;
  for (int i = 0; i < 3 && count < 2; ++i)
    if (s.s[i] == 0) points[count++] = t[i];  // a vertex on the plane (within the tolerance)
  for (int i = 0; i < 3 && count < 2; ++i) {
    const int j = (i + 1) % 3;
    if (s.s[i] * s.s[j] < 0)  // the edge straddles the plane
      points[count++] = t[i] + (t[j] - t[i]) * (s.d[i] / (s.d[i] - s.d[j]));
  }
  if (count == 1) points[1] = points[0];
  return {points[0], points[1]};
}

// ---- step 4: the 2-D part ----

template <class T>
struct Point2 {
  T x, y;
};

struct Axes {
  int i0, i1;
};

// Drop the axis of the largest |component| of the normal (the projection that keeps most area).
template <class T>
Axes dominant_projection(const Vec3<T>& n) {
  using std::abs;
  const T a0 = abs(n[0]), a1 = abs(n[1]), a2 = abs(n[2]);
  if (a0 > a1 && a0 > a2) return {1, 2};
  if (a1 > a2) return {0, 2};
  return {0, 1};
}

template <class T>
Point2<T> project(const Vec3<T>& p, Axes ax) {
  return {p[ax.i0], p[ax.i1]};
}

template <class T>
T cross2(const Point2<T>& a, const Point2<T>& b, const Point2<T>& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

template <class T>
T length2(const Point2<T>& a, const Point2<T>& b) {
  using std::sqrt;
  return sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
}

// Side of p against the line a→b: the distance compared with eps (0 within it). A degenerate
// line (a == b) puts every point on it.
template <class T>
int side(const Point2<T>& a, const Point2<T>& b, const Point2<T>& p, const T& eps) {
  return classify(cross2(a, b, p), eps * length2(a, b));
}

// A triangle in the projection, with its orientation so that "inside" is the left of its edges.
template <class T>
struct Triangle2 {
  Point2<T> v[3];
  int orientation;  // +1 counter-clockwise, -1 clockwise
};

template <class T>
Triangle2<T> project(const TriangleT<T>& t, Axes ax) {
  Triangle2<T> r{{project(t[0], ax), project(t[1], ax), project(t[2], ax)}, 1};
  if (cross2(r.v[0], r.v[1], r.v[2]) < T(0)) r.orientation = -1;
  return r;
}

template <class T>
bool point_in(const Point2<T>& p, const Triangle2<T>& t, const T& eps) {
  for (int k = 0; k < 3; ++k)
    if (t.orientation * side(t.v[k], t.v[(k + 1) % 3], p, eps) < 0) return false;
  return true;
}

// The 2-D segment-vs-triangle test: an endpoint inside, or the segment crossing an edge.
template <class T>
bool segment_meets(const Point2<T>& a, const Point2<T>& b, const Triangle2<T>& t, const T& eps) {
  if (point_in(a, t, eps) || point_in(b, t, eps)) return true;
  for (int k = 0; k < 3; ++k) {
    const Point2<T>& u = t.v[k];
    const Point2<T>& v = t.v[(k + 1) % 3];
    const int sa = side(u, v, a, eps), sb = side(u, v, b, eps);
    if (sa == 0 && sb == 0) continue;  // collinear with this edge: decided elsewhere
    if (sa * sb > 0) continue;
    if (side(a, b, u, eps) * side(a, b, v, eps) > 0) continue;
    return true;
  }
  return false;
}

template <class T>
bool coplanar_overlap(const Vec3<T>& n1, const TriangleT<T>& t1, const TriangleT<T>& t2, const T& eps) {
  const Axes ax = dominant_projection(n1);
  const Triangle2<T> a = project(t1, ax), b = project(t2, ax);
  for (int k = 0; k < 3; ++k)
    if (segment_meets(b.v[k], b.v[(k + 1) % 3], a, eps)) return true;
  return point_in(a.v[0], b, eps);
}

// ---- the test ----

template <class T, bool Tolerant = true>
bool overlap(const PairT<T>& pair) {
  const T eps = tolerance<T, Tolerant>();
  const Vec3<T> n1 = unit_normal(pair.t1);                      // step 1
  const Sides<T> s = sides(n1, pair.t1[0], pair.t2, eps);        // step 2
  if (s.rejected()) return false;
  if (s.coplanar()) return coplanar_overlap(n1, pair.t1, pair.t2, eps);
  const Cut<T> c = cut(pair.t2, s);                              // step 3
  const Axes ax = dominant_projection(n1);                       // step 4
  return segment_meets(project(c.a, ax), project(c.b, ax), project(pair.t1, ax), eps);
}

// The segment level: s ∩ T1, by clipping s's parameter range [0, 1] against T1's edges.
template <class T, bool Tolerant = true>
SegmentAnswer segment(const PairT<T>& pair) {
  SegmentAnswer out;
  out.kind = SegmentKind::empty;
  const T eps = tolerance<T, Tolerant>();
  const Vec3<T> n1 = unit_normal(pair.t1);
  const Sides<T> s = sides(n1, pair.t1[0], pair.t2, eps);
  if (s.rejected()) return out;
  if (s.coplanar()) {
    if (coplanar_overlap(n1, pair.t1, pair.t2, eps)) out.kind = SegmentKind::coplanar;
    return out;
  }
  const Cut<T> c = cut(pair.t2, s);
  const Axes ax = dominant_projection(n1);
  const Triangle2<T> t = project(pair.t1, ax);
  const Point2<T> a = project(c.a, ax), b = project(c.b, ax);
  T lo(0), hi(1);
  for (int k = 0; k < 3; ++k) {
    const Point2<T>& u = t.v[k];
    const Point2<T>& v = t.v[(k + 1) % 3];
    // f(λ) = fa + λ (fb − fa) ≥ −slack keeps the point on the inner side of this edge
    const T slack = eps * length2(u, v);
    const T ca = cross2(u, v, a), cb = cross2(u, v, b);
    const T fa = t.orientation > 0 ? ca : -ca, fb = t.orientation > 0 ? cb : -cb;
    const bool a_in = fa >= -slack, b_in = fb >= -slack;
    if (a_in && b_in) continue;
    if (!a_in && !b_in) return out;
    const T lambda = (-slack - fa) / (fb - fa);
    if (a_in) {
      if (lambda < hi) hi = lambda;
    } else if (lambda > lo) {
      lo = lambda;
    }
  }
  if (lo > hi) return out;
  const Vec3<T> p = c.a + (c.b - c.a) * lo, q = c.a + (c.b - c.a) * hi;
  out.p = p.template cast<double>();
  out.q = q.template cast<double>();
  out.kind = out.p == out.q ? SegmentKind::point : SegmentKind::segment;
  return out;
}

}  // namespace tritri::held97
