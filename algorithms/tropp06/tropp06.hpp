// Tropp, Tal & Shimshoni 2006, "A fast triangle to triangle intersection test for collision
// detection", Computer Animation and Virtual Worlds 17(5):527–535. doi:10.1002/cav.115
//
// A port of the authors' published routine tr_tri_intersect3D. Triangle A = (C1; P1, P2) and
// B = (D1; Q1, Q2), each a vertex and its two edge vectors; every linear system is solved by
// Cramer's rule with its minors shared, and nothing is divided. Steps:
//   1. r = D1 − C1; the minors of [P1 P2] (= N_A = P1×P2); dq1 = N_A·Q1, dq2 = N_A·Q2,
//      dr = N_A·(C1 − D1). Where B's edge Qi meets plane A is βi = dr/dqi, kept unnormalised:
//      βi·dqi² = dr·dqi, legal iff dqi ≠ 0 and 0 ≤ dr·dqi ≤ dqi².
//   2. dq1 = dq2 = 0: parallel planes; dr ≠ 0 → disjoint, else coplanar → Möller's coplanar
//      test (the published code calls Möller's coplanar_tri_tri: so does this port).
//   3. Neither Q1 nor Q2 legal → reject (a plane crossing B crosses two of its edges).
//   4. The two crossed edges (Q1,Q2), (Q1,Q3) or (Q2,Q3), Q3 = Q2 − Q1 from D1 + Q1, give the
//      cut segment of B in plane A as a start point and a direction, both scaled by
//      SF = dqi·dqj.
//   5. 2-D segment-vs-triangle in plane A, in A's frame (C1 at the origin, A's edges SF·P1 and
//      SF·P2): for each edge of A the 2-D cross product with the direction (det), the parameter
//      where the segment's line crosses that edge (alpha, legal in [0, det²]) and where along
//      the segment (gamma, inside in [−det², 0]). The line crosses two of A's edges; the
//      segment meets A iff one crossing lies on it or they lie on either side of its start.
//   Returns 0, or which pair of A's edges the line crosses: 12, 13, 23 (edge 1 along P1, edge 2
//   along P2, edge 3 from C1+P1 to C1+P2); the coplanar branch returns Möller's 0/1.
//
// Choices, and what the published code does:
// - Set-up inside the call: the published routine takes P1, P2, Q1, Q2 from the caller; here
//   they are computed from the vertices inside the call, so they are timed.
// - Which triangle is cut: B (= T2) by A's plane (T1). T1 is never tested against T2's plane.
// - The 2-D step uses the x and y components of A's edges, of the start point and of the
//   direction, whatever A's orientation: published. It is only valid when the projection of
//   plane A on the xy-plane is one-to-one. When N_A has a zero z component (A contains the z
//   direction) every 2-D cross product is 0, no edge is legal, and every pair that reaches
//   step 5 is reported disjoint. `Projection::dominant` (variant tropp06-fixed) uses the two
//   components that drop N_A's largest one instead.
// - When B touches plane A in a single vertex the cut segment has length 0: its direction is
//   the zero vector, every det is 0, and the published code reports disjoint even when that
//   vertex lies on A. The fixed variant tests that point against A (code kVertex). The same
//   blind spot hits D1 on plane A with B straddling it: edges Q1 and Q2 both cross at D1
//   (β = 0), the published code takes those two and never edge Q3, and the cut collapses to
//   D1 (builtin case cross-vertex-on-face). The fixed variant then cuts along Q1 and Q3.
// - The fixed variant (tropp06-fixed) corrects all three defects; the template flags are
//   Projection (the 2-D plane) and PointCase (the point contact and the line through C1).
// - When the cut line passes through A's vertex C1, edges 1 and 2 are both legal (both cross at
//   C1) and the published code compares the segment with that one point, never with edge 3:
//   a segment that enters A at C1 and runs into A without containing C1 is reported disjoint.
//   The fixed variant uses edges 1 and 3 when both crossings are at C1 and edge 3 is legal.
// - No tolerance: every comparison is against zero. Boundary: closed (≤, ≥ everywhere).
// - Degenerate (zero-area) triangles: not handled.
#pragma once

#include "algorithms/moller97/moller97.hpp"  // Möller's coplanar test, as the authors' code uses it

#include "tritri/answers.hpp"

#include <cmath>

