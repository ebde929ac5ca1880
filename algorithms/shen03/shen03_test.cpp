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

// The published distances are unnormalised: N·X + d with |N| = twice the area, so a height h
// above kFloor (|N| = 16) gives 16 h; the snap to 0 is on that value, not on h.
TEST(Shen03Pieces, PlaneDistancesAreUnnormalisedAndSnappedBelowTheTolerance) {
  const Vec3<double> a(0, 0, 0), b(4, 0, 0), c(0, 4, 0);
  const auto plane = detail::plane_through(a.data(), b.data(), c.data());
  const Vec3<double> up(0, 0, 3), down(1, 1, -2), close(2, 2, 5e-9), not_close(2, 2, 1e-8);
  EXPECT_EQ(detail::height(plane, up.data()), 48.0);
  EXPECT_EQ(detail::height(plane, down.data()), -32.0);
  EXPECT_EQ(detail::height(plane, close.data()), 0.0);       // 8e-8 < 1e-7
  EXPECT_EQ(detail::height(plane, not_close.data()), 16e-8);  // not below the tolerance
}

TEST(Shen03Pieces, LineLineValueIsATripleProduct) {
  // the x axis, and the line through (0,0,2) along y (5 long): ((1,0,0)×(0,5,0))·(0,0,2) = 10
  const Vec3<double> a0(0, 0, 0), a1(1, 0, 0), b0(0, 0, 2), b1(0, 5, 2);
  const double w[3] = {0, 0, 2};
  EXPECT_EQ(detail::line_line(a1.data(), a0.data(), b1.data(), b0.data(), w), 10.0);
  EXPECT_EQ(detail::line_line(a1.data(), a0.data(), b0.data(), b1.data(), w), -10.0);
}

TEST(Shen03Pieces, AloneIsThePublishedSignTest) {
  EXPECT_TRUE(detail::alone(1.0, 2.0, -1.0));
  EXPECT_TRUE(detail::alone(0.0, 2.0, -1.0));   // a zero sides with the pair
  EXPECT_TRUE(detail::alone(1.0, 2.0, 0.0));    // a zero can be the lone one
  EXPECT_FALSE(detail::alone(0.0, 0.0, 0.0));
  EXPECT_FALSE(detail::alone(1.0, -2.0, 3.0));
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

// The published tolerance is on N·X + d, unnormalised: kFloor's |N| is 16, so a height below
// 1e-7 / 16 = 6.25e-9 counts as 0 (and would be 4 times larger for a floor half the size).
TEST(Shen03, NearMissesWithinTheToleranceCountAsTouching) {
  auto hovering = [](double h) { return TrianglePair{kFloor, tri({1, 1, h}, {1, 1, 3}, {3, 2, 3})}; };
  EXPECT_TRUE(overlap(hovering(5e-9)));   // apart by 5e-9: 16 h = 8e-8, reported touching
  EXPECT_FALSE(overlap(hovering(5e-8)));  // apart by 5e-8: 16 h = 8e-7, rejected
  EXPECT_TRUE(overlap(hovering(0)));
  // a near-coplanar pair within the tolerance takes the coplanar branch
  EXPECT_TRUE(overlap(TrianglePair{kFloor, tri({1, 1, 5e-9}, {5, 1, 5e-9}, {1, 5, 5e-9})}));
  EXPECT_FALSE(overlap(TrianglePair{kFloor, tri({1, 1, 5e-8}, {5, 1, 5e-8}, {1, 5, 5e-8})}));
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
