// Guigue–Devillers 2003: the lone-vertex table, the 2-D region test, and the two tests against the
// oracle. Sign-only code on small integers is exact in double, so there the port must agree with
// the oracle on every pair, singular or not.
#include "algorithms/guigue03/guigue03.hpp"

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"
#include "tritri/counting.hpp"

#include "harness/testing/counting_pairs.hpp"

#include <gtest/gtest.h>

#include <random>

namespace tritri::guigue03 {
namespace {

Triangle tri(Vec3<double> a, Vec3<double> b, Vec3<double> c) { return {{a, b, c}}; }
const Triangle kFloor = tri({0, 0, 0}, {4, 0, 0}, {0, 4, 0});

std::vector<Case> builtin_cases() { return read_case_file(std::string(TRITRI_SOURCE_DIR) + "/cases/builtin.cases"); }

// Random pairs of proper triangles with coordinates in [-range, range]: small ranges make many
// vertices fall on planes and edges, so every branch of the case analysis is exercised.
std::vector<TrianglePair> random_pairs(int count, int range, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(-range, range);
  std::vector<TrianglePair> pairs;
  while (static_cast<int>(pairs.size()) < count) {
    TrianglePair p;
    for (auto* t : {&p.t1, &p.t2})
      for (int i = 0; i < 3; ++i) (*t)[i] = Vec3<double>(coord(rng), coord(rng), coord(rng));
    if (!has_degenerate_triangle(p)) pairs.push_back(p);
  }
  return pairs;
}

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
        SCOPED_TRACE(testing::Message() << a << " " << b << " " << c);
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

TEST(Guigue03, BuiltinCasesAgreeWithTheOracle) {
  for (const auto& c : builtin_cases()) {
    const bool truth = oracle_label(c.pair).overlap;
    EXPECT_EQ(overlap(c.pair), truth) << c.name;
    EXPECT_EQ(overlap(swapped(c.pair)), truth) << c.name << " (swapped)";
    EXPECT_EQ(overlap_with_segment(c.pair), truth) << c.name << " (segment variant)";
  }
}

TEST(Guigue03, RandomSmallIntegerPairsAgreeWithTheOracle) {
  int singular = 0;
  for (const auto& p : random_pairs(4000, 3, 2003)) {
    const OracleRecord truth = oracle_label(p);
    if (truth.relation != Relation::disjoint && truth.relation != Relation::cross) ++singular;
    ASSERT_EQ(overlap(p), truth.overlap) << format_case({"r", p, {}, "", 0}, NumberStyle::g17);
    ASSERT_EQ(overlap(swapped(p)), truth.overlap);
  }
  EXPECT_GT(singular, 200);  // the sample really does exercise the singular cases
}

TEST(Guigue03, SegmentMatchesTheOraclesIntersection) {
  int compared = 0;
  for (const auto& p : random_pairs(3000, 3, 8)) {
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

TEST(Guigue03, FloatInstantiationAnswersTheBuiltinGeneralCases) {
  for (const auto& c : builtin_cases()) {
    if (c.family() != "general") continue;
    EXPECT_EQ(overlap(cast<float>(c.pair)), oracle_label(c.pair).overlap) << c.name;
  }
}

// ---- the counting instantiation (tritri bench's operation counts) ----

// Counted answers exactly as double does (test_support/counting_pairs.hpp says why).


TEST(Guigue03Counted, GivesTheDoubleAnswers) {
  test_support::expect_counted_matches_double(3, [](const auto& p) {
    using T = test_support::scalar_of<decltype(p)>;
    return std::tuple{overlap<T>(p), overlap_with_segment<T>(p), segment<T>(p)};
  });
}

}  // namespace
}  // namespace tritri::guigue03
