// The brute-force baseline: its segment-vs-triangle test, how it handles edges in the other
// plane, and its coplanar branch. Its answers against the oracle are the conformance suite's: on
// small integers its determinants are exact, so it is right there, singular pairs included.
#include "algorithms/brute/brute.hpp"

#include "cases/oracle/oracle.hpp"
#include "harness/testing/hand_built.hpp"
#include "harness/testing/tritri/testing.hpp"

#include <gtest/gtest.h>

TRITRI_ALGORITHM_CONFORMANCE(Brute, "brute", exact)

namespace tritri::brute {
namespace {

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

}  // namespace
}  // namespace tritri::brute
