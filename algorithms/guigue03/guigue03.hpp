// Guigue & Devillers 2003, "Fast and Robust Triangle-Triangle Overlap Test Using Orientation
// Predicates", journal of graphics tools 8(1):25–32. doi:10.1080/10867651.2003.10487580
//
// Every decision is the sign of an orientation determinant
//   [a,b,c,d] = (d − a)·((b − a)×(c − a))   (positive: d on the side (b−a)×(c−a) points to)
// and, in the coplanar branch, of its 2-D counterpart (b − a)×(c − a). No point is constructed
// by the overlap test; the segment variant constructs the two endpoints only after the signs
// have decided. Step numbers are the paper's:
//   1. signs of T1's vertices against plane(T2); all non-zero and equal: reject
//   2. the same for T2 against plane(T1)
//   3. all zero: coplanar, 2-D test in the projection that drops N1's largest component
//   4. rotate each triangle so that its lone vertex comes first and lies on the positive side of
//      the other plane (swapping the other triangle's last two vertices when it is negative)
//   5. the intervals on L = π1 ∩ π2 overlap iff [p1,q1,p2,q2] ≤ 0 and [p1,r1,r2,p2] ≤ 0
//
// Choices the paper leaves open, and what this port does:
// - The signs come from a predicates type (`Predicates`): `FloatPredicates<T>` evaluates the
//   determinants in T and takes the sign, as the published code does. An exact or filtered
//   predicates type can be dropped in without touching the algorithm.
// - Zero signs (a vertex on the other plane): the lone-vertex table below picks, for every sign
//   pattern, a first vertex whose two edges reach the other plane, so that the segment
//   variant never divides by zero. Touching counts: the triangles are closed.
// - Coplanar branch: locate p1 in the seven regions cut by T2's edge lines (2-D orientations);
//   inside → overlap; beyond one edge → T1 meets that edge; beyond two edges (a vertex region)
//   → T1 meets one of the two edges at that vertex. The region analysis is the paper's; the
//   closing "does T1 meet segment e" sub-test is written here in orientation signs (endpoint in
//   T1, or e crossing an edge of T1), not as the published sequence of orientation calls.
// - Both tests of step 1 and 2 are done before the coplanar test, as published.
// - Tolerance: none. Degenerate (zero-area) triangles: not handled; the harness does not pass
//   them.
#pragma once

#include "tritri/answers.hpp"

#include <cmath>
#include <utility>

