// Families 1-7: contact between the triangles at a vertex, an edge or a face.
//
// Every construction keeps T1 in the plane z = 0 (see canonical.hpp) and puts T2's singular
// vertex first, since perturbation moves T2's first vertex. A recurring device: a T2 whose
// edge PQ has midpoint X on the plane z = 0 (P = X + e, Q = X - e, e.z != 0) cuts the plane
// along a segment starting at X, so the segment's other end is irrelevant when X is inside T1.
#include "cases/generator/canonical.hpp"
#include "cases/generator/families_parts.hpp"

namespace tritri::corpus {
namespace {

using R = Relation;

int random_vertex(Rng& rng) { return rng.between(0, 2); }

// ---- 1. shared-vertex -------------------------------------------------------------------

// T2 leaves the shared vertex upwards only: the planes meet in a line through V alone.
Construction shared_vertex_away(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 v = t[random_vertex(rng)];
  const V3 u = upward(rng), w = upward(rng);
  return {pair_of(t, v, v + u, v + w)};
}

// T2 cuts the plane along a segment from V into T1's interior (X = V + k(Y - V), Y inside).
Construction shared_vertex_cross(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 v = t[random_vertex(rng)];
  const double k = rng.between(1, 2);
  const V3 x = v + k * (interior_point(rng, t) - v);
  const V3 e = upward(rng);
  return {pair_of(t, v, x + e, x - e)};
}

// T2 cuts the plane along a segment from V directly away from T1.
Construction shared_vertex_through_outside(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 v = t[random_vertex(rng)];
  const V3 x = away_from(rng, t, v);
  const V3 e = upward(rng);
  return {pair_of(t, v, x + e, x - e)};
}

// Coplanar, T2 inside V's opposite cone: the two closed cones share only their apex.
Construction shared_vertex_coplanar_point(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 v = t[random_vertex(rng)];
  const V3 p = away_from(rng, t, v), q = away_from(rng, t, v);
  return {pair_of(t, v, p, q)};
}

// Coplanar, T2 has a vertex inside T1: they share area around it.
Construction shared_vertex_coplanar_overlap(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 v = t[random_vertex(rng)];
  const V3 y = interior_point(rng, t);
  return {pair_of(t, v, y, y + in_plane(rng))};
}

// ---- 2. vertex-on-edge ------------------------------------------------------------------

struct EdgeContact {
  Triangle t;
  int edge;
  V3 e;  // strictly inside the edge
};

EdgeContact edge_contact(Rng& rng) {
  EdgeContact c{canonical_t1(rng), rng.between(0, 2), {}};
  c.e = edge_point(rng, c.t, c.edge);
  return c;
}

Construction vertex_on_edge_above(Rng& rng) {
  const auto c = edge_contact(rng);
  const V3 u = upward(rng), w = upward(rng);
  return {pair_of(c.t, c.e, c.e + u, c.e + w)};
}

Construction vertex_on_edge_cross(Rng& rng) {
  const auto c = edge_contact(rng);
  const double k = rng.between(1, 2);
  const V3 x = c.e + k * (interior_point(rng, c.t) - c.e);
  const V3 e = upward(rng);
  return {pair_of(c.t, c.e, x + e, x - e)};
}

Construction vertex_on_edge_outward(Rng& rng) {
  const auto c = edge_contact(rng);
  const V3 x = away_from(rng, c.t, c.e);
  const V3 e = upward(rng);
  return {pair_of(c.t, c.e, x + e, x - e)};
}

// T2's cut runs from the edge point along the edge and past its end vertex: the contact is
// the part of T1's edge between them.
Construction vertex_on_edge_along(Rng& rng) {
  const auto c = edge_contact(rng);
  const V3 end = c.t[(c.edge + 1) % 3];
  const V3 x = end + double(rng.between(0, 2)) * (end - c.e) / 8.0;
  const V3 e = upward(rng);
  return {pair_of(c.t, c.e, x + e, x - e)};
}

Construction vertex_on_edge_coplanar_point(Rng& rng) {
  const auto c = edge_contact(rng);
  const V3 p = away_from(rng, c.t, c.e), q = away_from(rng, c.t, c.e);
  return {pair_of(c.t, c.e, p, q)};
}

Construction vertex_on_edge_coplanar_overlap(Rng& rng) {
  const auto c = edge_contact(rng);
  const V3 y = interior_point(rng, c.t);
  return {pair_of(c.t, c.e, y, y + in_plane(rng))};
}

// ---- 3. vertex-on-face ------------------------------------------------------------------

Construction vertex_on_face_touch(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 y = interior_point(rng, t);
  const V3 u = upward(rng), w = upward(rng);
  return {pair_of(t, y, y + u, y + w)};
}

Construction vertex_on_face_pierce(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 y = interior_point(rng, t);
  const V3 x = y + in_plane(rng, 12);
  const V3 e = upward(rng);
  return {pair_of(t, y, x + e, x - e)};
}

// T2 crosses the plane at the interior point with one edge through it: the cut starts inside.
Construction vertex_on_face_straddle(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 y = interior_point(rng, t);
  const V3 up = upward(rng);
  return {pair_of(t, y, y + up, y - upward(rng))};
}

// ---- 4. shared-edge ---------------------------------------------------------------------

struct SharedEdge {
  Triangle t;
  V3 p, q, mid, inward;  // inward: from the edge's midpoint towards the opposite vertex
};

SharedEdge shared_edge(Rng& rng) {
  SharedEdge s{canonical_t1(rng), {}, {}, {}, {}};
  const int e = rng.between(0, 2);
  s.p = s.t[e];
  s.q = s.t[(e + 1) % 3];
  s.mid = (s.p + s.q) / 2.0;
  s.inward = s.t[(e + 2) % 3] - s.mid;
  return s;
}

// The hinge opens at many dihedral angles: any mix of inward, outward and upward.
Construction shared_edge_hinge(Rng& rng) {
  const auto s = shared_edge(rng);
  const double in = rng.between(-3, 3), along = rng.between(-2, 2), up = rng.nonzero_between(-8, 8);
  const V3 r = s.mid + in / 2.0 * s.inward + along / 8.0 * (s.q - s.p) + v3(0, 0, up);
  return {pair_of(s.t, s.p, s.q, r)};
}

Construction shared_edge_coplanar_opposite(Rng& rng) {
  const auto s = shared_edge(rng);
  const double out = rng.between(1, 4), along = rng.between(-4, 4);
  const V3 r = s.mid - out / 2.0 * s.inward + along / 8.0 * (s.q - s.p);
  return {pair_of(s.t, s.p, s.q, r)};
}

Construction shared_edge_coplanar_folded(Rng& rng) {
  const auto s = shared_edge(rng);
  const double in = rng.between(1, 4), along = rng.between(-4, 4);
  const V3 r = s.mid + in / 2.0 * s.inward + along / 8.0 * (s.q - s.p);
  return {pair_of(s.t, s.p, s.q, r)};
}

// ---- 5. collinear-edges -----------------------------------------------------------------
// T2's edge PQ lies on the x-axis, the line of T1's edge AB = [0, L]. T1 meets the x-axis in
// AB only, so the contact is PQ ∩ AB (or an area, when T2 folds onto T1's side).

enum class Span { overlap, contain, endpoint, gap };

// [p, q] on the x-axis in the relation `span` with [0, L].
std::pair<double, double> span_on_axis(Rng& rng, Span span, double l) {
  const double in = rng.between(1, int(l) - 1);
  switch (span) {
    case Span::overlap:
      return rng.sign() > 0 ? std::pair{in, l + rng.between(1, 8)} : std::pair{-double(rng.between(1, 8)), in};
    case Span::contain: {
      if (rng.sign() > 0) return {-double(rng.between(1, 8)), l + rng.between(1, 8)};  // T2's edge holds AB
      const double a = rng.between(0, int(l) - 1), b = rng.between(int(a) + 1, int(l));
      if (a == 0 && b == l) return {0, l - 1};  // all of AB would be the shared-edge family
      return {a, b};
    }
    case Span::endpoint:
      return rng.sign() > 0 ? std::pair{l, l + rng.between(1, 8)} : std::pair{-double(rng.between(1, 8)), 0.0};
    case Span::gap:
      return rng.sign() > 0 ? std::pair{l + rng.between(1, 4), l + rng.between(5, 12)}
                            : std::pair{-double(rng.between(5, 12)), -double(rng.between(1, 4))};
  }
  return {0, 0};
}

enum class Third { skew, opposite, same };

template <Span span, Third third>
Construction collinear(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const auto [p, q] = span_on_axis(rng, span, t[1].x());
  V3 r = third == Third::skew ? upward(rng) : in_plane(rng);
  if (third == Third::opposite) r.y() = -std::abs(r.y()) - 1;
  if (third == Third::same) r.y() = std::abs(r.y()) + 1;
  if (third == Third::skew && rng.sign() < 0) r.z() = -r.z();
  return {pair_of(t, v3(p, 0, 0), v3(q, 0, 0), r)};
}

// ---- 6. edge-crossing -------------------------------------------------------------------
// T2 = P, Q, R with Q below the plane and P = 2X - Q, R = 2F - Q above it: T2 cuts the plane
// along XF, X on edge PQ. With X on T1's edge AB (the x-axis) the edges cross at X.

V3 below_axis(Rng& rng, double l) {
  const double x = rng.between(-4, int(l) + 4), y = -rng.between(1, 6);
  return v3(x, y, 0);
}

TrianglePair edge_cross_pair(const Triangle& t, const V3& x, const V3& f, Rng& rng) {
  const double dx = rng.between(-4, 4), dy = rng.between(-4, 4), dz = -rng.between(1, 6);
  const V3 q = x + v3(dx, dy, dz);
  return pair_of(t, 2.0 * x - q, q, 2.0 * f - q);
}

Construction edge_crossing_touch(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 x = edge_point(rng, t, 0);
  return {edge_cross_pair(t, x, below_axis(rng, t[1].x()), rng)};
}

Construction edge_crossing_through(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 x = edge_point(rng, t, 0);
  return {edge_cross_pair(t, x, interior_point(rng, t), rng)};
}

Construction edge_crossing_at_vertex(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 x = t[random_vertex(rng)];
  return {edge_cross_pair(t, x, away_from(rng, t, x), rng)};
}

Construction edge_crossing_beyond(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 x = v3(t[1].x() + rng.between(1, 8), 0, 0);
  return {edge_cross_pair(t, x, below_axis(rng, t[1].x()), rng)};
}

// ---- 7. edge-on-face --------------------------------------------------------------------

Construction edge_on_face_inside(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 p = interior_point(rng, t), q = interior_point(rng, t), r = off_plane(rng);
  return {pair_of(t, p, q, r)};
}

Construction edge_on_face_exiting(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 p = interior_point(rng, t);
  const int e = rng.between(0, 2);
  const V3 q = away_from(rng, t, edge_point(rng, t, e)), r = off_plane(rng);
  return {pair_of(t, p, q, r)};
}

// The edge passes through an interior point, its ends (mostly) outside.
Construction edge_on_face_spanning(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 y = interior_point(rng, t);
  const V3 d = 8.0 * in_plane(rng);
  return {pair_of(t, y + d, y - d, off_plane(rng))};
}

Construction edge_on_face_piercing(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 y = interior_point(rng, t);
  const V3 e = upward(rng);
  return {pair_of(t, y + e, y - e, off_plane(rng))};
}

// In T1's plane but across one of its edges: both ends beyond the same edge line.
Construction edge_on_face_outside(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const int e = rng.between(0, 2);
  const V3 p = away_from(rng, t, edge_point(rng, t, e));
  const V3 q = away_from(rng, t, edge_point(rng, t, e));
  return {pair_of(t, p, q, off_plane(rng))};
}

const FamilyConfig kContactConfigs[] = {
    {"shared-vertex", {"away", R::touch_point, shared_vertex_away}},
    {"shared-vertex", {"cross", R::cross, shared_vertex_cross}},
    {"shared-vertex", {"through-outside", R::touch_point, shared_vertex_through_outside}},
    {"shared-vertex", {"coplanar-point", R::coplanar_point, shared_vertex_coplanar_point}},
    {"shared-vertex", {"coplanar-overlap", R::coplanar_overlap, shared_vertex_coplanar_overlap}},
    {"vertex-on-edge", {"above", R::touch_point, vertex_on_edge_above}},
    {"vertex-on-edge", {"cross", R::cross, vertex_on_edge_cross}},
    {"vertex-on-edge", {"outward", R::touch_point, vertex_on_edge_outward}},
    {"vertex-on-edge", {"along", R::touch_segment, vertex_on_edge_along}},
    {"vertex-on-edge", {"coplanar-point", R::coplanar_point, vertex_on_edge_coplanar_point}},
    {"vertex-on-edge", {"coplanar-overlap", R::coplanar_overlap, vertex_on_edge_coplanar_overlap}},
    {"vertex-on-face", {"touch", R::touch_point, vertex_on_face_touch}},
    {"vertex-on-face", {"pierce", R::cross, vertex_on_face_pierce}},
    {"vertex-on-face", {"straddle", R::cross, vertex_on_face_straddle}},
    {"shared-edge", {"hinge", R::touch_segment, shared_edge_hinge}},
    {"shared-edge", {"coplanar-opposite", R::coplanar_segment, shared_edge_coplanar_opposite}},
    {"shared-edge", {"coplanar-folded", R::coplanar_overlap, shared_edge_coplanar_folded}},
    {"collinear-edges", {"overlap-skew", R::touch_segment, collinear<Span::overlap, Third::skew>}},
    {"collinear-edges", {"contain-skew", R::touch_segment, collinear<Span::contain, Third::skew>}},
    {"collinear-edges", {"endpoint-skew", R::touch_point, collinear<Span::endpoint, Third::skew>}},
    {"collinear-edges", {"gap-skew", R::disjoint, collinear<Span::gap, Third::skew>}},
    {"collinear-edges", {"overlap-coplanar", R::coplanar_segment, collinear<Span::overlap, Third::opposite>}},
    {"collinear-edges", {"contain-coplanar", R::coplanar_segment, collinear<Span::contain, Third::opposite>}},
    {"collinear-edges", {"endpoint-coplanar", R::coplanar_point, collinear<Span::endpoint, Third::opposite>}},
    {"collinear-edges", {"gap-coplanar", R::coplanar_disjoint, collinear<Span::gap, Third::opposite>}},
    {"collinear-edges", {"overlap-folded", R::coplanar_overlap, collinear<Span::overlap, Third::same>}},
    {"collinear-edges", {"contain-folded", R::coplanar_overlap, collinear<Span::contain, Third::same>}},
    {"edge-crossing", {"touch", R::touch_point, edge_crossing_touch}},
    {"edge-crossing", {"through", R::cross, edge_crossing_through}},
    {"edge-crossing", {"at-vertex", R::touch_point, edge_crossing_at_vertex}},
    {"edge-crossing", {"beyond", R::disjoint, edge_crossing_beyond}},
    {"edge-on-face", {"inside", R::touch_segment, edge_on_face_inside}},
    {"edge-on-face", {"exiting", R::touch_segment, edge_on_face_exiting}},
    {"edge-on-face", {"spanning", R::touch_segment, edge_on_face_spanning}},
    {"edge-on-face", {"piercing", R::cross, edge_on_face_piercing}},
    {"edge-on-face", {"outside", R::disjoint, edge_on_face_outside}},
};

}  // namespace

std::span<const FamilyConfig> contact_configs() { return kContactConfigs; }

}  // namespace tritri::corpus
