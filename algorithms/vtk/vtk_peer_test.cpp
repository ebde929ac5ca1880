// VTK's test on a handful of exact pairs, asserting what it does — including the coplanar
// pairs it declines, and the opposite-normal coplanar pairs it answers "no".
#include "algorithms/vtk/vtk_peer.hpp"
#include "harness/testing/hand_built.hpp"

#include <gtest/gtest.h>

namespace tritri::vtk_peer {
namespace {

TEST(Vtk, GivesTheSegmentOfCrossingPlanes) {
  const SegmentAnswer s = segment({kFloor, tri({1, 1, -2}, {1, 1, 2}, {1, -3, 1})});
  ASSERT_EQ(s.kind, SegmentKind::segment);
  EXPECT_EQ(s.p, Vec3<double>(1, 0, 0));
  EXPECT_EQ(s.q, Vec3<double>(1, 1, 0));
  EXPECT_EQ(overlap({kFloor, tri({0, 0, 2}, {4, 0, 3}, {0, 4, 5})}), Overlap::no);  // above
}

TEST(Vtk, TouchingCountsForCrossingPlanes) {
  EXPECT_EQ(segment({kFloor, tri({0, 0, 0}, {-1, -2, 3}, {-2, -1, 3})}).kind, SegmentKind::point);
  EXPECT_EQ(segment({kFloor, tri({0, 0, 0}, {4, 0, 0}, {1, -1, 2})}).kind, SegmentKind::segment);  // hinge
}

TEST(Vtk, DeclinesCoplanarPairsWithTheSameNormalAndMissesOppositeOnes) {
  const Triangle overlapping = tri({1, 1, 0}, {5, 1, 0}, {1, 5, 0});
  EXPECT_EQ(overlap({kFloor, overlapping}), Overlap::unsupported);
  EXPECT_EQ(segment({kFloor, overlapping}).kind, SegmentKind::coplanar);
  EXPECT_EQ(overlap({kFloor, reversed(overlapping)}), Overlap::no);
}

TEST(Vtk, ZeroAreaIsNeverIntersected) {
  EXPECT_EQ(overlap({kFloor, tri({1, 1, -1}, {1, 1, 1}, {1, 1, 3})}), Overlap::no);
}

}  // namespace
}  // namespace tritri::vtk_peer
