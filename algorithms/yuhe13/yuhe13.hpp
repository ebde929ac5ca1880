// Yu Haiyan, He Yuanjun. 空间两三角形的相交问题 (Testing the Intersection Status of Two
// Triangles). 图学学报 (Journal of Graphics) 34(4):54–62, 2013. (In Chinese.)
//
// The method, with the paper's section and algorithm numbers:
//   §4.1 step 1 / 基本算法1 (basic algorithm 1): the computational coordinate system on A:
//        origin A0, x = unit(A0A1) (n1), z = unit normal (n3), y = n3 × n1 (n2); both
//        triangles are transformed: X* = (x y z 1)·T, the 4×4 matrix with columns n1, n2, n3
//        and last row d_i = −(n_i·A0).                                   -> transform()
//   §4.1 step 2, in the frame:                                           -> intersect_in_frame()
//     §3 property 5: B's three z equal → parallel (−5), or coplanar when they are 0 (§6.3).
//     基本算法4 (z): B's three z of one strict sign → disjoint.
//     基本算法2/3: in the V (zx) view, where each edge of B meets z = 0: t = |z0|/(|z0|+|z1|),
//        or the endpoint whose z is 0; at most one crossing per edge, edge number n_i kept.
//     §6.1: three crossings mean one went through a vertex of B; drop the duplicate:
//        if (t0 == 0) {t0 = t2; n0 = n2;} else if (t1 == 0) {t1 = t2; n1 = n2;} n--.
//     基本算法4 (x): both crossings beyond the same end of A_V = [X_L, X_R] → disjoint.
//     §4.2 step 1: y interpolated on B's 3-D edge with the same t: L_B = P0P1 in the H plane.
//     §4.2 step 2 / 基本算法5 / §6.2: Q0Q1 = P0P1 ∩ A_H by Cyrus–Beck clipping, with the
//        singular cases (line through a vertex, along an edge, endpoint on the boundary, P0P1
//        a single point): empty → 0; Q0 = Q1 → 2; Q0Q1 along an edge of A_H → 3; else 1.
//   §4.1 step 3: Q0, Q1 transformed back (T⁻¹, rows n1, n2, n3, D_i = −Σ a_i d_i …).
//   Return codes (the relation vocabulary): 0 disjoint, 1 cross, 2 point contact, 3 segment
//   contact, −1 coplanar overlap, −2 coplanar disjoint, −3 coplanar point, −4 coplanar edge,
//   −5 parallel.
//
// Choices the paper leaves open, and defects found:
// - 基本算法4's x-reject is described as "both crossings to the right of X_R, or both to the left
//   of X_L" (and so in §3 property 6: max(x0,x1) ≤ X_L or min(x0,x1) ≥ X_R, equality being
//   contact), but its formulas read max(x0,x1) > X_R, min(x0,x1) < X_L, which rejects as soon
//   as ONE crossing lies beyond an end of A_V. yuhe13 implements the words (strict, so contact
//   at an end is kept); yuhe13-literal implements the formulas as printed.
// - An edge with both ends at z = 0 yields its start (t = 0): z0 is tested before z1. The
//   §6.1 rule then loses the edge B2B0 when it lies in A's plane ([B0, B2, B2] → [B2, B2]).
// - §6.3 (coplanar): "if B's edges meet A there is overlap (and vice versa)": each edge of B is
//   clipped by A and, for the "vice versa" (A inside B), each edge of A by B. A clipped edge
//   with a part of positive length not along an edge line of the other → −1; else one along
//   an edge → −4 (the paper: 4) takes priority over 3)); else a single point → −3; else −2.
//   So coplanar triangles whose edges all lie along each other's edges (identical triangles)
//   are "edge contact" (−4), not overlap: the rule's defect, kept.
// - §6.2 classifies contact only by A's boundary: a segment along B's edge inside A (B's edge
//   lying in A's plane) is reported as 1 (cross), not 3: kept as published.
// - The coplanar branch computes no intersection (§6.3 leaves the region to polygon Boolean
//   operations): the segment level answers `area` for −1 and `coplanar` for −3, −4.
// - Every comparison is exact (no tolerance): B's z must be exactly equal for "parallel", and
//   exactly 0 for "coplanar". After the transform (square roots, divisions) that holds only
//   when the frame is exact, e.g. A in an axis plane with an axis-aligned first edge.
// - Degenerate triangles must be excluded by the caller (the paper says so): not accepted.
// - Roles: A = T1 (the frame), B = T2.
#pragma once

