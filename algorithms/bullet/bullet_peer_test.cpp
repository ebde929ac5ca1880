// Bullet's GImpact tests on a handful of exact pairs, asserting what the float build does —
// including its margin and its one-sidedness, which make answers wrong for the closed sets.
#include "algorithms/bullet/bullet_peer.hpp"
#include "harness/testing/hand_built.hpp"

#include <gtest/gtest.h>

namespace tritri::bullet_peer {
namespace {

TEST(Bullet, TheLinkedBuildIsFloat) { EXPECT_EQ(scalar_bytes(), 4); }

TEST(Bullet, AnswersTheBasicRelations) {
  for (auto* f : {&gimpact_default, &gimpact_margin0, &gim_triangle_default}) {
    EXPECT_TRUE(f({kFloor, tri({1, 1, -2}, {1, 1, 2}, {1, -3, 1})}));   // cross
    EXPECT_FALSE(f({kFloor, tri({0, 0, 2}, {4, 0, 3}, {0, 4, 5})}));    // above
    EXPECT_TRUE(f({kFloor, tri({1, 1, 0}, {5, 1, 0}, {1, 5, 0})}));     // coplanar overlap
    EXPECT_FALSE(f({kFloor, tri({5, 5, 0}, {8, 5, 0}, {5, 8, 0})}));    // coplanar apart
    EXPECT_TRUE(f({kFloor, tri({0, 0, 0}, {-1, -2, 3}, {-2, -1, 3})}));  // shared vertex
    EXPECT_TRUE(f({kFloor, tri({1, 1, 0}, {1, 2, 3}, {2, 1, 3})}));     // vertex on face
  }
}

TEST(Bullet, TheMarginJoinsAGapOf1em3) {
  const TrianglePair gap{kFloor, tri({1, 1, 1e-3}, {1, 2, 3}, {2, 1, 3})};
  EXPECT_TRUE(gimpact_default(gap));       // 0.001 < 0.02
  EXPECT_FALSE(gimpact_margin0(gap));
  EXPECT_TRUE(gim_triangle_default(gap));  // 0.001 < 0.2
}

TEST(Bullet, ATriangleBehindThePlaneCountsWithOneOrientation) {
  // Parallel, one unit below the floor: apart, but "penetrating" once b's normal is reversed.
  const Triangle below = tri({0, 0, -1}, {4, 0, -1}, {0, 4, -1});
  EXPECT_FALSE(gimpact_default({kFloor, below}));
  EXPECT_TRUE(gimpact_default({kFloor, reversed(below)}));
  EXPECT_TRUE(gimpact_margin0({kFloor, reversed(below)}));
  EXPECT_FALSE(gim_triangle_default({kFloor, reversed(below)}));  // orients planes towards the other
}

TEST(Bullet, ZeroAreaGivesANaNPlaneAndNoContactInGImpact) {
  const Triangle piercing = tri({1, 1, -1}, {1, 1, 1}, {1, 1, 3});
  EXPECT_FALSE(gimpact_default({kFloor, piercing}));
  EXPECT_FALSE(gimpact_default({piercing, kFloor}));
  EXPECT_TRUE(gim_triangle_default({kFloor, piercing}));
}

}  // namespace
}  // namespace tritri::bullet_peer
