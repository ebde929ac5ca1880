// Families 12-16: near-coplanar tilts, axis-aligned walls, slivers, tiny against huge, and
// random pairs.
#include "cases/generator/canonical.hpp"
#include "cases/generator/families_parts.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace tritri::corpus {
namespace {

using R = Relation;

// ---- 12. near-coplanar ------------------------------------------------------------------
// T2 is built in T1's plane and then tilted about the line y = y0 by z = s·(y - y0), s = ±2^-k:
// a slope from about 1e-1 down to 1e-15 (the angle is atan(2^-k)), exact in double because s
// is a power of two. The shear is not rigid, but it keeps T2's cut with T1's plane on the line
// y = y0, which is what decides the relation. Rigid rotations, rounded, come with the rotate
// variant.

constexpr int kTiltExponents[] = {3, 7, 10, 13, 17, 20, 23, 27, 30, 33, 37, 40, 43, 47, 50};

Construction tilted(const Triangle& t, std::array<V3, 3> flat, double y0, Rng& rng) {
  const int k = kTiltExponents[rng.between(0, std::size(kTiltExponents) - 1)];
  const double s = rng.sign() * std::ldexp(1.0, -k);
  for (auto& v : flat) v.z() = s * (v.y() - y0);
  Construction c{pair_of(t, flat[0], flat[1], flat[2])};
  c.frame = FrameKind::planar;
  c.labels.push_back({"tilt", power_of_two(-k)});
  return c;
}

std::array<V3, 3> centred(const V3& c, Rng& rng) {
  const V3 d1 = in_plane(rng, 12), d2 = in_plane(rng, 12);
  return {c + d1, c + d2, c - d1 - d2};
}

// The tilt axis passes through a point inside both: the cut crosses both interiors.
Construction near_coplanar_through(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 y = interior_point(rng, t);
  return tilted(t, centred(y, rng), y.y(), rng);
}

// Overlapping before the tilt, but the axis runs beside both: T2 rises off T1's plane
// everywhere.
Construction near_coplanar_axis_outside(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const auto flat = centred(interior_point(rng, t), rng);
  double low = 0;
  for (const auto& v : flat) low = std::min(low, v.y());
  return tilted(t, flat, low - rng.between(1, 4), rng);
}

// Apart before the tilt (T2 below the x-axis, T1 above): the cut stays inside T2's shadow.
Construction near_coplanar_apart(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const double x0 = rng.between(-8, int(t[1].x()) + 8);
  const double y0 = -rng.between(1, 4);
  const double x1 = x0 + rng.between(-8, 8), y1 = -rng.between(5, 12);
  const double x2 = x0 + rng.nonzero_between(-8, 8), y2 = -rng.between(1, 12);
  const std::array<V3, 3> flat = {v3(x0, y0, 0), v3(x1, y1, 0), v3(x2, y2, 0)};
  return tilted(t, flat, rng.between(-8, 16), rng);
}

// Centred on a point of T1's edge AB and tilted about AB's line: the cut runs along T1's edge.
Construction near_coplanar_hinge(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  return tilted(t, centred(edge_point(rng, t, 0), rng), 0.0, rng);
}

// ---- 13. axis-aligned -------------------------------------------------------------------
// The canonical frame is already axis-aligned (T1 in z = 0); axis frames keep it so.

Construction axis_wall_cross(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 y1 = interior_point(rng, t), y2 = interior_point(rng, t);
  const V3 u = upward(rng);
  // T2 cuts T1's plane along Y1-Y2: PQ has midpoint Y1 and PR has midpoint Y2.
  Construction c{pair_of(t, y1 + u, y1 - u, 2.0 * y2 - (y1 + u))};
  c.frame = FrameKind::axis;
  return c;
}

Construction axis_wall_touch(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 y = interior_point(rng, t), u = upward(rng), w = upward(rng);
  Construction c{pair_of(t, y, y + u, y + w)};
  c.frame = FrameKind::axis;
  return c;
}

Construction axis_wall_edge(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 p = interior_point(rng, t), q = interior_point(rng, t), r = off_plane(rng);
  Construction c{pair_of(t, p, q, r)};
  c.frame = FrameKind::axis;
  return c;
}

V3 random_point(Rng& rng) {
  const double x = rng.between(-4, 28), y = rng.between(-4, 28), z = rng.between(-8, 8);
  return v3(x, y, z);
}

Construction axis_wall_random(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 p = random_point(rng), q = random_point(rng), r = random_point(rng);
  Construction c{pair_of(t, p, q, r)};
  c.frame = FrameKind::axis;
  return c;
}

// Two walls at right angles, as CAD faces meet.
Construction axis_perpendicular(Rng& rng) {
  const double x = rng.between(-2, 26);
  auto wall_point = [&] {
    const double y = rng.between(-4, 28), z = rng.between(-8, 8);
    return v3(x, y, z);
  };
  const Triangle t = canonical_t1(rng);
  const V3 p = wall_point(), q = wall_point(), r = wall_point();
  Construction c{pair_of(t, p, q, r)};
  c.frame = FrameKind::axis;
  return c;
}

// ---- 14. slivers ------------------------------------------------------------------------
// A needle (right triangle with a short leg) or a cap (apex near the middle of the long edge)
// of length L and width L·2^-k: aspect ratios from about 10 up to 1e8. Eighth-weight points of
// it are dyadic, so still exact.

constexpr int kAspectExponents[] = {3, 7, 10, 13, 17, 20, 23, 27};

struct Sliver {
  Triangle t;
  int k;
};

Sliver sliver(Rng& rng) {
  const double l = 8.0 * rng.between(1, 3);
  const int k = kAspectExponents[rng.between(0, std::size(kAspectExponents) - 1)];
  const double w = std::ldexp(l, -k);
  const double apex_x = rng.sign() > 0 ? l : std::ldexp(l, -1) + rng.between(-2, 2);
  return {Triangle{{v3(0, 0, 0), v3(l, 0, 0), v3(apex_x, w, 0)}}, k};
}

Construction with_aspect(TrianglePair pair, int k) {
  Construction c{pair};
  c.labels.push_back({"aspect", power_of_two(k)});
  return c;
}

Construction sliver_pierce(Rng& rng) {
  const auto s = sliver(rng);
  const V3 y = interior_point(rng, s.t), e = upward(rng);
  return with_aspect(pair_of(s.t, y + e, y - e, y + off_plane(rng)), s.k);
}

Construction sliver_touch(Rng& rng) {
  const auto s = sliver(rng);
  const V3 y = interior_point(rng, s.t), u = upward(rng), w = upward(rng);
  return with_aspect(pair_of(s.t, y, y + u, y + w), s.k);
}

// T2 cuts the plane along X-F, just below the sliver's long edge (by an eighth of its width).
Construction sliver_graze(Rng& rng) {
  const auto s = sliver(rng);
  const double w = s.t[2].y(), l = s.t[1].x();
  const V3 x = v3(rng.between(1, int(l) - 1), -w / 8, 0);
  const double fx = rng.between(-4, 4), fy = rng.between(1, 4);
  const V3 f = v3(x.x() + fx, x.y() - fy, 0);
  const double qx = rng.between(-4, 4), qy = rng.between(-4, 4), qz = rng.between(1, 6);
  const V3 q = v3(x.x() + qx, qy, -qz);
  return with_aspect(pair_of(s.t, 2.0 * x - q, q, 2.0 * f - q), s.k);
}

// A sliver T2 inside T1: its apex is a positive combination of three interior points.
Construction sliver_in_plane(Rng& rng) {
  const Triangle t = canonical_t1(rng);
  const V3 y1 = interior_point(rng, t), y2 = interior_point(rng, t), y3 = interior_point(rng, t);
  const int k = kAspectExponents[rng.between(0, std::size(kAspectExponents) - 1)];
  const V3 mid = (y1 + y2) / 2.0;
  return with_aspect(pair_of(t, y1, y2, mid + std::ldexp(1.0, -k) * (y3 - mid)), k);
}

Construction sliver_along_edge(Rng& rng) {
  const auto s = sliver(rng);
  const V3 p = edge_point(rng, s.t, 0), q = edge_point(rng, s.t, 0), r = off_plane(rng);
  return with_aspect(pair_of(s.t, p, q, r), s.k);
}

// ---- 15. tiny-vs-huge -------------------------------------------------------------------
// T2 is 2^-k the size of T1, k from 10 to 40 (ratios 1e-3 to 1e-12), placed at a point of T1.

struct Tiny {
  Triangle t;
  double eps;
  int k;
};

Tiny tiny(Rng& rng) {
  const int k = rng.between(10, 40);
  return {canonical_t1(rng), std::ldexp(1.0, -k), k};
}

Construction with_ratio(TrianglePair pair, int k) {
  Construction c{pair};
  c.labels.push_back({"ratio", power_of_two(-k)});
  return c;
}

Construction tiny_touch(Rng& rng) {
  const auto s = tiny(rng);
  const V3 y = interior_point(rng, s.t), u = upward(rng), w = upward(rng);
  return with_ratio(pair_of(s.t, y, y + s.eps * u, y + s.eps * w), s.k);
}

Construction tiny_cross(Rng& rng) {
  const auto s = tiny(rng);
  const V3 y = interior_point(rng, s.t), e = upward(rng);
  return with_ratio(pair_of(s.t, y + s.eps * e, y - s.eps * e, y + s.eps * off_plane(rng)), s.k);
}

// Hovering one tiny unit or more above the face: just missing. The heights differ, so that the
// planes are not parallel (that is the parallel family).
Construction tiny_miss(Rng& rng) {
  const auto s = tiny(rng);
  const V3 y = interior_point(rng, s.t);
  const V3 u = upward(rng, 3), w = upward(rng, 3);
  V3 higher = upward(rng, 3);
  higher.z() = u.z() + rng.between(1, 3);
  return with_ratio(pair_of(s.t, y + s.eps * u, y + s.eps * higher, y + s.eps * w), s.k);
}

Construction tiny_edge_touch(Rng& rng) {
  const auto s = tiny(rng);
  const V3 e = edge_point(rng, s.t, rng.between(0, 2));
  const V3 u = upward(rng), w = upward(rng);
  return with_ratio(pair_of(s.t, e, e + s.eps * u, e + s.eps * w), s.k);
}

// In T1's plane just across an edge: each vertex is the edge point moved directly away from
// an interior point by a tiny amount.
Construction tiny_coplanar_miss(Rng& rng) {
  const auto s = tiny(rng);
  const V3 e = edge_point(rng, s.t, rng.between(0, 2));
  auto away = [&]() -> V3 {
    const double k = rng.between(1, 3);
    return e - s.eps * k * (interior_point(rng, s.t) - e);
  };
  const V3 p = away(), q = away(), r = away();
  return with_ratio(pair_of(s.t, p, q, r), s.k);
}

// ---- 16. random -------------------------------------------------------------------------

Construction random_pair(Rng& rng) {
  auto point = [&] {
    const double x = rng.unit(), y = rng.unit();
    return v3(x, y, rng.unit());
  };
  const V3 a = point(), b = point(), c = point(), p = point(), q = point(), r = point();
  Construction out{TrianglePair{Triangle{{a, b, c}}, Triangle{{p, q, r}}}};
  out.frame = FrameKind::none;
  return out;
}

const FamilyConfig kStressConfigs[] = {
    {"near-coplanar", {"through", R::cross, near_coplanar_through}},
    {"near-coplanar", {"axis-outside", R::disjoint, near_coplanar_axis_outside}},
    {"near-coplanar", {"apart", R::disjoint, near_coplanar_apart}},
    {"near-coplanar", {"hinge", R::touch_segment, near_coplanar_hinge}},
    {"axis-aligned", {"wall-cross", R::cross, axis_wall_cross}},
    {"axis-aligned", {"wall-touch", R::touch_point, axis_wall_touch}},
    {"axis-aligned", {"wall-edge", R::touch_segment, axis_wall_edge}},
    {"axis-aligned", {"wall-random", std::nullopt, axis_wall_random}},
    {"axis-aligned", {"perpendicular", std::nullopt, axis_perpendicular}},
    {"slivers", {"pierce", R::cross, sliver_pierce}},
    {"slivers", {"touch", R::touch_point, sliver_touch}},
    {"slivers", {"graze", R::disjoint, sliver_graze}},
    {"slivers", {"in-plane", R::coplanar_overlap, sliver_in_plane}},
    {"slivers", {"along-edge", R::touch_segment, sliver_along_edge}},
    {"tiny-vs-huge", {"touch", R::touch_point, tiny_touch}},
    {"tiny-vs-huge", {"cross", R::cross, tiny_cross}},
    {"tiny-vs-huge", {"miss", R::disjoint, tiny_miss}},
    {"tiny-vs-huge", {"edge-touch", R::touch_point, tiny_edge_touch}},
    {"tiny-vs-huge", {"coplanar-miss", R::coplanar_disjoint, tiny_coplanar_miss}},
    {"random", {"cube", std::nullopt, random_pair}},
};

}  // namespace

std::span<const FamilyConfig> stress_configs() { return kStressConfigs; }

}  // namespace tritri::corpus
