// Shen–Heng–Tang 2003: its signed distances, its tolerance, and its answers in general position.
#include "algorithms/shen03/shen03.hpp"

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"
#include "tritri/counting.hpp"

#include "harness/testing/counting_pairs.hpp"

#include <gtest/gtest.h>

#include <random>

namespace tritri::shen03 {
namespace {

Triangle tri(Vec3<double> a, Vec3<double> b, Vec3<double> c) { return {{a, b, c}}; }
const Triangle kFloor = tri({0, 0, 0}, {4, 0, 0}, {0, 4, 0});

std::vector<Case> builtin_cases() { return read_case_file(std::string(TRITRI_SOURCE_DIR) + "/cases/builtin.cases"); }

TEST(Shen03Pieces, VertexPlaneDistancesAreLengths) {
  double d[3];
  int s[3];
  signed_distances(kFloor, tri({0, 0, 3}, {1, 1, -2}, {2, 2, 5e-8}), d, s);
  EXPECT_EQ(d[0], 3.0);
  EXPECT_EQ(d[1], -2.0);
  EXPECT_EQ(s[0], 1);
  EXPECT_EQ(s[1], -1);
  EXPECT_EQ(s[2], 0);  // 5e-8 is within the tolerance
}

TEST(Shen03Pieces, LineDistanceIsSignedAndALength) {
  // the x axis, and the line through (0,0,2) along y: 2 apart
  const Vec3<double> a(0, 0, 0), b(1, 0, 0);
  EXPECT_DOUBLE_EQ(line_distance<double>(a, b, {0, 0, 2}, {0, 5, 2}), -2.0);
  EXPECT_DOUBLE_EQ(line_distance<double>(a, b, {0, 5, 2}, {0, 0, 2}), 2.0);
  EXPECT_EQ(line_distance<double>(a, b, {3, -1, 0}, {3, 1, 0}), 0.0);  // they meet
  // the sign is Guigue–Devillers' orientation [a,b,c,d]
  EXPECT_EQ(guigue03::FloatPredicates<double>::orient3d(a, b, {0, 0, 2}, {0, 5, 2}), -1);
  EXPECT_EQ(guigue03::FloatPredicates<double>::orient3d(a, b, {0, 5, 2}, {0, 0, 2}), 1);
}

TEST(Shen03Pieces, ToleranceIsAbsoluteAndBelowItCountsAsZero) {
  EXPECT_EQ(tolerant_sign(1e-7), 0);
  EXPECT_EQ(tolerant_sign(-1e-7), 0);
  EXPECT_EQ(tolerant_sign(1.5e-7), 1);
  EXPECT_EQ(tolerant_sign(-1.5e-7), -1);
}

TEST(Shen03, GeneralBuiltinCasesAgreeWithTheOracle) {
  for (const auto& c : builtin_cases()) {
    if (c.family() != "general") continue;
    const bool truth = oracle_label(c.pair).overlap;
    EXPECT_EQ(overlap(c.pair), truth) << c.name;
    EXPECT_EQ(overlap(swapped(c.pair)), truth) << c.name << " (swapped)";
  }
}

TEST(Shen03, RandomGeneralPositionPairsAgreeWithTheOracle) {
  std::mt19937 rng(2003);
  std::uniform_real_distribution<double> coord(-1, 1);
  int checked = 0, overlapping = 0;
  for (int n = 0; n < 3000; ++n) {
    TrianglePair p;
    for (auto* t : {&p.t1, &p.t2})
      for (int i = 0; i < 3; ++i) (*t)[i] = Vec3<double>(coord(rng), coord(rng), coord(rng));
    const OracleRecord truth = oracle_label(p);
    if (truth.relation != Relation::disjoint && truth.relation != Relation::cross) continue;
    if (!truth.overlap && truth.separation < 1e-5) continue;  // well clear of the tolerance
    ++checked;
    overlapping += truth.overlap;
    ASSERT_EQ(overlap(p), truth.overlap) << format_case({"r", p, {}, "", 0}, NumberStyle::hex);
    ASSERT_EQ(overlap(swapped(p)), truth.overlap);
  }
  EXPECT_GT(checked, 2500);
  EXPECT_GT(overlapping, 100);
}

TEST(Shen03, SmallIntegerPairsIncludingSingularOnesAgreeWithTheOracle) {
  // Exact distances of 0 or ≥ 1e-3 on small integers: the tolerance never decides, so the
  // test answers as Guigue–Devillers does, which is exact there.
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(-3, 3);
  for (int n = 0; n < 3000; ++n) {
    TrianglePair p;
    for (auto* t : {&p.t1, &p.t2})
      for (int i = 0; i < 3; ++i) (*t)[i] = Vec3<double>(coord(rng), coord(rng), coord(rng));
    if (has_degenerate_triangle(p)) continue;
    ASSERT_EQ(overlap(p), oracle_label(p).overlap) << format_case({"r", p, {}, "", 0}, NumberStyle::g17);
  }
}

TEST(Shen03, NearMissesWithinTheToleranceCountAsTouching) {
  auto hovering = [](double h) { return TrianglePair{kFloor, tri({1, 1, h}, {1, 1, 3}, {3, 2, 3})}; };
  EXPECT_TRUE(overlap(hovering(5e-8)));   // apart by 5e-8: reported overlapping (by design)
  EXPECT_FALSE(overlap(hovering(5e-7)));  // apart by 5e-7: rejected
  EXPECT_TRUE(overlap(hovering(0)));
  // a near-coplanar pair within the tolerance takes the coplanar branch
  EXPECT_TRUE(overlap(TrianglePair{kFloor, tri({1, 1, 5e-8}, {5, 1, 5e-8}, {1, 5, 5e-8})}));
  EXPECT_FALSE(overlap(TrianglePair{kFloor, tri({1, 1, 5e-6}, {5, 1, 5e-6}, {1, 5, 5e-6})}));
}

// ---- the counting instantiation (tritri bench's operation counts) ----

// Counted answers exactly as double does (test_support/counting_pairs.hpp says why).
TEST(Shen03Counted, GivesTheDoubleAnswers) {
  test_support::expect_counted_matches_double(30, [](const auto& p) {
    using T = test_support::scalar_of<decltype(p)>;
    return std::tuple{overlap<T>(p)};
  });
}

}  // namespace
}  // namespace tritri::shen03