namespace tritri::guigue03 {

template <class T>
struct Point2 {
  T x, y;
};

template <class T>
int sign_of(const T& v) {
  return v > T(0) ? 1 : (v < T(0) ? -1 : 0);
}

// The orientation predicates, evaluated in the scalar type and reduced to a sign.
template <class T>
struct FloatPredicates {
  static int orient3d(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Vec3<T>& d) {
    return sign_of<T>((d - a).dot((b - a).cross(c - a)));
  }
  static int orient2d(const Point2<T>& a, const Point2<T>& b, const Point2<T>& c) {
    return sign_of<T>((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
};

inline bool one_sided(const int (&s)[3]) {
  return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
}
inline bool all_zero(const int (&s)[3]) { return s[0] == 0 && s[1] == 0 && s[2] == 0; }

// Step 4 for one triangle: which vertex comes first, and whether the other triangle must be
// flipped (its last two vertices swapped) so that the first vertex is on the non-negative side.
// The first vertex either has a non-zero sign, or is on the plane with both others strictly on
// one side: its two edges always reach the plane at a well-defined point.
struct Lone {
  int index = -1;  // -1: all three signs are zero (coplanar)
  bool flip = false;
};

inline Lone lone_vertex(const int (&s)[3]) {
  const int a = s[0], b = s[1], c = s[2];
  if (a > 0) {
    if (b > 0) return {2, true};   // p, q above: r alone below or on the plane
    if (c > 0) return {1, true};   // p, r above: q alone
    return {0, false};             // p alone above
  }
  if (a < 0) {
    if (b < 0) return {2, false};  // p, q below: r alone above or on the plane
    if (c < 0) return {1, false};  // p, r below: q alone
    return {0, true};              // p alone below
  }
  // p on the plane
  if (b < 0) {
    if (c > 0) return {2, false};  // r alone above
    if (c == 0) return {1, true};  // q alone below, p and r on the plane
    return {0, false};             // p on the plane, q and r below
  }
  if (b > 0) {
    if (c < 0) return {2, true};   // r alone below
    if (c == 0) return {1, false}; // q alone above
    return {0, true};              // p on the plane, q and r above
  }
  if (c > 0) return {2, false};    // p, q on the plane, r above
  if (c < 0) return {2, true};     // p, q on the plane, r below
  return {};
}

template <class T>
TriangleT<T> rotated(const TriangleT<T>& t, int first) {
  return {{t[first], t[(first + 1) % 3], t[(first + 2) % 3]}};
}

// Steps 1–4: the two triangles in canonical order, or the reason there is none.
template <class T>
struct Canonical {
  enum class Outcome { rejected, coplanar, general } outcome = Outcome::general;
  TriangleT<T> t1, t2;  // general: p1 alone on the positive side of π2, p2 of π1
};

// Step 4 given the signs: rotate T1 by its lone vertex (flipping T2 if that vertex is below
// π2), then T2 by its own (flipping T1's last two vertices if below π1).
template <class T>
Canonical<T> canonical_from_signs(const PairT<T>& pair, const int (&s1)[3], const int (&s2)[3]) {
  Canonical<T> c;
  const Lone l1 = lone_vertex(s1);
  c.t1 = rotated(pair.t1, l1.index);
  TriangleT<T> t2 = pair.t2;
  int signs2[3] = {s2[0], s2[1], s2[2]};
  if (l1.flip) {
    std::swap(t2[1], t2[2]);
    std::swap(signs2[1], signs2[2]);
  }
  const Lone l2 = lone_vertex(signs2);
  c.t2 = rotated(t2, l2.index);
  if (l2.flip) std::swap(c.t1[1], c.t1[2]);
  return c;
}

template <class T, class Predicates = FloatPredicates<T>>
Canonical<T> canonical(const PairT<T>& pair, int (&s1)[3], int (&s2)[3]) {
  using Out = typename Canonical<T>::Outcome;
  const auto& t1 = pair.t1;
  const auto& t2 = pair.t2;
  Canonical<T> c;
  for (int i = 0; i < 3; ++i) s1[i] = Predicates::orient3d(t2[0], t2[1], t2[2], t1[i]);  // step 1
  if (one_sided(s1)) return c.outcome = Out::rejected, c;
  for (int i = 0; i < 3; ++i) s2[i] = Predicates::orient3d(t1[0], t1[1], t1[2], t2[i]);  // step 2
  if (one_sided(s2)) return c.outcome = Out::rejected, c;
  if (all_zero(s1) || all_zero(s2)) return c.outcome = Out::coplanar, c;  // step 3
  return canonical_from_signs<T>(pair, s1, s2);
}

// ---- the coplanar branch (step 3) ----

template <class T>
void projection_axes(const Vec3<T>& n, int& i0, int& i1) {
  using std::abs;
  const T a0 = abs(n[0]), a1 = abs(n[1]), a2 = abs(n[2]);
  if (a0 > a1 && a0 > a2) i0 = 1, i1 = 2;  // x dominant
  else if (a1 > a2) i0 = 0, i1 = 2;         // y dominant
  else i0 = 0, i1 = 1;                      // z dominant (or tied with it)
}

template <class T, class Predicates>
bool point_in_ccw(const Point2<T>& p, const Point2<T>& a, const Point2<T>& b, const Point2<T>& c) {
  return Predicates::orient2d(a, b, p) >= 0 && Predicates::orient2d(b, c, p) >= 0 &&
         Predicates::orient2d(c, a, p) >= 0;
}

// Do closed segments [u,v] and [a,b] meet? Collinear pairs answer no: in the one place this is
// used, a collinear overlap always shows up as an endpoint inside the triangle or as a crossing
// of the neighbouring edge at a shared vertex.
template <class T, class Predicates>
bool segments_cross(const Point2<T>& u, const Point2<T>& v, const Point2<T>& a, const Point2<T>& b) {
  const int o1 = Predicates::orient2d(u, v, a), o2 = Predicates::orient2d(u, v, b);
  if (o1 == 0 && o2 == 0) return false;
  if (o1 * o2 > 0) return false;
  const int o3 = Predicates::orient2d(a, b, u), o4 = Predicates::orient2d(a, b, v);
  return o3 * o4 <= 0;
}

// Does the ccw triangle (p,q,r) meet the closed segment [a,b]?
template <class T, class Predicates>
bool triangle_meets_segment(const Point2<T>& p, const Point2<T>& q, const Point2<T>& r,
                            const Point2<T>& a, const Point2<T>& b) {
  if (point_in_ccw<T, Predicates>(a, p, q, r) || point_in_ccw<T, Predicates>(b, p, q, r)) return true;
  return segments_cross<T, Predicates>(p, q, a, b) || segments_cross<T, Predicates>(q, r, a, b) ||
         segments_cross<T, Predicates>(r, p, a, b);
}

// Both triangles counter-clockwise. Locate p1 against T2's edge lines, then finish with an
// edge or a vertex sub-test.
template <class T, class Predicates = FloatPredicates<T>>
bool ccw_overlap_2d(const Point2<T>& p1, const Point2<T>& q1, const Point2<T>& r1,
                    const Point2<T>& p2, const Point2<T>& q2, const Point2<T>& r2) {
  const Point2<T> v[3] = {p2, q2, r2};
  bool outside[3];  // outside[k]: p1 strictly beyond the edge v[k] → v[k+1]
  int count = 0;
  for (int k = 0; k < 3; ++k) {
    outside[k] = Predicates::orient2d(v[k], v[(k + 1) % 3], p1) < 0;
    count += outside[k] ? 1 : 0;
  }
  if (count == 0) return true;  // p1 inside T2
  if (count == 1) {             // edge region: T1 can only reach T2 through that edge
    for (int k = 0; k < 3; ++k)
      if (outside[k]) return triangle_meets_segment<T, Predicates>(p1, q1, r1, v[k], v[(k + 1) % 3]);
  }
  // vertex region: beyond the two edges that meet at vertex w; T1 enters T2 through one of them
  for (int k = 0; k < 3; ++k) {
    const int before = (k + 2) % 3;
    if (outside[k] && outside[before]) {
      const Point2<T>& w = v[k];
      return triangle_meets_segment<T, Predicates>(p1, q1, r1, v[before], w) ||
             triangle_meets_segment<T, Predicates>(p1, q1, r1, w, v[(k + 1) % 3]);
    }
  }
  return false;  // unreachable for a proper triangle: p1 cannot be beyond all three edges
}

template <class T, class Predicates = FloatPredicates<T>>
bool coplanar_overlap(const TriangleT<T>& t1, const TriangleT<T>& t2) {
  const Vec3<T> n1 = (t1[1] - t1[0]).cross(t1[2] - t1[0]);
  int i0, i1;
  projection_axes(n1, i0, i1);
  auto project = [&](const Vec3<T>& p) { return Point2<T>{p[i0], p[i1]}; };
  Point2<T> a[3] = {project(t1[0]), project(t1[1]), project(t1[2])};
  Point2<T> b[3] = {project(t2[0]), project(t2[1]), project(t2[2])};
  // make both counter-clockwise
  if (Predicates::orient2d(a[0], a[1], a[2]) < 0) std::swap(a[1], a[2]);
  if (Predicates::orient2d(b[0], b[1], b[2]) < 0) std::swap(b[1], b[2]);
  return ccw_overlap_2d<T, Predicates>(a[0], a[1], a[2], b[0], b[1], b[2]);
}

// ---- the overlap test ----

// Step 5 on the canonical triangles.
template <class T, class Predicates = FloatPredicates<T>>
bool intervals_overlap(const Canonical<T>& c) {
  const auto& [p1, q1, r1] = c.t1.v;
  const auto& [p2, q2, r2] = c.t2.v;
  return Predicates::orient3d(p1, q1, p2, q2) <= 0 && Predicates::orient3d(p1, r1, r2, p2) <= 0;
}

template <class T, class Predicates = FloatPredicates<T>>
bool overlap(const PairT<T>& pair) {
  int s1[3], s2[3];
  const Canonical<T> c = canonical<T, Predicates>(pair, s1, s2);
  switch (c.outcome) {
    case Canonical<T>::Outcome::rejected: return false;
    case Canonical<T>::Outcome::coplanar: return coplanar_overlap<T, Predicates>(pair.t1, pair.t2);
    case Canonical<T>::Outcome::general: break;
  }
  return intervals_overlap<T, Predicates>(c);
}

// ---- the segment-returning variant ----

// Where the edge a→b meets the plane through `on` with normal n (a is on one side or on it, b
// strictly on the other or on it, not both on it: guaranteed by the lone-vertex table).
template <class T>
Vec3<T> cut(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& n, const Vec3<T>& on) {
  const T da = n.dot(a - on), db = n.dot(b - on);
  return a + (b - a) * (da / (da - db));
}

// On L the canonical intervals are [j, i] for T1 (i on p1q1, j on p1r1) and [k, l] for T2 (k on
// p2q2, l on p2r2), both in the same direction; the overlap is [max(j,k), min(i,l)], and each
// comparison is one more orientation sign of the two lines involved.
template <class T, class Predicates = FloatPredicates<T>>
SegmentAnswer segment(const PairT<T>& pair) {
  SegmentAnswer out;
  out.kind = SegmentKind::empty;
  int s1[3], s2[3];
  const Canonical<T> c = canonical<T, Predicates>(pair, s1, s2);
  if (c.outcome == Canonical<T>::Outcome::rejected) return out;
  if (c.outcome == Canonical<T>::Outcome::coplanar) {
    // as published: the coplanar flag and the boolean, no intersection constructed
    if (coplanar_overlap<T, Predicates>(pair.t1, pair.t2)) out.kind = SegmentKind::coplanar;
    return out;
  }
  if (!intervals_overlap<T, Predicates>(c)) return out;
  const auto& [p1, q1, r1] = c.t1.v;
  const auto& [p2, q2, r2] = c.t2.v;
  const Vec3<T> n1 = (q1 - p1).cross(r1 - p1);
  const Vec3<T> n2 = (q2 - p2).cross(r2 - p2);
  const Vec3<T> from = Predicates::orient3d(p1, r1, q2, p2) <= 0 ? cut(p2, q2, n1, p1)   // k
                                                                 : cut(p1, r1, n2, p2);  // j
  const Vec3<T> to = Predicates::orient3d(p1, q1, p2, r2) <= 0 ? cut(p2, r2, n1, p1)     // l
                                                               : cut(p1, q1, n2, p2);    // i
  out.p = from.template cast<double>();
  out.q = to.template cast<double>();
  out.kind = out.p == out.q ? SegmentKind::point : SegmentKind::segment;
  return out;
}

template <class T, class Predicates = FloatPredicates<T>>
bool overlap_with_segment(const PairT<T>& pair) {
  return segment<T, Predicates>(pair).kind != SegmentKind::empty;
}

}  // namespace tritri::guigue03
