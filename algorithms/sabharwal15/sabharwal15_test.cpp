// Sabharwal–Leopold 2015: the pieces of §3, the defect of the published system, and the
// corrected variant against the oracle.
#include "algorithms/sabharwal15/sabharwal15.hpp"

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"
#include "tritri/counting.hpp"

#include "harness/testing/counting_pairs.hpp"

#include <gtest/gtest.h>

#include <random>

namespace tritri::sabharwal15 {
namespace {

Triangle tri(Vec3<double> a, Vec3<double> b, Vec3<double> c) { return {{a, b, c}}; }
const Triangle kFloor = tri({0, 0, 0}, {4, 0, 0}, {0, 4, 0});

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

// In general position the corrected variant answers as the oracle does, and its segment is
// the exact one to rounding; the published one says "area" for most meeting pairs.
TEST(Sabharwal15Plane, AgreesWithTheOracleOnRandomPairs) {
  std::mt19937_64 rng(2015);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto random_triangle = [&] {
    return tri({unit(rng), unit(rng), unit(rng)}, {unit(rng), unit(rng), unit(rng)},
               {unit(rng), unit(rng), unit(rng)});
  };
  int meeting = 0, published_area = 0;
  for (int i = 0; i < 3000; ++i) {
    const TrianglePair pair{random_triangle(), random_triangle()};
    const auto truth = oracle_label(pair);
    const auto r = with_plane(pair);
    ASSERT_EQ(r.dimension, truth.dimension) << i;
    if (truth.dimension == Dimension::segment) {
      ++meeting;
      const double a = std::min((r.segment.p - truth.points[0]).norm() + (r.segment.q - truth.points[1]).norm(),
                                (r.segment.p - truth.points[1]).norm() + (r.segment.q - truth.points[0]).norm());
      ASSERT_LT(a, 1e-9) << i;
      published_area += published_relation(pair).dimension == Dimension::area;
    }
  }
  EXPECT_GT(meeting, 100);
  EXPECT_GT(published_area, meeting / 2);  // the defect, measured
}

TEST(Sabharwal15, FloatInstantiationRuns) {
  const PairT<float> pair = cast<float>(TrianglePair{kFloor, tri({1, 1, -1}, {2, 1, 1}, {1, 2, 1})});
  EXPECT_EQ(plane_relation(pair).dimension, Dimension::segment);
}

// ---- the counting instantiation (tritri bench's operation counts) ----

std::vector<Case> builtin_cases() { return read_case_file(std::string(TRITRI_SOURCE_DIR) + "/cases/builtin.cases"); }

// Counted answers exactly as double does (test_support/counting_pairs.hpp says why).


TEST(Sabharwal15Counted, GivesTheDoubleAnswers) {
  test_support::expect_counted_matches_double(15, [](const auto& p) {
    using T = test_support::scalar_of<decltype(p)>;
    return std::tuple{published_relation<T>(p), published_segment<T>(p), plane_relation<T>(p), plane_segment<T>(p)};
  });
}

}  // namespace
}  // namespace tritri::sabharwal15
