// Open3D's test on a handful of exact pairs, asserting what the library does, including the
// answers that are wrong for the closed sets (its epsilon and its order-dependent degenerate
// handling): those are the library's behaviour, recorded so that a change shows.
#include "algorithms/open3d/open3d_peer.hpp"
#include "harness/testing/hand_built.hpp"

#include <gtest/gtest.h>

namespace tritri::open3d_peer {
namespace {

TEST(Open3d, AnswersTheBasicRelations) {
  EXPECT_TRUE(overlap({kFloor, tri({1, 1, -2}, {1, 1, 2}, {1, -3, 1})}));  // cross
  EXPECT_FALSE(overlap({kFloor, tri({0, 0, 2}, {4, 0, 3}, {0, 4, 5})}));   // above
  EXPECT_FALSE(overlap({kFloor, tri({0, 0, -1}, {4, 0, -1}, {0, 4, -1})}));  // parallel
  EXPECT_TRUE(overlap({kFloor, tri({1, 1, 0}, {5, 1, 0}, {1, 5, 0})}));    // coplanar overlap
  EXPECT_FALSE(overlap({kFloor, tri({5, 5, 0}, {8, 5, 0}, {5, 8, 0})}));   // coplanar apart
}

TEST(Open3d, TouchingCountsAsMeeting) {
  EXPECT_TRUE(overlap({kFloor, tri({0, 0, 0}, {-1, -2, 3}, {-2, -1, 3})}));  // shared vertex
  EXPECT_TRUE(overlap({kFloor, tri({0, 0, 0}, {4, 0, 0}, {1, -1, 2})}));     // hinge
  EXPECT_TRUE(overlap({kFloor, tri({0, 0, 0}, {4, 0, 0}, {0, -4, 0})}));     // coplanar shared edge
  EXPECT_TRUE(overlap({kFloor, tri({1, 1, 0}, {1, 2, 3}, {2, 1, 3})}));      // vertex on face
}

TEST(Open3d, ItsEpsilonJoinsAGapOf1em7) {
  // 1e-7 of a layout of size 4: inside the 1e-6 snap on the rescaled pair.
  EXPECT_TRUE(overlap({kFloor, tri({1, 1, 1e-7}, {1, 2, 3}, {2, 1, 3})}));
  EXPECT_FALSE(overlap({kFloor, tri({1, 1, 1e-3}, {1, 2, 3}, {2, 1, 3})}));
}

TEST(Open3d, ADegeneratePointOnTheFaceDependsOnArgumentOrder) {
  const Triangle point = tri({1, 1, 0}, {1, 1, 0}, {1, 1, 0});
  EXPECT_TRUE(overlap({kFloor, point}));
  EXPECT_FALSE(overlap({point, kFloor}));
}

}  // namespace
}  // namespace tritri::open3d_peer