#include "tritri/answers.hpp"

#include <algorithm>
#include <cmath>

namespace tritri::yuhe13 {

// ---- stage 1: the computational coordinate system (基本算法1) ----

template <class T>
struct Frame {
  Vec3<T> n1, n2, n3;  // x, y, z axes: the columns of T_{xyz→x*y*z*}
  T d1, d2, d3;        // its last row
};

template <class T>
struct Framed {
  Frame<T> frame;
  TriangleT<T> a, b;  // both triangles in the frame (a's z ≈ 0, a's y ≥ 0)
};

template <class T>
Frame<T> frame_of(const TriangleT<T>& a) {
  using std::sqrt;
  Frame<T> f;
  const Vec3<T> e = a[1] - a[0];
  f.n1 = e / sqrt(e.dot(e));                            // 1) P1P2's unit vector
  const Vec3<T> n = e.cross(Vec3<T>(a[2] - a[0]));
  f.n3 = n / sqrt(n.dot(n));                            // 2) the unit normal
  f.n2 = f.n3.cross(f.n1);                              // 3) n2 = n3 × n1
  f.d1 = -(f.n1[0] * a[0][0] + f.n1[1] * a[0][1] + f.n1[2] * a[0][2]);
  f.d2 = -(f.n2[0] * a[0][0] + f.n2[1] * a[0][1] + f.n2[2] * a[0][2]);
  f.d3 = -(f.n3[0] * a[0][0] + f.n3[1] * a[0][1] + f.n3[2] * a[0][2]);
  return f;
}

// (X* Y* Z* 1) = (x y z 1) · T_{xyz→x*y*z*}
template <class T>
Vec3<T> to_frame(const Frame<T>& f, const Vec3<T>& p) {
  return {p[0] * f.n1[0] + p[1] * f.n1[1] + p[2] * f.n1[2] + f.d1,
          p[0] * f.n2[0] + p[1] * f.n2[1] + p[2] * f.n2[2] + f.d2,
          p[0] * f.n3[0] + p[1] * f.n3[1] + p[2] * f.n3[2] + f.d3};
}

// (X Y Z 1) = (x* y* z* 1) · T⁻¹, with D_i = −(a_i d1 + b_i d2 + c_i d3) reconstructing A0.
template <class T>
Vec3<T> from_frame(const Frame<T>& f, const Vec3<T>& q) {
  Vec3<T> out;
  for (int i = 0; i < 3; ++i) {
    const T D = -(f.n1[i] * f.d1 + f.n2[i] * f.d2 + f.n3[i] * f.d3);
    out[i] = q[0] * f.n1[i] + q[1] * f.n2[i] + q[2] * f.n3[i] + D;
  }
  return out;
}

template <class T>
Framed<T> transform(const PairT<T>& pair) {
  Framed<T> out;
  out.frame = frame_of(pair.t1);
  for (int i = 0; i < 3; ++i) {
    out.a[i] = to_frame(out.frame, pair.t1[i]);
    out.b[i] = to_frame(out.frame, pair.t2[i]);
  }
  return out;
}

// ---- stage 2, pieces ----

template <class T>
struct Point2 {
  T x, y;
};

template <class T>
struct Triangle2 {
  Point2<T> v[3];
};

template <class T>
Triangle2<T> in_h_plane(const TriangleT<T>& t) {
  return {{{t[0][0], t[0][1]}, {t[1][0], t[1][1]}, {t[2][0], t[2][1]}}};
}

// 基本算法5: the part of P(t) = P0 + t (P1 − P0), 0 ≤ t ≤ 1, inside a closed triangle, by
// Cyrus–Beck: each edge's inward normal n_i gives n_i·(P(t) − V_i) ≥ 0, linear in t.
template <class T>
struct Clip {
  bool empty = true;
  T t_in = T(0), t_out = T(1);
  bool along_edge = false;  // the segment's line is an edge line of the triangle (§6.2 case 4)
};

template <class T>
Clip<T> clip(const Point2<T>& p0, const Point2<T>& p1, const Triangle2<T>& tri) {
  Clip<T> c;
  const T dx = p1.x - p0.x, dy = p1.y - p0.y;
  // The triangle's orientation decides which side is inward (A_H is counter-clockwise by
  // construction; B_H, clipped against in the coplanar branch, may not be).
  const T orient = (tri.v[1].x - tri.v[0].x) * (tri.v[2].y - tri.v[0].y) -
                   (tri.v[1].y - tri.v[0].y) * (tri.v[2].x - tri.v[0].x);
  const T sign = orient > T(0) ? T(1) : T(-1);
  T t_in = T(0), t_out = T(1);
  for (int i = 0; i < 3; ++i) {
    const Point2<T>& v = tri.v[i];
    const Point2<T>& w = tri.v[(i + 1) % 3];
    const T nx = -(w.y - v.y) * sign, ny = (w.x - v.x) * sign;
    const T num = nx * (p0.x - v.x) + ny * (p0.y - v.y);
    const T den = nx * dx + ny * dy;
    if (den == T(0)) {
      // parallel to this edge (or P0P1 is a single point): inside its half-plane or not at all
      if (num < T(0)) return c;
      if (num == T(0) && (dx != T(0) || dy != T(0))) c.along_edge = true;
    } else if (den > T(0)) {
      t_in = std::max(t_in, -num / den);  // entering
    } else {
      t_out = std::min(t_out, -num / den);  // leaving
    }
  }
  if (t_in > t_out) {
    c.along_edge = false;
    return c;
  }
  c.empty = false;
  c.t_in = t_in;
  c.t_out = t_out;
  return c;
}

template <class T>
Point2<T> at(const Point2<T>& p0, const Point2<T>& p1, T t) {
  return {p0.x + t * (p1.x - p0.x), p0.y + t * (p1.y - p0.y)};
}

// 基本算法2: where edge (z0 → z1) of B meets z = 0, as t on the edge; false when it does not.
template <class T>
bool crossing_parameter(T z0, T z1, T& t) {
  using std::abs;
  if (z0 == T(0)) return t = T(0), true;  // (2) the endpoint whose z is 0
  if (z1 == T(0)) return t = T(1), true;
  if ((z0 > T(0)) == (z1 > T(0))) return false;  // same sign: no crossing
  t = abs(z0) / (abs(z0) + abs(z1));               // (1)
  return true;
}


template <class T>
struct Crossings {
  T t[3];
  int edge[3];
  int count = 0;
};

// 基本算法3 and §6.1: the crossings of B's three edges with z = 0, the vertex duplicate dropped.
template <class T>
Crossings<T> crossings(const TriangleT<T>& b) {
  Crossings<T> c;
  for (int n = 0; n < 3; ++n) {
    T t;
    if (crossing_parameter(b[n][2], b[(n + 1) % 3][2], t)) {
      c.t[c.count] = t;
      c.edge[c.count] = n;
      ++c.count;
    }
  }
  if (c.count == 3) {  // §6.1 3): one crossing went through a vertex of B
    if (c.t[0] == T(0)) {
      c.t[0] = c.t[2], c.edge[0] = c.edge[2];
    } else if (c.t[1] == T(0)) {
      c.t[1] = c.t[2], c.edge[1] = c.edge[2];
    }
    c.count--;
  }
  return c;
}

// 基本算法2 (3): the crossing's x and y, interpolated on B's edge.
template <class T>
Point2<T> crossing_point(const TriangleT<T>& b, T t, int edge) {
  const Vec3<T>& p = b[edge];
  const Vec3<T>& q = b[(edge + 1) % 3];
  return {p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])};
}

