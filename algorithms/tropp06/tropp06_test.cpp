// Tropp–Tal–Shimshoni 2006: its three edge cases, the 2-D step and its edge-pair codes, the
// built-in general cases, the defects of the published routine, and its operation counts.
// Against the oracle, the conformance suite holds the published routine to random pairs in
// general position (its x–y step is blind to planes through the z axis, which random pairs never
// are), and the fixed one to every small-integer pair, singular ones included.
#include "algorithms/tropp06/tropp06.hpp"

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"
#include "harness/testing/hand_built.hpp"
#include "harness/testing/tritri/testing.hpp"
#include "tritri/counting.hpp"

#include <gtest/gtest.h>

TRITRI_ALGORITHM_CONFORMANCE(Tropp06, "tropp06", almost_everywhere)
TRITRI_ALGORITHM_CONFORMANCE(Tropp06Fixed, "tropp06-fixed", exact)

namespace tritri::tropp06 {
namespace {
const Triangle kWall = tri({0, 0, 0}, {4, 0, 0}, {0, 0, 4});  // the plane y = 0

bool same_segment(std::pair<Vec3<double>, Vec3<double>> s, Vec3<double> a, Vec3<double> b) {
  return ((s.first - a).norm() < 1e-12 && (s.second - b).norm() < 1e-12) ||
         ((s.first - b).norm() < 1e-12 && (s.second - a).norm() < 1e-12);
}

// The published routine never builds the 3-D cut: it goes from B's edge coefficients straight
// to the 2-D step. Each of its three edge cases (B's edges Q1 and Q2 crossing A's plane, Q1 and
// Q3, Q2 and Q3) is reached by putting D1, D1 + Q1 or D1 + Q2 alone below the floor; the cut
// from (2,1,0) to (1,2,0) lies inside A, and the routine reports overlap.
TEST(Tropp06Pieces, EachPairOfCrossedEdgesReachesTheTwoDimensionalStep) {
  EXPECT_NE(intersect<double>({kFloor, tri({1, 1, -1}, {3, 1, 1}, {1, 3, 1})}), kDisjoint);
  EXPECT_NE(intersect<double>({kFloor, tri({3, 1, 1}, {1, 1, -1}, {1, 3, 1})}), kDisjoint);
  EXPECT_NE(intersect<double>({kFloor, tri({3, 1, 1}, {1, 3, 1}, {1, 1, -1})}), kDisjoint);
  // the same cuts moved beyond A (x, y ≥ 6): the 2-D step rejects them
  EXPECT_EQ(intersect<double>({kFloor, tri({7, 6, -1}, {9, 6, 1}, {7, 8, 1})}), kDisjoint);
  EXPECT_EQ(intersect<double>({kFloor, tri({9, 6, 1}, {7, 6, -1}, {7, 8, 1})}), kDisjoint);
  EXPECT_EQ(intersect<double>({kFloor, tri({9, 6, 1}, {7, 8, 1}, {7, 6, -1})}), kDisjoint);
}

TEST(Tropp06Pieces, ParallelCoplanarAndRejectedPlanes) {
  auto code = [](const Triangle& a, const Triangle& b) { return intersect<double>({a, b}); };
  EXPECT_EQ(code(kFloor, tri({0, 0, 1}, {4, 0, 1}, {0, 4, 1})), kDisjoint);  // parallel
  EXPECT_EQ(code(kFloor, tri({1, 1, 0}, {5, 1, 0}, {1, 5, 0})), kCoplanar);  // Möller's test
  EXPECT_EQ(code(kFloor, tri({9, 9, 0}, {12, 9, 0}, {9, 12, 0})), kDisjoint); // coplanar, apart
  EXPECT_EQ(code(kFloor, tri({0, 0, 2}, {4, 0, 3}, {0, 4, 5})), kDisjoint);  // all above
}

TEST(Tropp06Pieces, EdgePairCodesName2DCrossings) {
  using V = Vec2<double>;
  const V p1{4, 0}, p2{0, 4};  // A = (0,0), (4,0), (0,4); edge 1 along p1, 2 along p2, 3 between
  // a horizontal line y = 1 crosses edges 2 (x = 0) and 3 (the hypotenuse)
  EXPECT_EQ(segment_vs_triangle_2d(p1, p2, V{-1, 1}, V{6, 0}), kEdges23);
  // a vertical line x = 1 crosses edges 1 and 3
  EXPECT_EQ(segment_vs_triangle_2d(p1, p2, V{1, -1}, V{0, 6}), kEdges13);
  // a line x + y = 1... through edges 1 and 2
  EXPECT_EQ(segment_vs_triangle_2d(p1, p2, V{2, -1}, V{-3, 3}), kEdges12);
  // the line crosses A, the segment stops short of it
  EXPECT_EQ(segment_vs_triangle_2d(p1, p2, V{-3, 1}, V{1, 0}), kDisjoint);
  // the segment lies inside A: both crossings beyond its ends, on either side
  EXPECT_EQ(segment_vs_triangle_2d(p1, p2, V{1, 1}, V{0.5, 0}), kEdges23);
  // the line misses A
  EXPECT_EQ(segment_vs_triangle_2d(p1, p2, V{-1, 5}, V{6, 0}), kDisjoint);
}

TEST(Tropp06, IntersectReturnsTheEdgePairOfTheFirstTriangle) {
  // B's cut lies along y = 1 from x = -1 to x = 1: its line crosses A's edges 2 (x = 0) and 3
  EXPECT_EQ(intersect<double>({kFloor, tri({-1, 1, -1}, {-1, 1, 1}, {3, 1, 1})}), kEdges23);
  EXPECT_EQ(intersect<double>({kFloor, tri({0, 0, 2}, {4, 0, 3}, {0, 4, 5})}), kDisjoint);
  EXPECT_EQ(intersect<double>({kFloor, tri({1, 1, 0}, {5, 1, 0}, {1, 5, 0})}), kCoplanar);
}

// Whether the published x–y step can see plane A at all (defect 1 below).
bool a_projects_onto_xy(const TrianglePair& p) { return (p.t1[1] - p.t1[0]).cross(p.t1[2] - p.t1[0])[2] != 0; }

TEST(Tropp06, GeneralBuiltinCasesAgreeWithTheOracle) {
  int vertical = 0;
  for (const auto& c : builtin_cases()) {
    if (c.family() != "general") continue;
    const bool truth = oracle_label(c.pair).overlap;
    for (const TrianglePair& p : {c.pair, swapped(c.pair)}) {
      EXPECT_EQ((overlap<double, Projection::dominant, true>(p)), truth) << c.name << " (fixed)";
      if (a_projects_onto_xy(p)) {
        EXPECT_EQ(overlap<double>(p), truth) << c.name;
      } else {
        // swapped cross-pierce (A in x = 1: a miss) and swapped disjoint-interval (A in x = 2)
        ++vertical;
        EXPECT_FALSE(overlap<double>(p)) << c.name;
      }
    }
  }
  EXPECT_EQ(vertical, 2);
}

// Published defect 1: the 2-D step in x–y. With A in the plane y = 0 every 2-D cross product
// vanishes: a plain crossing is reported disjoint.
TEST(Tropp06Defects, VerticalPlaneAIsReportedDisjoint) {
  const TrianglePair crossing{kWall, tri({1, -1, 1}, {1, 1, 1}, {2, 1, 1})};
  ASSERT_EQ(oracle_label(crossing).relation, Relation::cross);
  EXPECT_EQ(intersect<double>(crossing), kDisjoint);
  EXPECT_NE((intersect<double, Projection::dominant, false>(crossing)), kDisjoint);
  // the same pair turned so that A is not vertical is found by the published routine
  const TrianglePair turned{kFloor, tri({1, 1, -1}, {1, 1, 1}, {2, 1, 1})};
  ASSERT_EQ(oracle_label(turned).relation, Relation::cross);
  EXPECT_NE(intersect<double>(turned), kDisjoint);
}

// Published defect 2: B touching plane A in one vertex gives a zero-length cut, and the 2-D step
// never finds a zero direction legal.
TEST(Tropp06Defects, SingleVertexContactIsReportedDisjoint) {
  for (const Triangle& b : {tri({1, 1, 0}, {1, 1, 3}, {3, 2, 3}),    // D1 on A's face
                            tri({1, 1, 3}, {1, 1, 0}, {3, 2, 3}),    // D1 + Q1 on it
                            tri({1, 1, 3}, {3, 2, 3}, {1, 1, 0})}) { // D1 + Q2 on it
    const TrianglePair p{kFloor, b};
    ASSERT_EQ(oracle_label(p).relation, Relation::touch_point);
    EXPECT_EQ(intersect<double>(p), kDisjoint);
    EXPECT_EQ((intersect<double, Projection::dominant, true>(p)), kVertex);
  }
  // D1 on plane A, outside A, with B straddling the plane: the true cut runs from D1 to edge
  // Q3's crossing, (−1,1,0) → (3,1,0), and crosses A
  const TrianglePair straddling{kFloor, tri({-1, 1, 0}, {3, 1, 2}, {3, 1, -2})};
  ASSERT_EQ(oracle_label(straddling).relation, Relation::cross);
  EXPECT_EQ(intersect<double>(straddling), kDisjoint);
  EXPECT_NE((intersect<double, Projection::dominant, true>(straddling)), kDisjoint);
  // and the fixed variant still rejects a vertex on A's plane but outside A
  EXPECT_EQ((intersect<double, Projection::dominant, true>({kFloor, tri({5, 5, 0}, {5, 5, 3}, {6, 5, 3})})),
            kDisjoint);
}

// Published defect 3: a cut line through A's vertex C1 makes edges 1 and 2 both legal at C1,
// and the segment is compared with that point only. B's cut runs from (1,1,0) to (1.5,1.5,0),
// on the line x = y through C1 = (0,0,0), inside A.
TEST(Tropp06Defects, CutLineThroughC1IsComparedWithC1Only) {
  const TrianglePair p{kFloor, tri({1, 1, -1}, {1, 1, 1}, {2, 2, 1})};
  ASSERT_EQ(oracle_label(p).relation, Relation::cross);
  EXPECT_EQ(intersect<double>(p), kDisjoint);
  EXPECT_EQ((intersect<double, Projection::dominant, true>(p)), kEdges13);
  // the same segment with A's vertices rotated (C1 no longer on the line) is found
  EXPECT_NE(intersect<double>({tri({4, 0, 0}, {0, 4, 0}, {0, 0, 0}), p.t2}), kDisjoint);
  // a line through C1 that only touches A there: still one point, and it is on the segment
  const TrianglePair touching{kFloor, tri({-1, 1, -1}, {-1, 1, 1}, {1, -1, 1})};
  ASSERT_TRUE(oracle_label(touching).overlap);
  EXPECT_NE((intersect<double, Projection::dominant, true>(touching)), kDisjoint);
}

// ---- the counting instantiation (tritri bench's operation counts) ----

// The edge-pair codes, not only the overlap the suite compares: the counted run must take the
// same path as the double one, or its counts are of another computation.
TEST(Tropp06Counted, TakesTheDoublePath) {
  for (const TrianglePair& p : testing::counting_pairs()) {
    const PairT<Counted> c = cast<Counted>(p);
    if (intersect<double>(p) == intersect<Counted>(c) &&
        (intersect<double, Projection::dominant, true>(p)) == (intersect<Counted, Projection::dominant, true>(c)))
      continue;
    ADD_FAILURE() << "an edge-pair code differs between double and Counted on\n"
                  << format_case({"counted", p, {}, "", 0}, NumberStyle::hex);
  }
}

OpCounts counts_of(const TrianglePair& p) {
  op_counts() = {};
  (void)intersect<Counted>(cast<Counted>(p));
  return op_counts();
}

// A pair rejected at step 3, counted by hand: edge vectors 4×3 add, r 3 add, N_A = P1×P2
// (6 mul, 3 add), dq1, dq2, dr (9 mul, 6 add), β1 = dr·dq2, β2 = dr·dq1 (2 mul), dq3 and dr3
// (2 add, computed before the branch as published); each legality test stops at its first
// comparison (β ≥ 0 fails), then dq1 = 0? (1 cmp).
TEST(Tropp06Counted, AStep3RejectCostsWhatTheCodeSays) {
  EXPECT_EQ(counts_of({kFloor, tri({0, 0, 2}, {4, 0, 3}, {0, 4, 5})}), (OpCounts{26, 17, 0, 3, 0}));
}

// Division-free as the paper says, and every pair costs at least the step-3 reject's set-up.
TEST(Tropp06Counted, NoDivisionsAndNoSquareRoots) {
  const std::vector<TrianglePair> pairs = testing::counting_pairs();
  OpCounts total;
  for (const TrianglePair& p : pairs) {
    const OpCounts c = counts_of(p);
    EXPECT_EQ(c.div, 0u);
    EXPECT_EQ(c.sqrt, 0u);
    EXPECT_GE(c.add, 24u);
    EXPECT_GE(c.mul, 17u);
    total.add += c.add, total.mul += c.mul, total.cmp += c.cmp;
  }
  // those that reach step 5 cost far more than a reject, so the mean lies well above it
  EXPECT_GT(total.mul, 17u * pairs.size() + pairs.size());
  EXPECT_GT(total.cmp, 5u * pairs.size());
}

// The published interface, edges given by the caller (the bench's stage edges-given), answers as
// the vertex interface does on every built-in case, both ways round and with a unit-cube pair
// whose edges are not exact (they are the caller's own subtractions, the same as the port's).
TEST(Tropp06, EdgesGivenAnswerAsTheVerticesDo) {
  int compared = 0;
  std::vector<TrianglePair> pairs;
  for (const auto& c : builtin_cases()) pairs.insert(pairs.end(), {c.pair, swapped(c.pair)});
  pairs.push_back({tri({0.1, 0.7, 0.3}, {0.9, 0.2, 0.6}, {0.4, 0.4, 0.95}), tri({0.3, 0.1, 0.8}, {0.6, 0.9, 0.1}, {0.2, 0.5, 0.2})});
  for (const TrianglePair& p : pairs) {
    EXPECT_EQ(overlap_with_edges(with_edges(p)), overlap<double>(p));
    ++compared;
  }
  EXPECT_GT(compared, 20);
  const Algorithm* a = registry().find("tropp06");
  ASSERT_NE(a, nullptr);
  ASSERT_EQ(a->stages.size(), 1u);
  EXPECT_EQ(a->stages[0].name, "edges-given");
  std::vector<TrianglePair> prepared(pairs.size());
  a->stages[0].prepare(pairs.data(), pairs.size(), prepared.data());
  std::uint64_t expected = 0;
  for (const TrianglePair& p : pairs) expected += overlap<double>(p) ? 1u : 0u;
  EXPECT_EQ(a->stages[0].run(prepared.data(), prepared.size()), expected);
}

}  // namespace
}  // namespace tritri::tropp06
