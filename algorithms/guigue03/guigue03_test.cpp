// Guigue–Devillers 2003: the lone-vertex table, the 2-D region test, and the segment against the
// oracle's. Sign-only code on small integers is exact in double, so there both entries must agree
// with the oracle on every pair, singular or not: the conformance suite's promise "exact".
#include "algorithms/guigue03/guigue03.hpp"

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"
#include "harness/testing/hand_built.hpp"
#include "harness/testing/tritri/testing.hpp"

#include <gtest/gtest.h>

TRITRI_ALGORITHM_CONFORMANCE(Guigue03, "guigue03", exact)
TRITRI_ALGORITHM_CONFORMANCE(Guigue03Segment, "guigue03-segment", exact)

namespace tritri::guigue03 {
namespace {

TEST(Guigue03Pieces, OrientationSignConvention) {
  // [a,b,c,d] > 0 when d is on the side that (b−a)×(c−a) points to
  EXPECT_EQ(FloatPredicates<double>::orient3d(kFloor[0], kFloor[1], kFloor[2], {1, 1, 1}), 1);
  EXPECT_EQ(FloatPredicates<double>::orient3d(kFloor[0], kFloor[1], kFloor[2], {1, 1, -1}), -1);
  EXPECT_EQ(FloatPredicates<double>::orient3d(kFloor[0], kFloor[1], kFloor[2], {7, -3, 0}), 0);
  EXPECT_EQ(FloatPredicates<double>::orient2d({0, 0}, {1, 0}, {0, 1}), 1);
}

TEST(Guigue03Pieces, LoneVertexIsAloneAndItsEdgesReachThePlane) {
  // For every sign pattern but the one-sided and the all-zero ones: after the chosen flip, the
  // first vertex is ≥ 0, the other two ≤ 0, and the first is non-zero or both others are.
  for (int a = -1; a <= 1; ++a)
    for (int b = -1; b <= 1; ++b)
      for (int c = -1; c <= 1; ++c) {
        const int s[3] = {a, b, c};
        if (one_sided(s)) continue;
        const Lone l = lone_vertex(s);
        if (all_zero(s)) {
          EXPECT_EQ(l.index, -1);
          continue;
        }
        ASSERT_GE(l.index, 0);
        const int f = l.flip ? -1 : 1;
        const int first = f * s[l.index], second = f * s[(l.index + 1) % 3], third = f * s[(l.index + 2) % 3];
        SCOPED_TRACE(::testing::Message() << a << " " << b << " " << c);
        EXPECT_GE(first, 0);
        EXPECT_LE(second, 0);
        EXPECT_LE(third, 0);
        EXPECT_TRUE(first != 0 || (second != 0 && third != 0));
      }
}

TEST(Guigue03Pieces, CanonicalOrderPutsEachLoneVertexOnThePositiveSide) {
  const TrianglePair pair{tri({1, 1, -2}, {1, 1, 2}, {1, -3, 1}), kFloor};  // T1 pierces T2
  int s1[3], s2[3];
  const auto c = canonical<double>(pair, s1, s2);
  ASSERT_EQ(c.outcome, Canonical<double>::Outcome::general);
  const auto& [p1, q1, r1] = c.t1.v;
  const auto& [p2, q2, r2] = c.t2.v;
  EXPECT_GT(FloatPredicates<double>::orient3d(p2, q2, r2, p1), 0);
  EXPECT_LE(FloatPredicates<double>::orient3d(p2, q2, r2, q1), 0);
  EXPECT_LE(FloatPredicates<double>::orient3d(p2, q2, r2, r1), 0);
  EXPECT_GE(FloatPredicates<double>::orient3d(p1, q1, r1, p2), 0);
  EXPECT_LE(FloatPredicates<double>::orient3d(p1, q1, r1, q2), 0);
  EXPECT_LE(FloatPredicates<double>::orient3d(p1, q1, r1, r2), 0);
}

TEST(Guigue03Pieces, RegionTestInEachRegionKind) {
  using P = Point2<double>;
  const P a{0, 0}, b{4, 0}, c{0, 4};
  // p1 inside T2
  EXPECT_TRUE(ccw_overlap_2d<double>(P{1, 1}, P{9, 9}, P{8, 9}, a, b, c));
  // p1 in the edge region beyond (b,c): T1 reaches back across the hypotenuse, or not
  EXPECT_TRUE(ccw_overlap_2d<double>(P{4, 4}, P{6, 6}, P{1, 2}, a, b, c));
  EXPECT_FALSE(ccw_overlap_2d<double>(P{4, 4}, P{5, 4}, P{4, 5}, a, b, c));
  // p1 in the vertex region of a: T1 touches a exactly, or misses
  EXPECT_TRUE(ccw_overlap_2d<double>(P{-2, -2}, P{0, -2}, P{0, 0}, a, b, c));
  EXPECT_FALSE(ccw_overlap_2d<double>(P{-2, -2}, P{0, -3}, P{-1, -1}, a, b, c));
  // T1 contains T2 with p1 in a vertex region
  EXPECT_TRUE(ccw_overlap_2d<double>(P{-1, -1}, P{10, -1}, P{-1, 10}, a, b, c));
  // collinear edges overlapping: the case Möller's edge test misses
  EXPECT_TRUE(ccw_overlap_2d<double>(P{5, 0}, P{-1, 0}, P{7, -2}, a, b, c));
  // ... and collinear but apart
  EXPECT_FALSE(ccw_overlap_2d<double>(P{5, 0}, P{7, -2}, P{9, 0}, a, b, c));
}

// Small integers in [-3, 3]: many vertices fall on planes and edges, so every branch of the
// case analysis is exercised, and every endpoint is to within rounding of the exact one.
TEST(Guigue03, SegmentMatchesTheOraclesIntersection) {
  int compared = 0;
  for (const auto& p : testing::random_grid_pairs(8, 3000, 3)) {
    const OracleRecord truth = oracle_label(p);
    const SegmentAnswer s = segment(p);
    if (truth.coplanar) {
      EXPECT_EQ(s.kind, truth.overlap ? SegmentKind::coplanar : SegmentKind::empty);
      continue;
    }
    if (!truth.overlap) {
      EXPECT_EQ(s.kind, SegmentKind::empty);
      continue;
    }
    const std::string where = format_case({"r", p, {}, "", 0}, NumberStyle::g17);
    if (truth.dimension == Dimension::point) {
      // the two endpoints are constructed from different edges: they may differ by rounding
      ASSERT_NE(s.kind, SegmentKind::empty) << where;
      EXPECT_LT((s.p - truth.points[0]).norm(), 1e-12) << where;
      EXPECT_LT((s.q - truth.points[0]).norm(), 1e-12) << where;
    } else {
      ASSERT_EQ(s.kind, SegmentKind::segment) << where;
      const auto& a = truth.points[0];
      const auto& b = truth.points[1];
      const double same = (s.p - a).norm() + (s.q - b).norm();
      const double reversed = (s.p - b).norm() + (s.q - a).norm();
      EXPECT_LT(std::min(same, reversed), 1e-12) << where;
    }
    ++compared;
  }
  EXPECT_GT(compared, 300);
}

}  // namespace
}  // namespace tritri::guigue03