namespace tritri::tropp06 {

// The published return values, plus kVertex for the fixed variant's point contact.
inline constexpr int kDisjoint = 0;
inline constexpr int kCoplanar = 1;  // Möller's coplanar test said yes
inline constexpr int kVertex = 2;    // fixed variant only: B touches A's plane in a point on A
inline constexpr int kEdges12 = 12;
inline constexpr int kEdges13 = 13;
inline constexpr int kEdges23 = 23;

enum class Projection { xy, dominant };

template <class T>
struct Vec2 {
  T x, y;
};

template <class T>
T cross(const Vec2<T>& a, const Vec2<T>& b) {
  return a.x * b.y - a.y * b.x;
}

// The two coordinates step 5 works in.
template <class T, Projection Proj>
void axes(const Vec3<T>& n, int& i0, int& i1) {
  if constexpr (Proj == Projection::xy) {
    i0 = 0, i1 = 1;
  } else {
    using std::abs;
    const T a0 = abs(n[0]), a1 = abs(n[1]), a2 = abs(n[2]);
    if (a0 > a1 && a0 > a2) i0 = 1, i1 = 2;
    else if (a1 > a2) i0 = 0, i1 = 2;
    else i0 = 0, i1 = 1;
  }
}

// Steps 1–4: the cut segment of B in plane A, relative to C1 and scaled by SF.
template <class T>
struct CutSegment {
  enum class Kind { rejected, parallel, coplanar, segment } kind = Kind::segment;
  T sf = T(0);
  Vec3<T> start = Vec3<T>::Zero();      // SF · (first endpoint − C1)
  Vec3<T> direction = Vec3<T>::Zero();  // SF · (second endpoint − first endpoint)
};

template <class T>
bool legal(const T& beta_scaled, const T& dq) {  // β·dq² in [0, dq²], dq ≠ 0
  return dq != T(0) && beta_scaled >= T(0) && beta_scaled <= dq * dq;
}

// Fixed: when D1 is on plane A (dr = 0), Q1 and Q2 both "cross" at D1; take Q1 and Q3 instead
// when Q3 crosses too, so the cut is D1 → Q3's crossing rather than the point D1.
template <class T, bool Fixed = false>
CutSegment<T> cut_segment(const Vec3<T>& c1, const Vec3<T>& p1, const Vec3<T>& p2, const Vec3<T>& d1,
                          const Vec3<T>& q1, const Vec3<T>& q2) {
  using Kind = typename CutSegment<T>::Kind;
  CutSegment<T> out;
  const Vec3<T> r = d1 - c1;  // step 1
  const Vec3<T> n = p1.cross(p2);
  const T dq1 = q1.dot(n), dq2 = q2.dot(n), dr = -r.dot(n);
  const T b1 = dr * dq1;  // β1·dq1²
  const T b2 = dr * dq2;  // β2·dq2²
  bool legal1 = legal(b1, dq1), legal2 = legal(b2, dq2);
  if (dq1 == T(0) && dq2 == T(0)) {  // step 2
    out.kind = dr != T(0) ? Kind::parallel : Kind::coplanar;
    return out;
  }
  if (!legal1 && !legal2) {  // step 3
    out.kind = Kind::rejected;
    return out;
  }
  // step 4: each β scaled by SF; β3 = (dr − dq1)/dq3 on the edge from D1+Q1 to D1+Q2
  const T dq3 = dq2 - dq1;
  if constexpr (Fixed) {
    if (legal1 && legal2 && dr == T(0) && legal((dr - dq1) * dq3, dq3)) legal2 = false;
  }
  if (legal1 && legal2) {  // edges Q1 and Q2
    out.sf = dq1 * dq2;
    const T s1 = dr * dq2, s2 = dr * dq1;  // β1·SF, β2·SF
    out.start = r * out.sf + q1 * s1;
    out.direction = q2 * s2 - q1 * s1;
  } else if (legal1) {  // edges Q1 and Q3
    out.sf = dq1 * dq3;
    const T s1 = dr * dq3, s3 = (dr - dq1) * dq1;
    out.start = r * out.sf + q1 * s1;
    out.direction = q1 * (out.sf - s3 - s1) + q2 * s3;
  } else {  // edges Q2 and Q3
    out.sf = dq2 * dq3;
    const T s2 = dr * dq3, s3 = (dr - dq1) * dq2;
    out.start = r * out.sf + q2 * s2;
    out.direction = q1 * (out.sf - s3) + q2 * (s3 - s2);
  }
  return out;
}

// gamma in [−det², 0]: the edge crossing lies on the segment.
template <class T>
bool on_segment(const T& gamma, const T& det) {
  return gamma <= T(0) && gamma >= -(det * det);
}

// Step 5 in A's frame: p1, p2 = SF·(A's edges); s = start; q = direction. ThroughC1Fix: the
// fixed variant's handling of a line through C1.
template <class T, bool ThroughC1Fix = false>
int segment_vs_triangle_2d(const Vec2<T>& p1, const Vec2<T>& p2, const Vec2<T>& s, const Vec2<T>& q) {
  const T det1 = cross(p1, q);
  const T alpha1 = cross(s, q) * det1;
  const T gamma1 = cross(p1, s) * det1;
  const bool legal1 = det1 != T(0) && alpha1 >= T(0) && alpha1 <= det1 * det1;
  const T det2 = cross(p2, q);
  const T alpha2 = cross(s, q) * det2;
  const T gamma2 = cross(p2, s) * det2;
  const bool legal2 = det2 != T(0) && alpha2 >= T(0) && alpha2 <= det2 * det2;
  const T det3 = det2 - det1;
  const Vec2<T> e3{p2.x - p1.x, p2.y - p1.y}, s3{s.x - p1.x, s.y - p1.y};
  const T gamma3 = cross(e3, s3) * det3;
  if constexpr (ThroughC1Fix) {
    const T alpha3 = cross(s3, q) * det3;
    const bool legal3 = det3 != T(0) && alpha3 >= T(0) && alpha3 <= det3 * det3;
    if (legal1 && legal2 && alpha1 == T(0) && alpha2 == T(0) && legal3) {  // the line enters at C1
      if (on_segment(gamma1, det1) || on_segment(gamma3, det3) || gamma1 * gamma3 < T(0)) return kEdges13;
      return kDisjoint;
    }
  }
  if (legal1) {
    if (legal2) {
      if (on_segment(gamma1, det1) || on_segment(gamma2, det2) || gamma1 * gamma2 < T(0)) return kEdges12;
    } else {
      if (on_segment(gamma1, det1) || on_segment(gamma3, det3) || gamma1 * gamma3 < T(0)) return kEdges13;
    }
  } else if (legal2) {
    if (on_segment(gamma2, det2) || on_segment(gamma3, det3) || gamma2 * gamma3 < T(0)) return kEdges23;
  }
  return kDisjoint;
}

// The fixed variant's point case: is s (relative to C1) in the closed triangle (0, p1, p2)?
template <class T>
bool point_in_frame(const Vec2<T>& p1, const Vec2<T>& p2, const Vec2<T>& s) {
  const T o = cross(p1, p2);
  const Vec2<T> e3{p2.x - p1.x, p2.y - p1.y}, s3{s.x - p1.x, s.y - p1.y};
  const T a = cross(p1, s), b = cross(s, p2), c = cross(e3, s3);
  if (o > T(0)) return a >= T(0) && b >= T(0) && c >= T(0);
  return a <= T(0) && b <= T(0) && c <= T(0);
}

// The published routine on the two triangles' vertices; returns 0, 1 (coplanar), 12, 13, 23.
template <class T, Projection Proj = Projection::xy, bool PointCase = false>
int intersect(const PairT<T>& pair) {
  const Vec3<T>& c1 = pair.t1[0];
  const Vec3<T>& d1 = pair.t2[0];
  const Vec3<T> p1 = pair.t1[1] - c1, p2 = pair.t1[2] - c1;  // set-up, timed
  const Vec3<T> q1 = pair.t2[1] - d1, q2 = pair.t2[2] - d1;
  const CutSegment<T> cs = cut_segment<T, PointCase>(c1, p1, p2, d1, q1, q2);
  using Kind = typename CutSegment<T>::Kind;
  switch (cs.kind) {
    case Kind::rejected:
    case Kind::parallel: return kDisjoint;
    case Kind::coplanar:
      return moller97::coplanar_overlap(Vec3<T>(p1.cross(p2)), pair.t1, pair.t2) ? kCoplanar : kDisjoint;
    case Kind::segment: break;
  }
  int i0, i1;
  axes<T, Proj>(p1.cross(p2), i0, i1);
  const Vec2<T> a{cs.sf * p1[i0], cs.sf * p1[i1]}, b{cs.sf * p2[i0], cs.sf * p2[i1]};
  const Vec2<T> s{cs.start[i0], cs.start[i1]}, q{cs.direction[i0], cs.direction[i1]};
  if constexpr (PointCase) {
    if (q.x == T(0) && q.y == T(0)) return point_in_frame(a, b, s) ? kVertex : kDisjoint;
  }
  return segment_vs_triangle_2d<T, PointCase>(a, b, s, q);
}

template <class T, Projection Proj = Projection::xy, bool PointCase = false>
bool overlap(const PairT<T>& pair) {
  return intersect<T, Proj, PointCase>(pair) != kDisjoint;
}

}  // namespace tritri::tropp06
