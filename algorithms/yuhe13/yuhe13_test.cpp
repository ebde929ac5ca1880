// Yu–He 2013: the frame, the V-view crossings and their duplicate rule, the x-reject, the
// Cyrus–Beck clip with its singular cases, and the nine codes. Against the oracle, the
// conformance suite holds the published code to general position, codes and segments; the
// literal reading of the printed x-reject, wrong there too, only to its own instantiations.
#include "algorithms/yuhe13/yuhe13.hpp"

#include "cases/oracle/oracle.hpp"
#include "harness/testing/hand_built.hpp"
#include "harness/testing/tritri/testing.hpp"

#include <gtest/gtest.h>

TRITRI_ALGORITHM_CONFORMANCE(YuHe13, "yuhe13", general_position)
TRITRI_ALGORITHM_CONFORMANCE(YuHe13Literal, "yuhe13-literal", none)

namespace tritri::yuhe13 {
namespace {

Relation code(const Triangle& b, const Triangle& a = kFloor) { return relation<double>(TrianglePair{a, b}).relation; }

TEST(YuHe13Frame, IsOrthonormalWithAOnTheXAxisAndAboveIt) {
  const Triangle a = tri({1, 2, 3}, {4, 6, 3}, {0, 5, 7});
  const Framed<double> f = transform(TrianglePair{a, a});
  EXPECT_NEAR(f.frame.n1.dot(f.frame.n2), 0, 1e-15);
  EXPECT_NEAR(f.frame.n3.norm(), 1, 1e-15);
  EXPECT_EQ(f.a[0], Vec3<double>(0, 0, 0));  // d_i = −n_i·A0, computed the same way
  EXPECT_NEAR(f.a[1][0], 5, 1e-14);          // |A0A1| = 5 on the x axis
  EXPECT_NEAR(f.a[1][1], 0, 1e-14);
  EXPECT_GT(f.a[2][1], 0);                   // A occupies y ≥ 0 (§3 property 1)
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(f.a[i][2], 0, 1e-14);
    EXPECT_NEAR((from_frame(f.frame, f.a[i]) - a[i]).norm(), 0, 1e-14);  // T⁻¹ undoes T
  }
}

TEST(YuHe13Crossings, ParameterIsTheZRatioOrTheZeroEndpoint) {
  double t = -1;
  EXPECT_TRUE(crossing_parameter(1.0, -3.0, t));
  EXPECT_EQ(t, 0.25);
  EXPECT_TRUE(crossing_parameter(0.0, 2.0, t));
  EXPECT_EQ(t, 0.0);
  EXPECT_TRUE(crossing_parameter(2.0, 0.0, t));
  EXPECT_EQ(t, 1.0);
  EXPECT_FALSE(crossing_parameter(2.0, 1.0, t));
}

TEST(YuHe13Crossings, TheDuplicateAtAVertexIsDropped) {
  // B0 on z = 0, B1 above, B2 below: edges B0B1 (t = 0), B1B2, B2B0 (t = 1) all cross
  const Crossings<double> c = crossings(tri({1, 1, 0}, {2, 1, 2}, {1, 2, -2}));
  ASSERT_EQ(c.count, 2);
  EXPECT_EQ(c.edge[0], 2);  // t0 = 0 replaced by the third crossing (B0 again, t = 1)
  EXPECT_EQ(c.t[0], 1.0);
  EXPECT_EQ(c.edge[1], 1);
  // B1 on the plane: the second crossing has t = 0 and is replaced
  const Crossings<double> d = crossings(tri({1, 2, -2}, {1, 1, 0}, {2, 1, 2}));
  ASSERT_EQ(d.count, 2);
  EXPECT_EQ(d.edge[0], 0);
  EXPECT_EQ(d.edge[1], 2);
}

TEST(YuHe13Crossings, AnEdgeInThePlaneFromB2ToB0IsLostByTheRule) {
  // The choice "z0 = 0 first" gives [B0 (t=0), B2 (t=1), B2 (t=0)] → [B2, B2]: documented defect
  const Crossings<double> c = crossings(tri({1, 1, 0}, {2, 1, 2}, {2, 2, 0}));
  ASSERT_EQ(c.count, 2);
  EXPECT_EQ(crossing_point(tri({1, 1, 0}, {2, 1, 2}, {2, 2, 0}), c.t[0], c.edge[0]).x, 2.0);
  EXPECT_EQ(crossing_point(tri({1, 1, 0}, {2, 1, 2}, {2, 2, 0}), c.t[1], c.edge[1]).x, 2.0);
}

TEST(YuHe13Clip, CyrusBeckAndItsSingularCases) {
  const Triangle2<double> a{{{0, 0}, {4, 0}, {0, 4}}};
  auto c = clip<double>({-1, 1}, {5, 1}, a);  // normal clip
  ASSERT_FALSE(c.empty);
  EXPECT_DOUBLE_EQ(c.t_in, 1.0 / 6);
  EXPECT_DOUBLE_EQ(c.t_out, 4.0 / 6);
  EXPECT_FALSE(c.along_edge);
  c = clip<double>({-1, 5}, {5, -1}, a);  // along the hypotenuse
  ASSERT_FALSE(c.empty);
  EXPECT_TRUE(c.along_edge);
  c = clip<double>({-1, 1}, {1, -1}, a);  // line through the vertex (0,0) without entering
  ASSERT_FALSE(c.empty);
  EXPECT_EQ(c.t_in, c.t_out);
  c = clip<double>({1, 1}, {1, 1}, a);  // a single point inside
  EXPECT_FALSE(c.empty);
  c = clip<double>({5, 5}, {5, 5}, a);  // and outside
  EXPECT_TRUE(c.empty);
  // clockwise clipping triangle (the coplanar branch clips by B too)
  const Triangle2<double> cw{{{0, 0}, {0, 4}, {4, 0}}};
  EXPECT_FALSE(clip<double>({-1, 1}, {5, 1}, cw).empty);
}

TEST(YuHe13, TheNineCodes) {
  EXPECT_EQ(code(tri({0, 0, 2}, {4, 0, 3}, {0, 4, 5})), Relation::disjoint);
  EXPECT_EQ(code(tri({1, 1, -2}, {1, 1, 2}, {1, -3, 1})), Relation::cross);
  EXPECT_EQ(code(tri({1, 1, 0}, {1, 1, 3}, {3, 2, 3})), Relation::touch_point);
  EXPECT_EQ(code(tri({0, 0, 0}, {4, 0, 0}, {1, -1, 2})), Relation::touch_segment);
  EXPECT_EQ(code(tri({1, 1, 0}, {5, 1, 0}, {1, 5, 0})), Relation::coplanar_overlap);
  EXPECT_EQ(code(tri({5, 5, 0}, {8, 5, 0}, {5, 8, 0})), Relation::coplanar_disjoint);
  EXPECT_EQ(code(tri({0, 0, 0}, {-4, 0, 0}, {0, -4, 0})), Relation::coplanar_point);
  EXPECT_EQ(code(tri({0, 0, 0}, {4, 0, 0}, {2, -3, 0})), Relation::coplanar_segment);
  EXPECT_EQ(code(tri({0, 0, 1}, {4, 0, 1}, {0, 4, 1})), Relation::parallel);
}

TEST(YuHe13, CoplanarContainmentNeedsTheViceVersa) {
  // A inside B: no edge of B meets A; A's edges clipped by B find the overlap
  EXPECT_EQ(code(tri({-4, -4, 0}, {12, -4, 0}, {-4, 12, 0})), Relation::coplanar_overlap);
}

TEST(YuHe13, XRejectAsWrittenAndAsPrinted) {
  // B crosses z = 0 along y = 1 from x = −2 to x = 2: one crossing lies left of X_L = 0
  const TrianglePair pair{kFloor, tri({-2, 1, -1}, {-2, 1, 1}, {2, 1, 0})};
  EXPECT_EQ((relation<double, false>(pair).relation), Relation::cross);
  EXPECT_EQ((relation<double, true>(pair).relation), Relation::disjoint);  // the printed formula
}

TEST(YuHe13, SegmentIsTheIntersectionInTheOriginalFrame) {
  const TrianglePair pair{tri({1, 2, 3}, {5, 2, 3}, {1, 6, 3}), tri({2, 3, 1}, {2, 3, 5}, {2, -1, 4})};
  const SegmentAnswer s = segment<double>(pair);
  ASSERT_EQ(s.kind, SegmentKind::segment);
  const auto truth = oracle_label(pair);
  ASSERT_EQ(truth.point_count, 2);
  const double e = std::min((s.p - truth.points[0]).norm() + (s.q - truth.points[1]).norm(),
                            (s.p - truth.points[1]).norm() + (s.q - truth.points[0]).norm());
  EXPECT_LT(e, 1e-12);
}

}  // namespace
}  // namespace tritri::yuhe13