// §6.3: what one clipped edge contributes to the coplanar classification.
enum class EdgeContact { none, point, along_edge, interior };

template <class T>
EdgeContact edge_contact(const Point2<T>& p0, const Point2<T>& p1, const Triangle2<T>& tri) {
  const Clip<T> c = clip(p0, p1, tri);
  if (c.empty) return EdgeContact::none;
  const Point2<T> q0 = at(p0, p1, c.t_in), q1 = at(p0, p1, c.t_out);
  if (q0.x == q1.x && q0.y == q1.y) return EdgeContact::point;
  return c.along_edge ? EdgeContact::along_edge : EdgeContact::interior;
}

template <class T>
Relation coplanar_relation(const Triangle2<T>& a, const Triangle2<T>& b) {
  bool along = false, point = false;
  for (int pass = 0; pass < 2; ++pass) {
    const Triangle2<T>& edges = pass == 0 ? b : a;  // B's edges by A, then "vice versa"
    const Triangle2<T>& by = pass == 0 ? a : b;
    for (int i = 0; i < 3; ++i) {
      switch (edge_contact(edges.v[i], edges.v[(i + 1) % 3], by)) {
        case EdgeContact::interior: return Relation::coplanar_overlap;  // 1)
        case EdgeContact::along_edge: along = true; break;
        case EdgeContact::point: point = true; break;
        case EdgeContact::none: break;
      }
    }
  }
  if (along) return Relation::coplanar_segment;  // 4), before 3)
  if (point) return Relation::coplanar_point;    // 3)
  return Relation::coplanar_disjoint;            // 2)
}

