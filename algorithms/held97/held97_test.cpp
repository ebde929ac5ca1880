// Held 1997 (ERIT, reconstructed): its pieces, its segment, and what its length tolerance does.
// Its answers against the oracle are the conformance suite's: with the tolerance, rounding on
// small integers stays below it, so it is right there, singular pairs included; without it, in
// general position only.
#include "algorithms/held97/held97.hpp"

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"
#include "harness/testing/hand_built.hpp"
#include "harness/testing/tritri/testing.hpp"

#include <gtest/gtest.h>

TRITRI_ALGORITHM_CONFORMANCE(Held97, "held97", exact)
TRITRI_ALGORITHM_CONFORMANCE(Held97Notol, "held97-notol", general_position)

namespace tritri::held97 {
namespace {

TEST(Held97Pieces, NormalIsUnitSoDistancesAreLengths) {
  const Vec3<double> n = unit_normal(tri({0, 0, 0}, {3, 0, 0}, {0, 7, 0}));
  EXPECT_DOUBLE_EQ(n.norm(), 1.0);
  const auto s = sides<double>(n, {0, 0, 0}, tri({0, 0, 2}, {1, 1, -0.5}, {5, 5, 0}), 0.0);
  EXPECT_EQ(s.d[0], 2.0);
  EXPECT_EQ(s.d[1], -0.5);
  EXPECT_EQ(s.s[2], 0);
}

TEST(Held97Pieces, ClassificationUsesTheLengthTolerance) {
  const Vec3<double> n(0, 0, 1);
  const auto s = sides<double>(n, {0, 0, 0}, tri({0, 0, 5e-11}, {0, 0, -5e-11}, {0, 0, 2e-10}), kZero);
  EXPECT_EQ(s.s[0], 0);
  EXPECT_EQ(s.s[1], 0);
  EXPECT_EQ(s.s[2], 1);
}

TEST(Held97Pieces, CutInterpolatesStraddlingEdgesAndKeepsVerticesOnThePlane) {
  const Vec3<double> n(0, 0, 1);
  const Triangle crossing = tri({1, 1, -1}, {3, 1, 1}, {1, 3, 1});
  const auto c = cut(crossing, sides<double>(n, {0, 0, 0}, crossing, kZero));
  EXPECT_EQ(c.a, Vec3<double>(2, 1, 0));
  EXPECT_EQ(c.b, Vec3<double>(1, 2, 0));
  const Triangle touching = tri({1, 1, 0}, {3, 1, 1}, {1, 3, 1});
  const auto p = cut(touching, sides<double>(n, {0, 0, 0}, touching, kZero));
  EXPECT_EQ(p.a, Vec3<double>(1, 1, 0));
  EXPECT_EQ(p.b, p.a);
  const Triangle through_vertex = tri({1, 1, 0}, {3, 1, 1}, {3, 1, -1});
  const auto v = cut(through_vertex, sides<double>(n, {0, 0, 0}, through_vertex, kZero));
  EXPECT_EQ(v.a, Vec3<double>(1, 1, 0));
  EXPECT_EQ(v.b, Vec3<double>(3, 1, 0));
}

TEST(Held97Pieces, ProjectionDropsTheDominantAxis) {
  EXPECT_EQ(dominant_projection<double>({0.1, 0.2, -0.9}).i0, 0);
  EXPECT_EQ(dominant_projection<double>({0.1, 0.2, -0.9}).i1, 1);
  EXPECT_EQ(dominant_projection<double>({-0.9, 0.2, 0.1}).i0, 1);
  EXPECT_EQ(dominant_projection<double>({0.1, 0.9, 0.2}).i1, 2);
}

TEST(Held97Pieces, SegmentVersusTriangleIn2D) {
  const Triangle2<double> t = project(kFloor, Axes{0, 1});
  using P = Point2<double>;
  const double eps = kZero;
  EXPECT_TRUE(segment_meets(P{1, 1}, P{9, 9}, t, eps));     // endpoint inside
  EXPECT_TRUE(segment_meets(P{-1, 1}, P{9, 1}, t, eps));    // through, both endpoints outside
  EXPECT_TRUE(segment_meets(P{4, 0}, P{6, 0}, t, eps));     // touches a vertex
  EXPECT_TRUE(segment_meets(P{-2, 0}, P{6, 0}, t, eps));    // along an edge, beyond both ends
  EXPECT_FALSE(segment_meets(P{5, 0}, P{6, 0}, t, eps));    // collinear with an edge, apart
  EXPECT_FALSE(segment_meets(P{3, 3}, P{5, 1}, t, eps));    // parallel to the hypotenuse, outside
  EXPECT_TRUE(segment_meets(P{2, 2 + 5e-11}, P{2, 2 + 5e-11}, t, eps));   // a point within kZero
  EXPECT_FALSE(segment_meets(P{2, 2 + 1e-9}, P{2, 2 + 1e-9}, t, eps));    // a point beyond it
  // clockwise triangles work the same
  const Triangle2<double> cw = project(tri({0, 0, 0}, {0, 4, 0}, {4, 0, 0}), Axes{0, 1});
  EXPECT_EQ(cw.orientation, -1);
  EXPECT_TRUE(point_in(P{1, 1}, cw, eps));
  EXPECT_FALSE(point_in(P{3, 3}, cw, eps));
}

TEST(Held97, SegmentIsTheOraclesIntersection) {
  for (const auto& c : builtin_cases()) {
    const OracleRecord truth = oracle_label(c.pair);
    if (truth.coplanar || truth.dimension != Dimension::segment) continue;
    const SegmentAnswer s = segment(c.pair);
    ASSERT_EQ(s.kind, SegmentKind::segment) << c.name;
    const auto& a = truth.points[0];
    const auto& b = truth.points[1];
    const double err = std::min((s.p - a).norm() + (s.q - b).norm(), (s.p - b).norm() + (s.q - a).norm());
    // the clip keeps the tolerance's slack: each end may lie up to kZero (a projected length)
    // beyond T1's edge
    EXPECT_LT(err, 4 * kZero) << c.name;
  }
}

TEST(Held97, TheToleranceCountsNearMissesAsTouching) {
  // T2's lowest vertex hovers h above T1's face.
  auto hovering = [](double h) { return TrianglePair{kFloor, tri({1, 1, h}, {1, 1, 3}, {3, 2, 3})}; };
  EXPECT_TRUE(overlap(hovering(5e-11)));                 // within kZero: touching, a false positive
  EXPECT_FALSE((overlap<double, false>(hovering(5e-11))));  // without the tolerance: apart
  EXPECT_FALSE(overlap(hovering(2e-10)));                // beyond kZero: apart
  EXPECT_TRUE(overlap(hovering(0)));                     // real touching
  EXPECT_EQ(segment(hovering(0)).kind, SegmentKind::point);
}

TEST(Held97, CoplanarBranch) {
  EXPECT_TRUE(overlap(TrianglePair{kFloor, tri({1, 1, 0}, {5, 1, 0}, {1, 5, 0})}));
  EXPECT_FALSE(overlap(TrianglePair{kFloor, tri({5, 5, 0}, {8, 5, 0}, {5, 8, 0})}));
  EXPECT_TRUE(overlap(TrianglePair{kFloor, tri({2, 0, 0}, {6, 0, 0}, {4, -2, 0})}));  // collinear edges
  EXPECT_TRUE(overlap(TrianglePair{tri({1, 1, 0}, {2, 1, 0}, {1, 2, 0}), kFloor}));   // T1 inside T2
  EXPECT_EQ(segment(TrianglePair{kFloor, tri({1, 1, 0}, {5, 1, 0}, {1, 5, 0})}).kind, SegmentKind::coplanar);
}

}  // namespace
}  // namespace tritri::held97
