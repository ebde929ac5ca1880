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

TEST(Shen03, NearMissesWithinTheToleranceCountAsTouching) {
  auto hovering = [](double h) { return TrianglePair{kFloor, tri({1, 1, h}, {1, 1, 3}, {3, 2, 3})}; };
  EXPECT_TRUE(overlap(hovering(5e-8)));   // apart by 5e-8: reported overlapping (by design)
  EXPECT_FALSE(overlap(hovering(5e-7)));  // apart by 5e-7: rejected
  EXPECT_TRUE(overlap(hovering(0)));
  // a near-coplanar pair within the tolerance takes the coplanar branch
  EXPECT_TRUE(overlap(TrianglePair{kFloor, tri({1, 1, 5e-8}, {5, 1, 5e-8}, {1, 5, 5e-8})}));
  EXPECT_FALSE(overlap(TrianglePair{kFloor, tri({1, 1, 5e-6}, {5, 1, 5e-6}, {1, 5, 5e-6})}));
}

}  // namespace
}  // namespace tritri::shen03
