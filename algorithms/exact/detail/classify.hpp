// The exact classification of a pair, written once against a predicate policy (predicates.hpp).
// It reproduces the oracle's definitions (cases/oracle/oracle.hpp) from signs alone:
//
//   degenerate  a triangle whose vertices are collinear (all three 2-D orientations of its
//               vertices zero) is its hull, a point or the segment between its extreme
//               vertices; the answer is {Relation::degenerate, dimension of the meet}.
//   otherwise   s1 = signs of T1's vertices against T2's plane, s2 of T2's against T1's.
//     one-sided (all three signs equal and non-zero): disjoint, or parallel when the planes
//               are parallel (det[b2-a2, c2-a2, b1-a1] = det[b2-a2, c2-a2, c1-a1] = 0).
//     coplanar  (all of s2 zero): 2-D in the projection that drops an axis along which T1's
//               normal is non-zero; 18 edge/vertex orientations decide, by the separating-axis
//               theorem for convex polygons: an edge line with all of the other triangle's
//               vertices strictly outside -> disjoint; no edge line with them all outside or on
//               it -> area; else the contact lies on such a line: one vertex on it -> point,
//               an edge on it -> the overlap of two collinear segments, a point or a segment.
//     crossing  Guigue–Devillers' canonical order (p1 alone on the positive side of π2, or on
//               it with q1, r1 strictly below; likewise p2), the intervals I1 = [j, i] and
//               I2 = [k, l] on L = π1 ∩ π2, and G1 = [p1,q1,p2,q2] (sign of i - k),
//               G2 = [p1,r1,r2,p2] (sign of j - l): they meet iff G1 <= 0 and G2 <= 0; in a
//               point iff moreover G1 = 0, G2 = 0, or I1 or I2 is a point (p1 or p2 on the
//               other plane); else in a segment, `cross` unless a triangle has an edge on L
//               (exactly two zero signs), which puts the segment on its boundary.
// algorithms/exact/README.md proves each step.
#pragma once

#include "algorithms/exact/detail/predicates.hpp"
#include "algorithms/exact/detail/projected.hpp"
#include "tritri/answers.hpp"

#include <array>
#include <utility>

namespace tritri::exact::detail {

struct Tri {
  P v[3];
};

inline bool same_point(P a, P b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

// An axis along which a and b differ (they must differ).
inline int differing_axis(P a, P b) { return a[0] != b[0] ? 0 : (a[1] != b[1] ? 1 : 2); }

// The overlap of collinear segments [a,b] and [c,d] (a != b): none, point or segment, compared
// along an axis where a and b differ (the order of collinear points along any such axis is
// their order along the line).
inline Dimension collinear_overlap(P a, P b, P c, P d) {
  const int k = differing_axis(a, b);
  const double lo1 = std::min(a[k], b[k]), hi1 = std::max(a[k], b[k]);
  const double lo2 = std::min(c[k], d[k]), hi2 = std::max(c[k], d[k]);
  const double lo = std::max(lo1, lo2), hi = std::min(hi1, hi2);
  return lo > hi ? Dimension::none : (lo == hi ? Dimension::point : Dimension::segment);
}

// Signs of T's normal components (x, y, z) = signs of its 2-D orientations in the planes
// (y,z), (z,x), (x,y). All zero iff T is degenerate.
// One cross product and one bound per triangle (the extents of its vertices), each component
// evaluated exactly as det2_value evaluates o2.
template <class Pr>
bool normal_signs(const Tri& t, int n[3]) {
  P a = t.v[0], b = t.v[1], c = t.v[2];
  double u[3], v[3], e[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = b[k] - a[k];
    v[k] = c[k] - a[k];
    e[k] = std::max(std::max(a[k], b[k]), c[k]) - std::min(std::min(a[k], b[k]), c[k]);
  }
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double value = u[i] * v[j] - u[j] * v[i];
    n[k] = Pr::o2_with(value, det2_bound(e[i], e[j]), a, b, c, i, j);
  }
  return n[0] != 0 || n[1] != 0 || n[2] != 0;
}

// s1: T1's vertices against T2's plane, s2: T2's against T1's; one normal per plane and one
// bound for the pair (pair_bound3), each value evaluated exactly as det3_eval evaluates o3.
template <class Pr>
void plane_signs(const Tri& t1, const Tri& t2, int s1[3], int s2[3]) {
  double c[18];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) c[3 * i + k] = t1.v[i][k], c[9 + 3 * i + k] = t2.v[i][k];
  const double bnd = pair_bound3(c);
  for (int side = 0; side < 2; ++side) {
    const Tri& plane = side == 0 ? t2 : t1;
    const Tri& pts = side == 0 ? t1 : t2;
    int* s = side == 0 ? s1 : s2;
    P a = plane.v[0], b = plane.v[1], cc = plane.v[2];
    const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
    const double vx = cc[0] - a[0], vy = cc[1] - a[1], vz = cc[2] - a[2];
    const double mx = uy * vz - uz * vy, my = uz * vx - ux * vz, mz = ux * vy - uy * vx;
    for (int i = 0; i < 3; ++i) {
      P x = pts.v[i];
      const double value = ((x[0] - a[0]) * mx + (x[1] - a[1]) * my) + (x[2] - a[2]) * mz;
      s[i] = Pr::o3_with(value, bnd, a, b, cc, x);
    }
  }
}

