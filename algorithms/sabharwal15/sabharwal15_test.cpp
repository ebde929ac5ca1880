// Sabharwal–Leopold 2015: the pieces of §3, the defect of the published system, and the
// corrected variant's point and segment. Against the oracle, the conformance suite holds the
// corrected variant to general position; the published one, wrong there too, only to its own
// instantiations.
#include "algorithms/sabharwal15/sabharwal15.hpp"

#include "cases/oracle/oracle.hpp"
#include "harness/testing/hand_built.hpp"
#include "harness/testing/tritri/testing.hpp"

#include <gtest/gtest.h>

TRITRI_ALGORITHM_CONFORMANCE(Sabharwal15, "sabharwal15", none)
TRITRI_ALGORITHM_CONFORMANCE(Sabharwal15Plane, "sabharwal15-plane", general_position)

namespace tritri::sabharwal15 {
namespace {

// u, v of §3 for the point P + sS + tT, from the rows of the system.
void uv(const System<double>& sys, double s, double t, double& u, double& v) {
  v = sys.row[0].a * s + sys.row[0].b * t - sys.row[0].m;  // (a): v = γ·U + s α·U + t β·U
  u = -(sys.row[1].a * s + sys.row[1].b * t - sys.row[1].n);  // (b): u = −(γ·V + …)
}

TEST(Sabharwal15Algebra, UAndVAreCoordinatesOfTheProjectionOntoABCsPlane) {
  // PQR far above the floor: u, v of a point of PQR are those of its shadow on z = 0.
  const TrianglePair pair{kFloor, tri({1, 1, 7}, {3, 1, 9}, {1, 2, 11})};
  const auto sys = build_system(pair);
  for (double s : {0.0, 0.25, 0.5})
    for (double t : {0.0, 0.25, 0.5}) {
      const Vec3<double> x = pair.t2[0] + (pair.t2[1] - pair.t2[0]) * s + (pair.t2[2] - pair.t2[0]) * t;
      double u, v;
      uv(sys, s, t, u, v);
      EXPECT_NEAR(u, x[0] / 4, 1e-15);  // U = (4,0,0): u = x / 4, whatever x's height
      EXPECT_NEAR(v, x[1] / 4, 1e-15);
    }
  // The equation the derivation dropped is N·(AP + sS + tT) = 0: here 16·z.
  EXPECT_EQ(sys.plane0, 16 * 7.0);
  EXPECT_EQ(sys.plane_s, 16 * 2.0);
  EXPECT_EQ(sys.plane_t, 16 * 4.0);
}

TEST(Sabharwal15Pieces, ClassificationTestsTheGapAtBothEndsAndTheMiddle) {
  Solution<double> sol;
  sol.feasible = true;
  sol.s_min = 0, sol.s_max = 1;
  sol.lower[0] = {0, 0};
  sol.lower_count = 1;
  // t ≤ min(s, 1 − s): zero at both ends, positive inside: an area, not a segment
  sol.upper[0] = {0, 1};
  sol.upper[1] = {1, -1};
  sol.upper_count = 2;
  EXPECT_EQ(classify(sol), Dimension::area);
  sol.upper[0] = {0, 0};
  sol.upper_count = 1;  // t ≤ 0 = t_m: a segment along s
  EXPECT_EQ(classify(sol), Dimension::segment);
  sol.s_max = 0;  // and a single point
  EXPECT_EQ(classify(sol), Dimension::point);
  sol.feasible = false;
  EXPECT_EQ(classify(sol), Dimension::none);
}

TEST(Sabharwal15Published, StackedParallelTrianglesAreAnArea) {
  // The defect: the system sees only the shadow of PQR on ABC's plane.
  const TrianglePair stacked{kFloor, tri({0, 0, 1}, {4, 0, 1}, {0, 4, 1})};
  EXPECT_EQ(published_relation(stacked).dimension, Dimension::area);
  EXPECT_EQ(plane_relation(stacked).dimension, Dimension::none);
}

TEST(Sabharwal15Published, ACrossingPairIsAnArea) {
  // The classification is of the (s, t) solution set: every point of PQR whose shadow lies in
  // ABC. For a crossing pair that set is two-dimensional, even when the shadow is a segment.
  const TrianglePair pierce{kFloor, tri({1, 1, -2}, {1, 1, 2}, {1, -3, 1})};
  EXPECT_EQ(published_relation(pierce).dimension, Dimension::area);
  const TrianglePair tilted{kFloor, tri({1, 1, -1}, {2, 1, 1}, {1, 2, 1})};
  EXPECT_EQ(published_relation(tilted).dimension, Dimension::area);
  EXPECT_EQ(plane_relation(tilted).dimension, Dimension::segment);
  EXPECT_EQ(plane_relation(pierce).dimension, Dimension::segment);
}

TEST(Sabharwal15Published, CoplanarAnswersAreTheShadowsAndSoRight) {
  EXPECT_EQ(published_relation(TrianglePair{kFloor, tri({1, 1, 0}, {5, 1, 0}, {1, 5, 0})}).dimension,
            Dimension::area);
  EXPECT_EQ(published_relation(TrianglePair{kFloor, tri({5, 5, 0}, {8, 5, 0}, {5, 8, 0})}).dimension,
            Dimension::none);
  EXPECT_EQ(published_relation(TrianglePair{kFloor, tri({0, 0, 0}, {-4, 0, 0}, {0, -4, 0})}).dimension,
            Dimension::point);
}

// The defect, measured: the published system says "area" for most random crossing pairs.
TEST(Sabharwal15Published, MostRandomCrossingPairsAreAnArea) {
  int crossing = 0, area = 0;
  for (const TrianglePair& pair : testing::random_pairs(2015, 3000)) {
    if (oracle_label(pair).relation != Relation::cross) continue;
    ++crossing;
    area += published_relation(pair).dimension == Dimension::area;
  }
  EXPECT_GT(crossing, 100);
  EXPECT_GT(area, crossing / 2);
}

TEST(Sabharwal15Plane, TouchingAtAVertexIsAPoint) {
  const TrianglePair touch{kFloor, tri({1, 1, 0}, {1, 1, 3}, {3, 2, 3})};
  const auto r = with_plane(touch);
  EXPECT_EQ(r.dimension, Dimension::point);
  EXPECT_EQ(r.segment.p, Vec3<double>(1, 1, 0));
}

TEST(Sabharwal15Plane, TheSegmentIsTheIntersection) {
  const TrianglePair pierce{kFloor, tri({1, 1, -2}, {1, 1, 2}, {1, -3, 1})};
  const auto r = with_plane(pierce);
  ASSERT_EQ(r.segment.kind, SegmentKind::segment);
  const auto truth = oracle_label(pierce);
  ASSERT_EQ(truth.point_count, 2);
  const bool same = (r.segment.p - truth.points[0]).norm() < 1e-12 && (r.segment.q - truth.points[1]).norm() < 1e-12;
  const bool flipped = (r.segment.p - truth.points[1]).norm() < 1e-12 && (r.segment.q - truth.points[0]).norm() < 1e-12;
  EXPECT_TRUE(same || flipped) << r.segment.p.transpose() << " / " << r.segment.q.transpose();
}

}  // namespace
}  // namespace tritri::sabharwal15
