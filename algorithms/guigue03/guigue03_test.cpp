// Guigue–Devillers 2003: the lone-vertex table, the 2-D region test, and the segment against the
// oracle's. Sign-only code on small integers is exact in double, so there both entries must agree
// with the oracle on every pair, singular or not: the conformance suite's promise "exact".
#include "algorithms/guigue03/guigue03.hpp"
#include "cases/util/random.hpp"

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"
#include "harness/testing/hand_built.hpp"
#include "harness/testing/tritri/testing.hpp"

#include <gtest/gtest.h>

TRITRI_ALGORITHM_CONFORMANCE(Guigue03, "guigue03", exact)
TRITRI_ALGORITHM_CONFORMANCE(Guigue03Segment, "guigue03-segment", exact)
TRITRI_ALGORITHM_CONFORMANCE(Guigue03Lanes, "guigue03-lanes", exact)  // the port on lanes: algorithms/lanes

namespace tritri::guigue03 {
namespace {

TEST(Guigue03Pieces, OrientationSignConvention) {
  // [a,b,c,d] > 0 when d is on the side that (b−a)×(c−a) points to
  EXPECT_EQ(FloatPredicates<double>::orient3d(kFloor[0], kFloor[1], kFloor[2], {1, 1, 1}), 1);
  EXPECT_EQ(FloatPredicates<double>::orient3d(kFloor[0], kFloor[1], kFloor[2], {1, 1, -1}), -1);
  EXPECT_EQ(FloatPredicates<double>::orient3d(kFloor[0], kFloor[1], kFloor[2], {7, -3, 0}), 0);
  EXPECT_EQ(FloatPredicates<double>::orient2d({0, 0}, {1, 0}, {0, 1}), 1);
}

// Step 3's two sign tables put each triangle's lone vertex first, on the positive side of the
// other's plane, the other two on the non-positive side: the order step 4's two determinants
// rely on. Checked on small-integer pairs, where every orientation is exact and zero signs occur.
struct RecordLast {
  const double* v[6] = {};
  bool general_reached = false;
  bool rejected() { return false; }
  bool general(const double* p1, const double* q1, const double* r1, const double* p2,
               const double* q2, const double* r2) {
    general_reached = true;
    const double* w[6] = {p1, q1, r1, p2, q2, r2};
    for (int i = 0; i < 6; ++i) v[i] = w[i];
    return true;
  }
  bool coplanar(const double*, const double*, const double*, const double*, const double*,
                const double*) {
    return true;
  }
};

TEST(Guigue03Pieces, SignTablesPutEachLoneVertexOnThePositiveSide) {
  using P = FloatPredicates<double>;
  Rng rng(3);
  auto coord = [](Rng& r) { return static_cast<double>(r.between(-2, 2)); };
  int general = 0;
  for (int n = 0; n < 3000; ++n) {
    TrianglePair pair;
    for (auto* t : {&pair.t1, &pair.t2})
      for (int i = 0; i < 3; ++i) {
        const double x = coord(rng);
        const double y = coord(rng);
        const double z = coord(rng);
        (*t)[i] = Vec3<double>(x, y, z);
      }
    if (has_degenerate_triangle(pair)) continue;
    double n1[3], n2[3];
    RecordLast last;
    detail::canonical<double, P>(pair, n1, n2, last);
    if (!last.general_reached) continue;
    ++general;
    const auto& v = last.v;
    SCOPED_TRACE(format_case({"r", pair, {}, "", 0}, NumberStyle::g17));
    const double first1 = P::orient3d_value(v[3], v[4], v[5], v[0]);
    EXPECT_GE(first1, 0);
    EXPECT_LE(P::orient3d_value(v[3], v[4], v[5], v[1]), 0);
    EXPECT_LE(P::orient3d_value(v[3], v[4], v[5], v[2]), 0);
    EXPECT_GE(P::orient3d_value(v[0], v[1], v[2], v[3]), 0);
    EXPECT_LE(P::orient3d_value(v[0], v[1], v[2], v[4]), 0);
    EXPECT_LE(P::orient3d_value(v[0], v[1], v[2], v[5]), 0);
  }
  EXPECT_GT(general, 300);
}

TEST(Guigue03Pieces, RegionTestInEachRegionKind) {
  using P = FloatPredicates<double>;
  const double a[2] = {0, 0}, b[2] = {4, 0}, c[2] = {0, 4};
  auto ccw = [&](std::array<double, 2> p, std::array<double, 2> q, std::array<double, 2> r) {
    return detail::ccw_overlap_2d<double, P>(p.data(), q.data(), r.data(), a, b, c);
  };
  // p1 inside T2
  EXPECT_TRUE(ccw({1, 1}, {9, 9}, {8, 9}));
  // p1 in the edge region beyond (b,c): T1 reaches back across the hypotenuse, or not
  EXPECT_TRUE(ccw({4, 4}, {6, 6}, {1, 2}));
  EXPECT_FALSE(ccw({4, 4}, {5, 4}, {4, 5}));
  // p1 in the vertex region of a: T1 touches a exactly, or misses
  EXPECT_TRUE(ccw({-2, -2}, {0, -2}, {0, 0}));
  EXPECT_FALSE(ccw({-2, -2}, {0, -3}, {-1, -1}));
  // T1 contains T2 with p1 in a vertex region
  EXPECT_TRUE(ccw({-1, -1}, {10, -1}, {-1, 10}));
  // collinear edges overlapping: the case Möller's edge test misses
  EXPECT_TRUE(ccw({5, 0}, {-1, 0}, {7, -2}));
  // ... and collinear but apart
  EXPECT_FALSE(ccw({5, 0}, {7, -2}, {9, 0}));
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