// The projection for a non-degenerate triangle with normal signs n: drop an axis k with
// n[k] != 0 and keep (i, j) = (k+1, k+2) mod 3, in which the triangle's orientation is n[k].
struct Projection {
  int i, j, orientation;
};
inline Projection projection_for(const int n[3]) {
  const int k = n[2] != 0 ? 2 : (n[0] != 0 ? 0 : 1);
  return {(k + 1) % 3, (k + 2) % 3, n[k]};
}

template <class Pr>
bool collinear3(P a, P b, P c) {
  return Pr::o2(a, b, c, 1, 2) == 0 && Pr::o2(a, b, c, 2, 0) == 0 && Pr::o2(a, b, c, 0, 1) == 0;
}

// ---- degenerate shapes ----

struct Shape {
  int kind;  // 0 point p[0], 1 segment p[0]p[1], 2 triangle p[0]p[1]p[2]
  P p[3];
  int n[3];  // triangle: normal signs
};

inline Shape hull_of_collinear(const Tri& t) {
  Shape s{};
  if (same_point(t.v[0], t.v[1]) && same_point(t.v[1], t.v[2])) {
    s.kind = 0;
    s.p[0] = t.v[0];
    return s;
  }
  int k = 0;
  for (; k < 3; ++k)
    if (!(t.v[0][k] == t.v[1][k] && t.v[1][k] == t.v[2][k])) break;
  int lo = 0, hi = 0;
  for (int i = 1; i < 3; ++i) {
    if (t.v[i][k] < t.v[lo][k]) lo = i;
    if (t.v[i][k] > t.v[hi][k]) hi = i;
  }
  s.kind = 1;
  s.p[0] = t.v[lo];
  s.p[1] = t.v[hi];
  return s;
}

template <class Pr>
bool point_on_segment(P p, P a, P b) {
  if (!collinear3<Pr>(a, b, p)) return false;
  const int k = differing_axis(a, b);
  return std::min(a[k], b[k]) <= p[k] && p[k] <= std::max(a[k], b[k]);
}

// p in the closed triangle t (normal signs n); the plane test included.
template <class Pr>
bool point_in_triangle(P p, const Tri& t, const int n[3]) {
  if (Pr::o3(t.v[0], t.v[1], t.v[2], p) != 0) return false;
  const Projection pr = projection_for(n);
  for (int e = 0; e < 3; ++e)
    if (Pr::o2(t.v[e], t.v[(e + 1) % 3], p, pr.i, pr.j) * pr.orientation < 0) return false;
  return true;
}

template <class Pr>
Dimension segment_segment(P a, P b, P c, P d) {
  if (Pr::o3(a, b, c, d) != 0) return Dimension::none;
  // Coplanar: find a projection injective on the common plane, or they are collinear.
  int k = -1;
  for (P third : {c, d}) {
    const int o[3] = {Pr::o2(a, b, third, 1, 2), Pr::o2(a, b, third, 2, 0), Pr::o2(a, b, third, 0, 1)};
    for (int axis = 0; axis < 3 && k < 0; ++axis)
      if (o[axis] != 0) k = axis;
    if (k >= 0) break;
  }
  if (k < 0) return collinear_overlap(a, b, c, d);
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const int oc = Pr::o2(a, b, c, i, j), od = Pr::o2(a, b, d, i, j);
  const int oa = Pr::o2(c, d, a, i, j), ob = Pr::o2(c, d, b, i, j);
  return (oc * od <= 0 && oa * ob <= 0) ? Dimension::point : Dimension::none;
}

