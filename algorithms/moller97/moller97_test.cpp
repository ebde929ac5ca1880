// Möller 1997: its pieces (plane distances, snap, the case order, the coplanar edge test), its
// segment, the behaviour of its snap, and its float instantiation.
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
TRITRI_ALGORITHM_CONFORMANCE(Moller97Lanes, "moller97-lanes", general_position)  // the port on lanes: algorithms/lanes

namespace tritri::moller97 {
namespace {

using detail::heights;
using detail::plane_through;

detail::Plane<double> floor_plane() { return plane_through(kFloor[0].data(), kFloor[1].data(), kFloor[2].data()); }

TEST(Moller97Pieces, PlaneDistancesAreUnnormalised) {
  const auto p = floor_plane();
  EXPECT_EQ(p.n[0], 0.0);
  EXPECT_EQ(p.n[1], 0.0);
  EXPECT_EQ(p.n[2], 16.0);  // (4,0,0) x (0,4,0)
  EXPECT_EQ(p.d, 0.0);
  const Triangle t = tri({0, 0, 1}, {0, 0, -2}, {5, 5, 0});
  const auto d = heights<double, false>(p, t[0].data(), t[1].data(), t[2].data());
  EXPECT_EQ(d.d[0], 16.0);
  EXPECT_EQ(d.d[1], -32.0);
  EXPECT_EQ(d.d[2], 0.0);
  EXPECT_EQ(d.d0d1, -512.0);  // the products the published code decides with
  EXPECT_EQ(d.d0d2, 0.0);
}

TEST(Moller97Pieces, SnapZeroesOnlyBelowEpsilon) {
  const auto p = floor_plane();  // |N| = 16: a height h gives d = 16 h
  const Triangle t = tri({0, 0, 5e-8}, {0, 0, 1e-7}, {0, 0, 1e-6});
  const auto snapped = heights<double, true>(p, t[0].data(), t[1].data(), t[2].data());
  EXPECT_EQ(snapped.d[0], 0.0);    // 8e-7 < 1e-6
  EXPECT_EQ(snapped.d[1], 16e-7);  // not below EPSILON
  EXPECT_EQ(snapped.d[2], 16e-6);
  const auto exact = heights<double, false>(p, t[0].data(), t[1].data(), t[2].data());
  EXPECT_EQ(exact.d[0], 8e-7);  // the exact-zero variant keeps it
}

// The order of the published tests decides which vertex is the lone one when distances are
// zero, and with it the rounding and which end of the interval comes first.
TEST(Moller97Pieces, LoneVertexFollowsThePublishedCaseOrder) {
  auto with = [](double a, double b, double c) {
    const detail::Heights<double> h{{a, b, c}, a * b, a * c};
    int lone = -1, partners = -1;
    const bool found = detail::with_lone_vertex(h, [&]<int K, int A, int B>(detail::Lone<K, A, B>) {
      lone = K;
      partners = 10 * A + B;
    });
    EXPECT_EQ(found, lone >= 0);
    EXPECT_TRUE(lone < 0 || partners == (lone == 0 ? 12 : lone == 1 ? 2 : 1)) << partners;
    return lone;
  };
  EXPECT_EQ(with(1, 2, -1), 2);
  EXPECT_EQ(with(1, -2, 3), 1);
  EXPECT_EQ(with(-1, 2, 3), 0);
  EXPECT_EQ(with(0, 2, 3), 0);   // a vertex on the plane, the others on one side
  EXPECT_EQ(with(0, 2, -3), 1);  // a vertex on the plane, the others straddling
  EXPECT_EQ(with(0, 0, 3), 2);
  EXPECT_EQ(with(0, 0, 0), -1);  // coplanar
}

TEST(Moller97Pieces, TheEdgeTestMissesCollinearOverlap) {
  const Vec3<double> o(0, 0, 0);
  auto meet = [&](Vec3<double> u0, Vec3<double> u1) {
    return detail::edges_cross(0, 1, 4.0, 0.0, o.data(), u0.data(), u1.data());
  };
  // crossing edges are found, endpoints included
  EXPECT_TRUE(meet({2, -1, 0}, {2, 1, 0}));
  EXPECT_TRUE(meet({4, 0, 0}, {5, 1, 0}));
  EXPECT_FALSE(meet({5, -1, 0}, {5, 1, 0}));  // beyond the edge's end
  // collinear overlapping edges have a zero denominator and are never reported: as published
  EXPECT_FALSE(meet({2, 0, 0}, {6, 0, 0}));
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
// the two sets of unnormalised distances. tri_tri_intersect and NoDivTriTriIsect then take their
// coplanar branch from the second interval computation; tri_tri_intersect_with_isectline reads
// U's interval unset there, and the port takes the coplanar branch too (README.md).
TEST(Moller97, SnapOnOneSideOnlyTakesTheCoplanarBranch) {
  // N1 = (0, 0, 1e4): T2's heights of at most 5e-11 give |d| <= 5e-7 < EPSILON, all snapped.
  // N2 = (0, -5e-8, 1e6): T1's vertex (0, 100, 0) is at d = -5e-6, beyond EPSILON: not snapped.
  const Triangle t1 = tri({0, 0, 0}, {100, 0, 0}, {0, 100, 0});
  const Triangle t2 = tri({0, 0, 0}, {1000, 0, 0}, {0, 1000, 5e-11});
  const TrianglePair pair{t1, t2};
  const auto p1 = plane_through(t1[0].data(), t1[1].data(), t1[2].data());
  const auto p2 = plane_through(t2[0].data(), t2[1].data(), t2[2].data());
  const auto du = heights<double, true>(p1, t2[0].data(), t2[1].data(), t2[2].data());
  const auto dv = heights<double, true>(p2, t1[0].data(), t1[1].data(), t1[2].data());
  EXPECT_TRUE(du.d[0] == 0.0 && du.d[1] == 0.0 && du.d[2] == 0.0);  // T2 snapped into T1's plane
  EXPECT_NE(dv.d[2], 0.0);                                         // T1 not into T2's
  // coplanar branch: the projections overlap, so the snapped test says they meet
  EXPECT_TRUE((overlap<double, true>(pair)));
  EXPECT_TRUE((overlap_division_free<double, true>(pair)));
  EXPECT_TRUE((overlap_with_segment<double, true>(pair)));
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
