// The brute-force baseline: its segment-vs-triangle test, its answers in general position, how it
// handles edges in the other plane, and its coplanar branch.
#include "algorithms/brute/brute.hpp"

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"
#include "tritri/counting.hpp"

#include "harness/testing/counting_pairs.hpp"

#include <gtest/gtest.h>

#include <random>

namespace tritri::brute {
namespace {

Triangle tri(Vec3<double> a, Vec3<double> b, Vec3<double> c) { return {{a, b, c}}; }
const Triangle kFloor = tri({0, 0, 0}, {4, 0, 0}, {0, 4, 0});

std::vector<Case> builtin_cases() { return read_case_file(std::string(TRITRI_SOURCE_DIR) + "/cases/builtin.cases"); }

TEST(BrutePieces, SegmentTestIsClosedAtBothEnds) {
  EXPECT_TRUE(segment_hits_triangle<double>({1, 1, -1}, {1, 1, 1}, kFloor).hit);   // through the face
  EXPECT_TRUE(segment_hits_triangle<double>({1, 1, 0}, {1, 1, 1}, kFloor).hit);    // endpoint on the face
  EXPECT_TRUE(segment_hits_triangle<double>({1, 1, 1}, {1, 1, 0}, kFloor).hit);    // ... either endpoint
  EXPECT_TRUE(segment_hits_triangle<double>({2, 2, -1}, {2, 2, 1}, kFloor).hit);   // through the hypotenuse
  EXPECT_TRUE(segment_hits_triangle<double>({0, 0, -1}, {0, 0, 1}, kFloor).hit);   // through a vertex
  EXPECT_FALSE(segment_hits_triangle<double>({1, 1, 0.5}, {1, 1, 1}, kFloor).hit); // stops short
  EXPECT_FALSE(segment_hits_triangle<double>({3, 3, -1}, {3, 3, 1}, kFloor).hit); // misses the triangle
}

TEST(BrutePieces, EdgesParallelToThePlaneAreSkipped) {
  const EdgeResult above = segment_hits_triangle<double>({0, 0, 1}, {1, 1, 1}, kFloor);
  EXPECT_FALSE(above.hit);
  EXPECT_TRUE(above.parallel);
  const EdgeResult inside = segment_hits_triangle<double>({1, 1, 0}, {2, 1, 0}, kFloor);  // in the face
  EXPECT_FALSE(inside.hit);
  EXPECT_TRUE(inside.parallel);
}

TEST(Brute, GeneralBuiltinCasesAgreeWithTheOracle) {
  for (const auto& c : builtin_cases()) {
    if (c.family() != "general") continue;
    const bool truth = oracle_label(c.pair).overlap;
    EXPECT_EQ(overlap(c.pair), truth) << c.name;
    EXPECT_EQ(overlap(swapped(c.pair)), truth) << c.name << " (swapped)";
  }
}

TEST(Brute, RandomGeneralPositionPairsAgreeWithTheOracle) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> coord(-1, 1);
  int checked = 0, overlapping = 0;
  for (int n = 0; n < 3000; ++n) {
    TrianglePair p;
    for (auto* t : {&p.t1, &p.t2})
      for (int i = 0; i < 3; ++i) (*t)[i] = Vec3<double>(coord(rng), coord(rng), coord(rng));
    const OracleRecord truth = oracle_label(p);
    if (truth.relation != Relation::disjoint && truth.relation != Relation::cross) continue;
    ++checked;
    overlapping += truth.overlap;
    ASSERT_EQ(overlap(p), truth.overlap) << format_case({"r", p, {}, "", 0}, NumberStyle::hex);
  }
  EXPECT_GT(checked, 2900);
  EXPECT_GT(overlapping, 100);
}

TEST(Brute, AnEdgeInThePlaneIsFoundThroughItsNeighbours) {
  // T2's edge lies in T1's plane and crosses T1 with both endpoints outside it: the edge itself
  // is skipped, the two other edges meet the plane outside T1, and the hit comes from T1's
  // edges crossing T2.
  const TrianglePair p{kFloor, tri({-1, 1, 0}, {5, 1, 0}, {2, 1, 3})};
  ASSERT_TRUE(oracle_label(p).overlap);
  EXPECT_TRUE(overlap(p));
}

TEST(Brute, CoplanarBranchIsMollers) {
  EXPECT_TRUE(overlap(TrianglePair{kFloor, tri({1, 1, 0}, {5, 1, 0}, {1, 5, 0})}));
  EXPECT_FALSE(overlap(TrianglePair{kFloor, tri({5, 5, 0}, {8, 5, 0}, {5, 8, 0})}));
  EXPECT_FALSE(overlap(TrianglePair{kFloor, tri({0, 0, 1}, {4, 0, 1}, {0, 4, 1})}));  // parallel
  // collinear edges are never reported by Möller's edge test, but the non-collinear edge at the
  // end of the shared stretch touches there, so the contact is found
  const TrianglePair collinear{kFloor, tri({2, 0, 0}, {6, 0, 0}, {4, -2, 0})};
  ASSERT_TRUE(oracle_label(collinear).overlap);
  EXPECT_TRUE(overlap(collinear));
}

// ---- the counting instantiation (tritri bench's operation counts) ----

// Counted answers exactly as double does (test_support/counting_pairs.hpp says why).
TEST(BruteCounted, GivesTheDoubleAnswers) {
  test_support::expect_counted_matches_double(1, [](const auto& p) {
    using T = test_support::scalar_of<decltype(p)>;
    return std::tuple{overlap<T>(p)};
  });
}

}  // namespace
}  // namespace tritri::brute
