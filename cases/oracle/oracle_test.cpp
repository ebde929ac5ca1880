// The oracle agrees with every hand-built label, whatever the order of arguments and vertices;
// degenerate input is judged, not guessed.
#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace tritri {
namespace {

const std::vector<Case>& builtin() {
  static const auto cases = read_case_file(std::string(TRITRI_SOURCE_DIR) + "/cases/builtin.cases");
  return cases;
}

TEST(Oracle, BuiltinCasesCoverEveryRelationAtLeastTwice) {
  for (Relation r : kAllRelations) {
    const auto n = std::count_if(builtin().begin(), builtin().end(),
                                 [&](const Case& c) { return c.label("expect") == to_string(r); });
    EXPECT_GE(n, 2) << to_string(r);
  }
}

TEST(Oracle, MatchesEveryExpectLabelInEveryArgumentAndVertexOrder) {
  ASSERT_GE(builtin().size(), 40u);
  for (const Case& c : builtin()) {
    const auto expected = parse_relation(*c.label("expect"));
    ASSERT_TRUE(expected) << c.name;
    for (bool swap : {false, true})
      for (const auto& o1 : kVertexOrders)
        for (const auto& o2 : kVertexOrders) {
          TrianglePair p{permuted(c.pair.t1, o1), permuted(c.pair.t2, o2)};
          if (swap) p = swapped(p);
          const OracleRecord r = oracle_label(p);
          ASSERT_EQ(r.relation, *expected) << c.name << (swap ? " swapped" : "") << " orders " << o1[0]
                                           << o1[1] << o1[2] << "/" << o2[0] << o2[1] << o2[2];
          EXPECT_EQ(r.overlap, dimension_of(*expected) != Dimension::none) << c.name;
          EXPECT_EQ(r.dimension, dimension_of(*expected)) << c.name;
          EXPECT_EQ(r.coplanar, is_coplanar_relation(*expected)) << c.name;
        }
  }
}

Triangle tri(Vec3<double> a, Vec3<double> b, Vec3<double> c) { return {{a, b, c}}; }
const Triangle kFloor = tri({0, 0, 0}, {4, 0, 0}, {0, 4, 0});

TEST(Oracle, SeparationIsTheExactDistance) {
  const auto parallel = oracle_label({kFloor, tri({0, 0, 3}, {4, 0, 3}, {0, 4, 3})});
  EXPECT_EQ(parallel.relation, Relation::parallel);
  EXPECT_EQ(parallel.separation, 3.0);
  // nearest: T2's vertex (7,4,0) and its foot (3.5,0.5,0) on T1's hypotenuse x + y = 4
  const auto apart = oracle_label({kFloor, tri({7, 4, 0}, {9, 4, 0}, {7, 6, 0})});
  EXPECT_EQ(apart.relation, Relation::coplanar_disjoint);
  EXPECT_DOUBLE_EQ(apart.separation, 7.0 / std::sqrt(2.0));
  EXPECT_EQ(oracle_label({kFloor, kFloor}).separation, 0.0);
}

TEST(Oracle, SeparationOfHugeCoordinatesDoesNotOverflow) {
  const double big = 1e300;
  const auto r = oracle_label({tri({0, 0, 0}, {big, 0, 0}, {0, big, 0}),
                               tri({0, 0, big}, {big, 0, big}, {0, big, big})});
  EXPECT_EQ(r.relation, Relation::parallel);
  EXPECT_DOUBLE_EQ(r.separation, big);
}

TEST(Oracle, SeparationDoesNotDependOnVertexOrder) {
  const Triangle a = tri({0.1, 0.2, 0.3}, {1.7, 0.1, 0.2}, {0.3, 1.9, 0.7});
  const Triangle b = tri({2.1, 2.2, 3.3}, {3.7, 2.1, 2.9}, {2.3, 3.9, 2.7});
  const double reference = oracle_label({a, b}).separation;
  for (const auto& o1 : kVertexOrders)
    for (const auto& o2 : kVertexOrders) {
      EXPECT_EQ(oracle_label({permuted(a, o1), permuted(b, o2)}).separation, reference);
      EXPECT_EQ(oracle_label({permuted(b, o2), permuted(a, o1)}).separation, reference);
    }
}

TEST(Oracle, StageFollowsThePlaneTests) {
  // T1 strictly above T2's plane
  EXPECT_EQ(oracle_label({tri({0, 0, 1}, {4, 0, 1}, {0, 4, 2}), kFloor}).stage, Stage::plane2);
  // T1 straddles T2's plane, T2 strictly on one side of T1's (vertical plane x = 10)
  EXPECT_EQ(oracle_label({tri({10, 0, -1}, {10, 4, -1}, {10, 2, 3}), kFloor}).stage, Stage::plane1);
  EXPECT_EQ(oracle_label({kFloor, tri({1, 1, 0}, {5, 1, 0}, {1, 5, 0})}).stage, Stage::coplanar);
  EXPECT_EQ(oracle_label({kFloor, tri({1, 1, -2}, {1, 1, 2}, {1, -3, 1})}).stage, Stage::interval);
}

TEST(Oracle, IntersectionPointsAreTheExactOnesRounded) {
  // T2 in the plane x = 1 crosses the floor along y in [0, 1] (see cross-pierce)
  const auto r = oracle_label({kFloor, tri({1, 1, -2}, {1, 1, 2}, {1, -3, 1})});
  ASSERT_EQ(r.point_count, 2);
  std::array<Vec3<double>, 2> ends{r.points[0], r.points[1]};
  std::sort(ends.begin(), ends.end(), [](auto& a, auto& b) { return a.y() < b.y(); });
  EXPECT_EQ(ends[0], Vec3<double>(1, 0, 0));
  EXPECT_EQ(ends[1], Vec3<double>(1, 1, 0));
  const auto star = oracle_label({tri({0, 0, 0}, {6, 0, 0}, {3, 6, 0}), tri({0, 4, 0}, {6, 4, 0}, {3, -2, 0})});
  EXPECT_EQ(star.point_count, 6);
}

TEST(Oracle, DegenerateTrianglesAreJudgedAsTheirHulls) {
  // A collinear "triangle" far away: CGAL's Triangle_3 predicates would be unreliable here.
  const Triangle far_needle = tri({100, 100, 5}, {101, 101, 5}, {102, 102, 5});
  auto r = oracle_label({kFloor, far_needle});
  EXPECT_TRUE(r.degenerate);
  EXPECT_EQ(r.relation, Relation::degenerate);
  EXPECT_FALSE(r.overlap);
  EXPECT_EQ(r.dimension, Dimension::none);

  // A collinear triangle piercing the floor: meets it in one point
  r = oracle_label({kFloor, tri({1, 1, -1}, {1, 1, 1}, {1, 1, 3})});
  EXPECT_TRUE(r.overlap);
  EXPECT_EQ(r.dimension, Dimension::point);

  // A collinear triangle lying in the floor: a segment; the middle vertex is not an endpoint
  r = oracle_label({tri({1, 1, 0}, {3, 0.5, 0}, {2, 0.75, 0}), kFloor});
  EXPECT_TRUE(r.overlap);
  EXPECT_EQ(r.dimension, Dimension::segment);

  // A single repeated point on the floor's edge
  r = oracle_label({kFloor, tri({2, 0, 0}, {2, 0, 0}, {2, 0, 0})});
  EXPECT_TRUE(r.overlap);
  EXPECT_EQ(r.dimension, Dimension::point);
  EXPECT_TRUE(has_degenerate_triangle({kFloor, tri({2, 0, 0}, {2, 0, 0}, {2, 0, 0})}));
  EXPECT_FALSE(has_degenerate_triangle({kFloor, kFloor}));
}

TEST(Oracle, IsExactWhereDoubleArithmeticIsNot) {
  // T2's lowest vertex is one ulp above the floor at 1: touching would need exactly 0.
  const double up = std::nextafter(0.0, 1.0);
  auto r = oracle_label({kFloor, tri({1, 1, up}, {1, 1, 3}, {3, 2, 3})});
  EXPECT_FALSE(r.overlap);
  EXPECT_EQ(r.relation, Relation::disjoint);
  EXPECT_EQ(r.separation, up);  // the distance itself, although its square underflows
  r = oracle_label({kFloor, tri({1, 1, 0}, {1, 1, 3}, {3, 2, 3})});
  EXPECT_EQ(r.relation, Relation::touch_point);
}

}  // namespace
}  // namespace tritri