template <class Pr>
Dimension segment_triangle(P a, P b, const Tri& t, const int n[3]) {
  const int oa = Pr::o3(t.v[0], t.v[1], t.v[2], a), ob = Pr::o3(t.v[0], t.v[1], t.v[2], b);
  if (oa * ob > 0) return Dimension::none;
  if (oa == 0 && ob == 0) {
    const Projection pr = projection_for(n);
    int ea[3], eb[3], l[3];
    for (int e = 0; e < 3; ++e) {
      ea[e] = Pr::o2(t.v[e], t.v[(e + 1) % 3], a, pr.i, pr.j) * pr.orientation;
      eb[e] = Pr::o2(t.v[e], t.v[(e + 1) % 3], b, pr.i, pr.j) * pr.orientation;
      l[e] = Pr::o2(a, b, t.v[e], pr.i, pr.j);
    }
    bool weak = false;
    for (int e = 0; e < 3; ++e) {
      if (ea[e] < 0 && eb[e] < 0) return Dimension::none;
      weak = weak || (ea[e] <= 0 && eb[e] <= 0);
    }
    if ((l[0] > 0 && l[1] > 0 && l[2] > 0) || (l[0] < 0 && l[1] < 0 && l[2] < 0)) return Dimension::none;
    weak = weak || (l[0] >= 0 && l[1] >= 0 && l[2] >= 0) || (l[0] <= 0 && l[1] <= 0 && l[2] <= 0);
    if (!weak) return Dimension::segment;  // the segment meets the triangle's interior
    for (int e = 0; e < 3; ++e)
      if (ea[e] == 0 && eb[e] == 0 && collinear_overlap(a, b, t.v[e], t.v[(e + 1) % 3]) == Dimension::segment)
        return Dimension::segment;
    return Dimension::point;
  }
  if (oa == 0) return point_in_triangle<Pr>(a, t, n) ? Dimension::point : Dimension::none;
  if (ob == 0) return point_in_triangle<Pr>(b, t, n) ? Dimension::point : Dimension::none;
  int g[3];
  for (int e = 0; e < 3; ++e) g[e] = Pr::o3(a, b, t.v[e], t.v[(e + 1) % 3]);
  const bool hit = (g[0] >= 0 && g[1] >= 0 && g[2] >= 0) || (g[0] <= 0 && g[1] <= 0 && g[2] <= 0);
  return hit ? Dimension::point : Dimension::none;
}

template <class Pr>
Dimension shapes_meet(Shape a, Shape b) {
  if (a.kind > b.kind) std::swap(a, b);
  if (a.kind == 0) {
    if (b.kind == 0) return same_point(a.p[0], b.p[0]) ? Dimension::point : Dimension::none;
    if (b.kind == 1) return point_on_segment<Pr>(a.p[0], b.p[0], b.p[1]) ? Dimension::point : Dimension::none;
    return point_in_triangle<Pr>(a.p[0], Tri{{b.p[0], b.p[1], b.p[2]}}, b.n) ? Dimension::point : Dimension::none;
  }
  if (b.kind == 1) return segment_segment<Pr>(a.p[0], a.p[1], b.p[0], b.p[1]);
  return segment_triangle<Pr>(a.p[0], a.p[1], Tri{{b.p[0], b.p[1], b.p[2]}}, b.n);
}

// ---- coplanar proper triangles ----

// The 18 signs of a coplanar pair in one projection, sign-normalised so that inside is positive:
// o[0][e][v] is b's vertex v against a's edge e (from vertex e to e+1) times a's orientation,
// o[1][e][v] a's vertex v against b's edge e times b's orientation.
using CoplanarSigns = int[2][3][3];