// ---- stage 2: IntTwoTriangles3D, in the frame ----

template <class T>
struct InFrame {
  Relation code = Relation::disjoint;
  Vec3<T> q0 = Vec3<T>::Zero(), q1 = Vec3<T>::Zero();  // in the frame (z = 0), codes 1–3
};

// LiteralReject: the x-reject with 基本算法4's formulas as printed (see the header comment).
template <class T, bool LiteralReject = false>
InFrame<T> intersect_in_frame(const Framed<T>& f) {
  InFrame<T> out;
  const TriangleT<T>& b = f.b;
  const T z0 = b[0][2], z1 = b[1][2], z2 = b[2][2];
  // §3 property 5: B ∥ H
  if (z0 == z1 && z1 == z2) {
    if (z0 != T(0)) return out.code = Relation::parallel, out;
    out.code = coplanar_relation(in_h_plane(f.a), in_h_plane(b));  // §6.3
    return out;
  }
  // 基本算法4, z: B_V strictly above or below the x axis (图10①)
  if ((z0 > T(0) && z1 > T(0) && z2 > T(0)) || (z0 < T(0) && z1 < T(0) && z2 < T(0))) return out;
  // 基本算法2/3, §6.1
  const Crossings<T> c = crossings(b);
  if (c.count == 0) return out;  // ③⑤⑥⑦
  const Point2<T> p0 = crossing_point(b, c.t[0], c.edge[0]);
  const Point2<T> p1 = c.count > 1 ? crossing_point(b, c.t[1], c.edge[1]) : p0;
  // 基本算法4, x: A_V = [X_L, X_R]
  const T xl = std::min({T(0), f.a[2][0], f.a[0][0]});
  const T xr = std::max({f.a[1][0], f.a[2][0], f.a[0][0]});
  const T lo = std::min(p0.x, p1.x), hi = std::max(p0.x, p1.x);
  if constexpr (LiteralReject) {
    if (hi > xr || lo < xl) return out;
  } else {
    if (lo > xr || hi < xl) return out;
  }
  // §4.2 step 2: Q0Q1 = P0P1 ∩ A_H
  const Clip<T> q = clip(p0, p1, in_h_plane(f.a));
  if (q.empty) return out;  // 0
  const Point2<T> q0 = at(p0, p1, q.t_in), q1 = at(p0, p1, q.t_out);
  out.q0 = {q0.x, q0.y, T(0)};
  out.q1 = {q1.x, q1.y, T(0)};
  if (q0.x == q1.x && q0.y == q1.y) return out.code = Relation::touch_point, out;  // 2
  if (q.along_edge) return out.code = Relation::touch_segment, out;                 // 3
  return out.code = Relation::cross, out;                                           // 1
}

// ---- the whole method ----

template <class T, bool LiteralReject = false>
RelationAnswer relation(const PairT<T>& pair) {
  return answer_with(intersect_in_frame<T, LiteralReject>(transform(pair)).code);
}

template <class T, bool LiteralReject = false>
SegmentAnswer segment(const PairT<T>& pair) {
  const Framed<T> f = transform(pair);
  const InFrame<T> r = intersect_in_frame<T, LiteralReject>(f);
  SegmentAnswer out;
  switch (r.code) {
    case Relation::cross:
    case Relation::touch_point:
    case Relation::touch_segment:
      // §4.1 step 3: back to the original coordinates
      out.p = from_frame(f.frame, r.q0).template cast<double>();
      out.q = from_frame(f.frame, r.q1).template cast<double>();
      out.kind = r.code == Relation::touch_point ? SegmentKind::point : SegmentKind::segment;
      break;
    case Relation::coplanar_overlap: out.kind = SegmentKind::area; break;
    case Relation::coplanar_point:
    case Relation::coplanar_segment: out.kind = SegmentKind::coplanar; break;
    default: out.kind = SegmentKind::empty;
  }
  return out;
}

}  // namespace tritri::yuhe13
