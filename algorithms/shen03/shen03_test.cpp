// Shen–Heng–Tang 2003: its signed distances and its tolerance. Its answers against the oracle are
// the conformance suite's: on small integers, distances are exactly 0 or at least 1e-3, so the
// tolerance never decides and the test answers as Guigue–Devillers does, exact there, singular
// pairs included.
#include "algorithms/shen03/shen03.hpp"

#include "harness/testing/hand_built.hpp"
#include "harness/testing/tritri/testing.hpp"

#include <gtest/gtest.h>

TRITRI_ALGORITHM_CONFORMANCE(Shen03, "shen03", exact)

namespace tritri::shen03 {
namespace {


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

}  // namespace
}  // namespace tritri::shen03