// The relation of coplanar proper triangles a, b from their 18 exact signs, by the separating-
// axis theorem (algorithms/exact/README.md, step 3 of "The decisions"). At the overlap level only
// the emptiness counts.
template <bool kRelation>
Relation coplanar_from_signs(const Tri& a, const Tri& b, const CoplanarSigns& o) {
  // Without branches on the signs: an edge separates strictly when the largest of its three
  // signs is negative, weakly when it is not positive.
  int largest[6];
  bool strict = false;
  for (int s = 0; s < 2; ++s)
    for (int e = 0; e < 3; ++e) {
      const int* r = o[s][e];
      const int m = std::max(r[0], std::max(r[1], r[2]));
      largest[3 * s + e] = m;
      strict |= m < 0;
    }
  if (strict) return Relation::coplanar_disjoint;
  if (!kRelation) return Relation::coplanar_overlap;  // meets; the kind is not asked for
  int weak_side = -1, weak_edge = -1;
  for (int k = 0; k < 6; ++k)
    if (weak_side < 0 && largest[k] <= 0) weak_side = k / 3, weak_edge = k % 3;
  if (weak_side < 0) return Relation::coplanar_overlap;
  const Tri& edge_owner = weak_side == 0 ? a : b;
  const Tri& other = weak_side == 0 ? b : a;
  const int* r = o[weak_side][weak_edge];
  const int zeros = (r[0] == 0) + (r[1] == 0) + (r[2] == 0);
  if (zeros == 1) return Relation::coplanar_point;
  int u = -1, w = -1;
  for (int v = 0; v < 3; ++v)
    if (r[v] == 0) (u < 0 ? u : w) = v;
  const Dimension d = collinear_overlap(edge_owner.v[weak_edge], edge_owner.v[(weak_edge + 1) % 3],
                                        other.v[u], other.v[w]);
  return d == Dimension::segment ? Relation::coplanar_segment : Relation::coplanar_point;
}

template <class Pr, bool kRelation>
Relation coplanar(const Tri& a, const Tri& b, const int na[3], const int nb[3]) {
  const Projection pr = projection_for(na);
  const int ob = nb[(pr.i + 2) % 3];  // b's orientation in the same projection (non-zero)
  const Projected p = project(a.v, b.v, pr.i, pr.j);
  const double bound2 = projected_bound(p);  // one bound for all 18 orientations
  const CoplanarValues cv = coplanar_values(p);
  CoplanarSigns o;
  for (int side = 0; side < 2; ++side) {
    const Tri& t = side == 0 ? a : b;
    const Tri& u = side == 0 ? b : a;
    const int orient = side == 0 ? pr.orientation : ob;
    for (int e = 0; e < 3; ++e)
      for (int v = 0; v < 3; ++v)
        o[side][e][v] = Pr::o2_with(cv.edge[e][v][side], bound2, t.v[e], t.v[(e + 1) % 3], u.v[v], pr.i, pr.j) * orient;
  }
  return coplanar_from_signs<kRelation>(a, b, o);
}

// ---- Guigue–Devillers' canonical order ----

// The lone vertex l and the sign f (±1) with f·s[l] >= 0 >= f·s[l+1], f·s[l+2], and either
// f·s[l] > 0 or both others strictly negative (the first such l, then f = 1 before -1). s is
// neither all zero nor one-sided.
constexpr bool is_lone(const int s[3], int l, int f) {
  const int p = f * s[l], q = f * s[(l + 1) % 3], r = f * s[(l + 2) % 3];
  return p >= 0 && q <= 0 && r <= 0 && (p > 0 || (q < 0 && r < 0));
}

// lone_vertex's answer per sign triple, indexed by 9(s0 + 1) + 3(s1 + 1) + s2 + 1; the patterns
// it is not asked about (all zero, one-sided) hold l = 0, f = 1.
struct LoneFlip {
  signed char l, f;
};
constexpr auto kLoneFlip = [] {
  std::array<LoneFlip, 27> t{};
  for (int k = 0; k < 27; ++k) {
    const int s[3] = {k / 9 - 1, k / 3 % 3 - 1, k % 3 - 1};
    t[k] = {0, 1};
    for (int l = 2; l >= 0; --l)  // downwards, so that the first match is the one kept
      for (int f = -1; f <= 1; f += 2)
        if (is_lone(s, l, f)) t[k] = {static_cast<signed char>(l), static_cast<signed char>(f)};
  }
  return t;
}();

