// Möller 1997: its pieces, its segment, the behaviour of its snap, and its float instantiation.
// Its answers against the oracle are the conformance suite's: the published code and its
// exact-zero and segment variants are right in general position (on singular small-integer
// pairs they now and then are not: their baseline records where), the division-free variant on
// every small-integer pair.
#include "algorithms/moller97/moller97.hpp"

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"
#include "harness/testing/hand_built.hpp"
#include "harness/testing/tritri/testing.hpp"

#include <gtest/gtest.h>

TRITRI_ALGORITHM_CONFORMANCE(Moller97, "moller97", general_position)
TRITRI_ALGORITHM_CONFORMANCE(Moller97Nosnap, "moller97-nosnap", general_position)
TRITRI_ALGORITHM_CONFORMANCE(Moller97Nodiv, "moller97-nodiv", exact)
TRITRI_ALGORITHM_CONFORMANCE(Moller97Segment, "moller97-segment", general_position)

namespace tritri::moller97 {
namespace {

TEST(Moller97Pieces, PlaneDistancesAreUnnormalised) {
  const auto p = plane_of(kFloor);
  EXPECT_EQ(p.normal, Vec3<double>(0, 0, 16));  // (4,0,0) x (0,4,0)
  const auto d = distances<double, false>(p, tri({0, 0, 1}, {0, 0, -2}, {5, 5, 0}));
  EXPECT_EQ(d.d[0], 16.0);
  EXPECT_EQ(d.d[1], -32.0);
  EXPECT_EQ(d.d[2], 0.0);
}

TEST(Moller97Pieces, SnapZeroesOnlyBelowEpsilon) {
  const auto p = plane_of(kFloor);  // |N| = 16: a height h gives d = 16 h
  const auto d = distances<double, true>(p, tri({0, 0, 5e-8}, {0, 0, 1e-7}, {0, 0, 1e-6}));
  EXPECT_EQ(d.d[0], 0.0);   // 8e-7 < 1e-6
  EXPECT_EQ(d.d[1], 16e-7); // not below EPSILON
  EXPECT_EQ(d.d[2], 16e-6);
}

TEST(Moller97Pieces, LoneVertexFollowsThePublishedCaseOrder) {
  auto with = [](double a, double b, double c) {
    Distances<double> s{{a, b, c}, a * b, a * c};
    return lone_vertex(s);
  };
  EXPECT_EQ(with(1, 2, -1), 2);
  EXPECT_EQ(with(1, -2, 3), 1);
  EXPECT_EQ(with(-1, 2, 3), 0);
  EXPECT_EQ(with(0, 2, 3), 0);   // a vertex on the plane, the others on one side
  EXPECT_EQ(with(0, 2, -3), 1);  // a vertex on the plane, the others straddling
  EXPECT_EQ(with(0, 0, 3), 2);
  EXPECT_EQ(with(0, 0, 0), -1);  // coplanar
}

TEST(Moller97Pieces, CoplanarProjectionDropsTheDominantAxis) {
  EXPECT_EQ(coplanar_projection<double>({0, 0, 5}).i0, 0);
  EXPECT_EQ(coplanar_projection<double>({0, 0, 5}).i1, 1);
  EXPECT_EQ(coplanar_projection<double>({5, 1, 1}).i0, 1);
  EXPECT_EQ(coplanar_projection<double>({1, 5, 1}).i1, 2);
}

TEST(Moller97Pieces, TheEdgeTestMissesCollinearOverlap) {
  const auto p = coplanar_projection<double>({0, 0, 1});
  // crossing edges are found, endpoints included
  EXPECT_TRUE(edges_meet<double>(p, {0, 0, 0}, 4, 0, {2, -1, 0}, {2, 1, 0}));
  EXPECT_TRUE(edges_meet<double>(p, {0, 0, 0}, 4, 0, {4, 0, 0}, {5, 1, 0}));
  // collinear overlapping edges have a zero denominator and are never reported: as published
  EXPECT_FALSE(edges_meet<double>(p, {0, 0, 0}, 4, 0, {2, 0, 0}, {6, 0, 0}));
}

TEST(Moller97, SegmentVariantReturnsTheIntersection) {
  // T2 in the plane x = 1 crosses the floor along y in [0, 1]
  const TrianglePair pair{kFloor, tri({1, 1, -2}, {1, 1, 2}, {1, -3, 1})};
  const SegmentAnswer s = segment<double, true>(pair);
  ASSERT_EQ(s.kind, SegmentKind::segment);
  const Vec3<double> lo = s.p.y() < s.q.y() ? s.p : s.q, hi = s.p.y() < s.q.y() ? s.q : s.p;
  EXPECT_NEAR((lo - Vec3<double>(1, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((hi - Vec3<double>(1, 1, 0)).norm(), 0.0, 1e-15);
  EXPECT_EQ((segment<double, true>({kFloor, tri({0, 0, 5}, {1, 0, 5}, {0, 1, 6})}).kind), SegmentKind::empty);
  EXPECT_EQ((segment<double, true>({kFloor, tri({1, 1, 0}, {5, 1, 0}, {1, 5, 0})}).kind), SegmentKind::coplanar);
}

// The snap can put T2 in T1's plane without putting T1 in T2's: |N1| and |N2| differ, and so do
// the two sets of unnormalised distances. The published code then takes its coplanar branch
// from the second interval computation; an early port read past its arrays instead (found by
// UndefinedBehaviorSanitizer on the perturbed corpus).
TEST(Moller97, SnapOnOneSideOnlyTakesTheCoplanarBranch) {
  // N1 = (0, 0, 1e4): T2's heights of at most 5e-11 give |d| <= 5e-7 < EPSILON, all snapped.
  // N2 = (0, -5e-8, 1e6): T1's vertex (0, 100, 0) is at d = -5e-6, beyond EPSILON: not snapped.
  const Triangle t1 = tri({0, 0, 0}, {100, 0, 0}, {0, 100, 0});
  const Triangle t2 = tri({0, 0, 0}, {1000, 0, 0}, {0, 1000, 5e-11});
  const TrianglePair pair{t1, t2};
  tritri::moller97::Setup<double, true> s;
  ASSERT_TRUE((setup<double, true>(pair, s)));
  EXPECT_GE(s.lone1, 0);
  EXPECT_LT(s.lone2, 0);
  EXPECT_TRUE(s.coplanar());
  // coplanar branch: the projections overlap, so the snapped test says they meet
  EXPECT_TRUE((overlap<double, true>(pair)));
  EXPECT_TRUE((overlap_division_free<double, true>(pair)));
  EXPECT_EQ((segment<double, true>(pair).kind), SegmentKind::coplanar);
}

// The published snap is absolute: a small triangle hovering 1e-8 above the floor is snapped
// into it and reported as touching, while the exact-zero variant keeps it apart.
TEST(Moller97, AbsoluteSnapMakesNearbySmallTrianglesTouch) {
  const TrianglePair hovering{kFloor, tri({1, 1, 1e-8}, {1.001, 1, 1e-8}, {1, 1.001, 1e-8})};
  ASSERT_FALSE(oracle_label(hovering).overlap);
  EXPECT_TRUE((overlap<double, true>(hovering)));
  EXPECT_FALSE((overlap<double, false>(hovering)));
}

// Every built-in case, singular ones included, not only the general ones the suite holds a float
// instantiation to: their small integers are exact in float.
TEST(Moller97, FloatInstantiationAnswersEveryBuiltinCase) {
  for (const auto& c : builtin_cases()) {
    const bool truth = dimension_of(*parse_relation(*c.label("expect"))) != Dimension::none;
    EXPECT_EQ((overlap<float, true>(cast<float>(c.pair))), truth) << c.name;  // small integers: exact in float
  }
}

}  // namespace
}  // namespace tritri::moller97
