// Families 8-11: the triangles in one plane or in two parallel planes.
#include "cases/generator/canonical.hpp"
#include "cases/generator/families_parts.hpp"

#include <cmath>
#include <string>

namespace tritri::corpus {
namespace {

using R = Relation;

// ---- 8. coplanar-containment ------------------------------------------------------------

Construction containment_strict(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 p = interior_point(rng, t), q = interior_point(rng, t), r = interior_point(rng, t);
  return {pair_of(t, p, q, r)};
}

Construction containment_vertex(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 p = t[rng.between(0, 2)], q = interior_point(rng, t), r = interior_point(rng, t);
  return {pair_of(t, p, q, r)};
}

Construction containment_edge_points(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const int e = rng.between(0, 2);
  const V3 p = edge_point(rng, t, e), q = edge_point(rng, t, e), r = interior_point(rng, t);
  return {pair_of(t, p, q, r)};
}

Construction containment_whole_edge(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const int e = rng.between(0, 2);
  return {pair_of(t, t[e], t[(e + 1) % 3], interior_point(rng, t))};
}

Construction containment_two_edges(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const int e = rng.between(0, 2);
  const V3 p = edge_point(rng, t, e), q = edge_point(rng, t, (e + 1) % 3), r = interior_point(rng, t);
  return {pair_of(t, p, q, r)};
}

Construction containment_identical(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const int k = rng.between(0, 2);
  return {pair_of(t, t[k], t[(k + 1) % 3], t[(k + 2) % 3])};
}

// ---- 9. coplanar-overlap ----------------------------------------------------------------
// The star of David: T1 reflected through its centroid G. T1's coordinates are multiples of
// 24 here, so G (a third of the sum) and the eighth-weight points are integers.

Construction overlap_star(Rng& rng) {
  const Triangle t = canonical_t1(rng, 24);
  const V3 g2 = 2.0 * (t[0] + t[1] + t[2]) / 3.0;
  return {pair_of(t, g2 - t[0], g2 - t[1], g2 - t[2])};
}

// The star with its centre moved to another interior point Y: still inside both, so the
// overlap survives, with 3 to 6 corners.
Construction overlap_star_shifted(Rng& rng) {
  const Triangle t = canonical_t1(rng, 24);
  const V3 g = (t[0] + t[1] + t[2]) / 3.0;
  const V3 shift = interior_point(rng, t) - g;
  return {pair_of(t, 2.0 * g - t[0] + shift, 2.0 * g - t[1] + shift, 2.0 * g - t[2] + shift)};
}

Construction overlap_vertex_inside(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 y = interior_point(rng, t);
  const V3 d1 = in_plane(rng), d2 = in_plane(rng);
  return {pair_of(t, y, y + 4.0 * d1, y + 4.0 * d2)};
}

Construction overlap_two_inside(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const int e = rng.between(0, 2);
  const V3 p = interior_point(rng, t), q = interior_point(rng, t), r = away_from(rng, t, edge_point(rng, t, e));
  return {pair_of(t, p, q, r)};
}

// A triangle whose centroid c is a point of T1 (a vertex, or an interior point): T2 then
// contains a neighbourhood of c, and T1 has area in any neighbourhood of its own points.
Construction centred_on(const Triangle& t, const V3& c, Rng& rng) {
  const V3 d1 = in_plane(rng, 12), d2 = in_plane(rng, 12);
  return {pair_of(t, c + d1, c + d2, c - d1 - d2)};
}

Construction overlap_around_vertex(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  return centred_on(t, t[rng.between(0, 2)], rng);
}

Construction overlap_random(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  return centred_on(t, interior_point(rng, t), rng);
}

// ---- 10. coplanar-disjoint --------------------------------------------------------------
// T1 lies in y >= 0 with edge AB on y = 0; T2 lies in y <= -gap.

int gap_exponent(Rng& rng) { return rng.between(-40, 3); }

Construction apart_by(const Triangle& t, double gap, bool edge_parallel, Rng& rng) {
  const double l = t[1].x();
  const double x0 = rng.between(-8, int(l) + 8);
  const V3 p = v3(x0, -gap, 0);
  V3 q;
  if (edge_parallel) {
    q = v3(x0 + rng.nonzero_between(-8, 8), -gap, 0);
  } else {
    const double dx = rng.between(-8, 8), dy = rng.between(1, 8);
    q = v3(x0 + dx, -gap - dy, 0);
  }
  const double dx = rng.between(-8, 8), dy = rng.between(1, 8);
  const V3 r = v3(x0 + dx, -gap - dy, 0);
  return {pair_of(t, p, q, r)};
}

template <bool edge_parallel>
Construction disjoint_gap(Rng& rng) {
  const int k = gap_exponent(rng);
  Construction c = apart_by(canonical_t1(rng), std::ldexp(1.0, k), edge_parallel, rng);
  c.labels.push_back({"gap", power_of_two(k)});
  return c;
}

// One ulp: the edge line is moved to y = c, and T2's nearest vertices sit at the double just
// below c. Only axis frames keep that exact.
template <bool edge_parallel>
Construction disjoint_ulp(Rng& rng) {
  Triangle t = canonical_t1(rng);
  const double c = rng.between(1, 64);
  for (auto& v : t.v) v.y() += c;
  Construction out = apart_by(t, 1.0, edge_parallel, rng);
  for (auto& v : out.pair.t2.v) v.y() += c;
  const double below = std::nextafter(c, -INFINITY);
  out.pair.t2[0].y() = below;
  if (edge_parallel) out.pair.t2[1].y() = below;
  out.frame = FrameKind::axis;
  out.labels.push_back({"gap", "ulp"});
  return out;
}

// ---- 11. parallel -----------------------------------------------------------------------

double offset(Rng& rng, int& k) {
  k = rng.between(-40, 3);
  return rng.sign() * std::ldexp(1.0, k);
}

Construction lifted(const Triangle& t, const std::array<V3, 3>& shape, double h, int k) {
  const V3 up = v3(0, 0, h);
  Construction c{pair_of(t, shape[0] + up, shape[1] + up, shape[2] + up)};
  c.labels.push_back({"offset", power_of_two(k)});
  return c;
}

Construction parallel_stacked(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  int k;
  const double h = offset(rng, k);
  return lifted(t, t.v, h, k);
}

Construction parallel_shifted(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  int k;
  const double h = offset(rng, k);
  const V3 d = in_plane(rng, 16);
  return lifted(t, {t[0] + d, t[1] + d, t[2] + d}, h, k);
}

Construction parallel_other(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  int k;
  const double h = offset(rng, k);
  const V3 c = interior_point(rng, t), d1 = in_plane(rng, 12), d2 = in_plane(rng, 12);
  return lifted(t, {c + d1, c + d2, c - d1 - d2}, h, k);
}

Construction parallel_ulp(Rng& rng) {
  Triangle t = canonical_t1(rng);
  const double c = rng.between(1, 64);
  for (auto& v : t.v) v.z() = c;
  const double next = std::nextafter(c, rng.sign() * INFINITY);
  const V3 d = in_plane(rng, 4);
  Construction out{pair_of(t, t[0] + d, t[1] + d, t[2] + d)};
  for (auto& v : out.pair.t2.v) v.z() = next;
  out.frame = FrameKind::axis;
  out.labels.push_back({"offset", "ulp"});
  return out;
}

const FamilyConfig kPlaneConfigs[] = {
    {"coplanar-containment", {"strict", R::coplanar_overlap, containment_strict}},
    {"coplanar-containment", {"vertex", R::coplanar_overlap, containment_vertex}},
    {"coplanar-containment", {"edge-points", R::coplanar_overlap, containment_edge_points}},
    {"coplanar-containment", {"whole-edge", R::coplanar_overlap, containment_whole_edge}},
    {"coplanar-containment", {"two-edges", R::coplanar_overlap, containment_two_edges}},
    {"coplanar-containment", {"identical", R::coplanar_overlap, containment_identical}},
    {"coplanar-overlap", {"star", R::coplanar_overlap, overlap_star}},
    {"coplanar-overlap", {"star-shifted", R::coplanar_overlap, overlap_star_shifted}},
    {"coplanar-overlap", {"vertex-inside", R::coplanar_overlap, overlap_vertex_inside}},
    {"coplanar-overlap", {"two-inside", R::coplanar_overlap, overlap_two_inside}},
    {"coplanar-overlap", {"around-vertex", R::coplanar_overlap, overlap_around_vertex}},
    {"coplanar-overlap", {"random", R::coplanar_overlap, overlap_random}},
    {"coplanar-disjoint", {"gap-vertex", R::coplanar_disjoint, disjoint_gap<false>}},
    {"coplanar-disjoint", {"gap-edge", R::coplanar_disjoint, disjoint_gap<true>}},
    {"coplanar-disjoint", {"ulp-vertex", R::coplanar_disjoint, disjoint_ulp<false>}},
    {"coplanar-disjoint", {"ulp-edge", R::coplanar_disjoint, disjoint_ulp<true>}},
    {"parallel", {"stacked", R::parallel, parallel_stacked}},
    {"parallel", {"shifted", R::parallel, parallel_shifted}},
    {"parallel", {"other", R::parallel, parallel_other}},
    {"parallel", {"ulp", R::parallel, parallel_ulp}},
};

}  // namespace

std::span<const FamilyConfig> plane_configs() { return kPlaneConfigs; }

}  // namespace tritri::corpus
