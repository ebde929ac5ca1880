// ODE's trimesh–trimesh collider on a handful of exact pairs, asserting what it does —
// including its orientation-dependent contact and its order-dependent degenerate answer.
#include "algorithms/ode/ode_peer.hpp"
#include "harness/testing/hand_built.hpp"

#include <gtest/gtest.h>

namespace tritri::ode_peer {
namespace {

TEST(Ode, AnswersTheBasicRelationsBothWays) {
  for (auto* f : {&overlap, &overlap_rebuild}) {
    EXPECT_TRUE(f({kFloor, tri({1, 1, -2}, {1, 1, 2}, {1, -3, 1})}));     // cross
    EXPECT_FALSE(f({kFloor, tri({0, 0, 2}, {4, 0, 3}, {0, 4, 5})}));      // above
    EXPECT_FALSE(f({kFloor, tri({0, 0, -1}, {4, 0, -1}, {0, 4, -1})}));   // parallel below
    EXPECT_TRUE(f({kFloor, tri({1, 1, 0}, {5, 1, 0}, {1, 5, 0})}));       // coplanar overlap
    EXPECT_FALSE(f({kFloor, tri({5, 5, 0}, {8, 5, 0}, {5, 8, 0})}));      // coplanar apart
    EXPECT_TRUE(f({kFloor, tri({0, 0, 0}, {-1, -2, 3}, {-2, -1, 3})}));   // shared vertex
    EXPECT_TRUE(f({kFloor, tri({0, 0, 0}, {4, 0, 0}, {1, -1, 2})}));      // hinge
  }
}

TEST(Ode, AVertexOnTheFaceCountsWithOneOrientationOnly) {
  const Triangle on_face = tri({1, 1, 0}, {1, 2, 3}, {2, 1, 3});
  EXPECT_FALSE(overlap({kFloor, on_face}));
  EXPECT_FALSE(overlap({on_face, kFloor}));
  EXPECT_TRUE(overlap({kFloor, reversed(on_face)}));
}

TEST(Ode, ADegeneratePointOnTheFaceDependsOnArgumentOrder) {
  const Triangle point = tri({1, 1, 0}, {1, 1, 0}, {1, 1, 0});
  EXPECT_TRUE(overlap({kFloor, point}));
  EXPECT_FALSE(overlap({point, kFloor}));
}

TEST(Ode, ThePrebuiltGeomsFollowTheVertices) {
  // The same geoms answer a crossing pair, then an apart pair, then the crossing pair again.
  const TrianglePair cross{kFloor, tri({1, 1, -2}, {1, 1, 2}, {1, -3, 1})};
  const TrianglePair apart{kFloor, tri({0, 0, 2}, {4, 0, 3}, {0, 4, 5})};
  EXPECT_TRUE(overlap(cross));
  EXPECT_FALSE(overlap(apart));
  EXPECT_TRUE(overlap(cross));
}

}  // namespace
}  // namespace tritri::ode_peer