inline void lone_vertex(const int s[3], int& l, int& f) {
  const LoneFlip e = kLoneFlip[9 * (s[0] + 1) + 3 * (s[1] + 1) + s[2] + 1];
  l = e.l, f = e.f;
}

inline int zero_count(const int s[3]) { return (s[0] == 0) + (s[1] == 0) + (s[2] == 0); }
inline bool one_sided(const int s[3]) {
  return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
}

// The relation of two proper triangles whose planes cross (s1, s2 not one-sided, not coplanar).
template <class Pr, bool kRelation>
Relation crossing(const Tri& t1, const Tri& t2, const int s1[3], const int s2[3]) {
  int l1, f1, l2, f2;
  lone_vertex(s1, l1, f1);
  lone_vertex(s2, l2, f2);
  P p1 = t1.v[l1], q1 = t1.v[(l1 + 1) % 3], r1 = t1.v[(l1 + 2) % 3];
  P p2 = t2.v[l2], q2 = t2.v[(l2 + 1) % 3], r2 = t2.v[(l2 + 2) % 3];
  if (f2 < 0) std::swap(q1, r1);  // flips π1 so that p2 is on its positive side
  if (f1 < 0) std::swap(q2, r2);  // flips π2 so that p1 is on its positive side
  const int g1 = Pr::o3(p1, q1, p2, q2);
  if (g1 > 0) return Relation::disjoint;
  const int g2 = Pr::o3(p1, r1, r2, p2);
  if (g2 > 0) return Relation::disjoint;
  if (!kRelation) return Relation::cross;  // meets
  if (g1 == 0 || g2 == 0 || s1[l1] == 0 || s2[l2] == 0) return Relation::touch_point;
  return (zero_count(s1) == 2 || zero_count(s2) == 2) ? Relation::touch_segment : Relation::cross;
}

// ---- the whole classification ----

// Degenerate input gives {degenerate, dimension}; otherwise the relation of the oracle. With
// kRelation false only meet/no-meet is exact (the relation returned is some relation with the
// right emptiness). `known`: T1's and T2's exact plane signs (s1 then s2) when the caller has
// them (one_pair.hpp, on the grid), else null.
template <class Pr, bool kRelation>
RelationAnswer classify(const Tri& t1, const Tri& t2, const int* known = nullptr) {
  int n1[3], n2[3];
  const bool proper1 = normal_signs<Pr>(t1, n1);
  const bool proper2 = normal_signs<Pr>(t2, n2);
  if (!proper1 || !proper2) {
    Shape a = proper1 ? Shape{2, {t1.v[0], t1.v[1], t1.v[2]}, {n1[0], n1[1], n1[2]}} : hull_of_collinear(t1);
    Shape b = proper2 ? Shape{2, {t2.v[0], t2.v[1], t2.v[2]}, {n2[0], n2[1], n2[2]}} : hull_of_collinear(t2);
    return {Relation::degenerate, shapes_meet<Pr>(a, b)};
  }
  int s1[3], s2[3];
  if (known) {
    for (int k = 0; k < 3; ++k) s1[k] = known[k], s2[k] = known[3 + k];
  } else {
    plane_signs<Pr>(t1, t2, s1, s2);
  }
  if (one_sided(s1) || one_sided(s2)) {
    if (!kRelation) return answer_with(Relation::disjoint);
    const bool parallel = Pr::d3(t2.v[0], t2.v[1], t2.v[0], t2.v[2], t1.v[0], t1.v[1]) == 0 &&
                          Pr::d3(t2.v[0], t2.v[1], t2.v[0], t2.v[2], t1.v[0], t1.v[2]) == 0;
    return answer_with(parallel ? Relation::parallel : Relation::disjoint);
  }
  if (s2[0] == 0 && s2[1] == 0 && s2[2] == 0) return answer_with(coplanar<Pr, kRelation>(t1, t2, n1, n2));
  return answer_with(crossing<Pr, kRelation>(t1, t2, s1, s2));
}

// Overlap from a classification: the meet is non-empty.
inline bool meets(const RelationAnswer& a) {
  if (a.relation == Relation::degenerate) return a.dimension != Dimension::none;
  return dimension_of(a.relation) != Dimension::none;
}

}  // namespace tritri::exact::detail
