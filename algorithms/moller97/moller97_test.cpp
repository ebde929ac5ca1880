// Möller 1997: its pieces, its segment, the behaviour of its snap, and its float instantiation.
// Its answers against the oracle are the conformance suite's: the published code and its
// exact-zero and segment variants are right in general position (on singular small-integer
// pairs they now and then are not: their baseline records where), the division-free variant on
// every small-integer pair.
#include "algorithms/moller97/moller97.hpp"

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"
#include "harness/testing/hand_built.hpp"
#include "harness/testing/tritri/testing.hpp"

#include <gtest/gtest.h>

TRITRI_ALGORITHM_CONFORMANCE(Moller97, "moller97", general_position)
TRITRI_ALGORITHM_CONFORMANCE(Moller97Nosnap, "moller97-nosnap", general_position)
TRITRI_ALGORITHM_CONFORMANCE(Moller97Nodiv, "moller97-nodiv", exact)
TRITRI_ALGORITHM_CONFORMANCE(Moller97Segment, "moller97-segment", general_position)

namespace tritri::moller97 {
namespace {

TEST(Moller97, SegmentVariantReturnsTheIntersection) {
  // T2 in the plane x = 1 crosses the floor along y in [0, 1]
  const TrianglePair pair{kFloor, tri({1, 1, -2}, {1, 1, 2}, {1, -3, 1})};
  const SegmentAnswer s = segment<double, true>(pair);
  ASSERT_EQ(s.kind, SegmentKind::segment);
  const Vec3<double> lo = s.p.y() < s.q.y() ? s.p : s.q, hi = s.p.y() < s.q.y() ? s.q : s.p;
  EXPECT_NEAR((lo - Vec3<double>(1, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((hi - Vec3<double>(1, 1, 0)).norm(), 0.0, 1e-15);
  EXPECT_EQ((segment<double, true>({kFloor, tri({0, 0, 5}, {1, 0, 5}, {0, 1, 6})}).kind), SegmentKind::empty);
  EXPECT_EQ((segment<double, true>({kFloor, tri({1, 1, 0}, {5, 1, 0}, {1, 5, 0})}).kind), SegmentKind::coplanar);
}

// The published snap is absolute: a small triangle hovering 1e-8 above the floor is snapped
// into it and reported as touching, while the exact-zero variant keeps it apart.
TEST(Moller97, AbsoluteSnapMakesNearbySmallTrianglesTouch) {
  const TrianglePair hovering{kFloor, tri({1, 1, 1e-8}, {1.001, 1, 1e-8}, {1, 1.001, 1e-8})};
  ASSERT_FALSE(oracle_label(hovering).overlap);
  EXPECT_TRUE((overlap<double, true>(hovering)));
  EXPECT_FALSE((overlap<double, false>(hovering)));
}

// Every built-in case, singular ones included, not only the general ones the suite holds a float
// instantiation to: their small integers are exact in float.
TEST(Moller97, FloatInstantiationAnswersEveryBuiltinCase) {
  for (const auto& c : builtin_cases()) {
    const bool truth = dimension_of(*parse_relation(*c.label("expect"))) != Dimension::none;
    EXPECT_EQ((overlap<float, true>(cast<float>(c.pair))), truth) << c.name;  // small integers: exact in float
  }
}

}  // namespace
}  // namespace tritri::moller97
