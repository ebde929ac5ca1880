// Shen–Heng–Tang 2003: its signed distances, its line–line value, its rotation and its tolerance.
// Its answers against the oracle are the conformance suite's: on small integers, distances are
// exactly 0 or at least 1e-3, so the tolerance never decides and the test answers as
// Guigue–Devillers does, exact there, singular pairs included.
#include "algorithms/shen03/shen03.hpp"

#include "harness/testing/hand_built.hpp"
#include "harness/testing/tritri/testing.hpp"

#include <gtest/gtest.h>

TRITRI_ALGORITHM_CONFORMANCE(Shen03, "shen03", exact)

namespace tritri::shen03 {
namespace {

// The published distances are unnormalised: N·X + d with |N| = twice the area, so a height h
// above kFloor (|N| = 16) gives 16 h; the snap to 0 is on that value, not on h.
TEST(Shen03Pieces, PlaneDistancesAreUnnormalisedAndSnappedBelowTheTolerance) {
  const auto plane = detail::plane_through(kFloor[0].data(), kFloor[1].data(), kFloor[2].data());
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
  EXPECT_TRUE(detail::alone(0.0, 2.0, -1.0));  // a zero sides with the pair
  EXPECT_TRUE(detail::alone(1.0, 2.0, 0.0));   // a zero can be the lone one
  EXPECT_FALSE(detail::alone(0.0, 0.0, 0.0));
  EXPECT_FALSE(detail::alone(1.0, -2.0, 3.0));
}

// The three "alone" tests are tried in the published order, and each rotation keeps the cyclic
// order of the vertices; when none passes (all distances zero) the published code goes on with
// unset pointers, and the port reports that instead.
TEST(Shen03Pieces, RotationPutsTheLoneVertexFirstInThePublishedOrder) {
  const double x0[3] = {0, 0, 0}, x1[3] = {1, 0, 0}, x2[3] = {0, 1, 0};
  auto first = [&](double d0, double d1, double d2) {
    detail::Rotated<double> r{};
    if (!detail::rotate(x0, x1, x2, d0, d1, d2, r)) return -1;
    const double* order[3] = {r.x0, r.x1, r.x2};
    const double* all[3] = {x0, x1, x2};
    const int k = r.x0 == x0 ? 0 : r.x0 == x1 ? 1 : 2;
    for (int i = 0; i < 3; ++i) EXPECT_EQ(order[i], all[(k + i) % 3]);
    const double d[3] = {d0, d1, d2};
    EXPECT_EQ(r.d0, d[k]);
    EXPECT_EQ(r.d1, d[(k + 1) % 3]);
    return k;
  };
  EXPECT_EQ(first(-1, 1, 1), 0);
  EXPECT_EQ(first(1, -1, 1), 1);
  EXPECT_EQ(first(1, 1, -1), 2);
  EXPECT_EQ(first(0, 1, 1), 0);    // the zero one is alone: tried first, it passes
  EXPECT_EQ(first(0, 0, 1), 2);    // (d1, d2, d0) = (0, 1, 0) and (d2, d0, d1) = (1, 0, 0) fail
  EXPECT_EQ(first(0, 0, 0), -1);   // coplanar: no rotation
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

}  // namespace
}  // namespace tritri::shen03
