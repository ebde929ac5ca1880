// Unit tests of the route for six points in one plane z = h (detail/one_pair.hpp `flat_first`
// one pair per call, `finish_pair` in the batch's scalar pass; detail/coplanar.hpp
// `coplanar_flat_z`; algorithms/exact/README.md, "Six points in one plane z = h: (x, y) before the
// 3-D grid test" and "…, before the filter's values"): which pairs it takes, and their answers
// against the oracle at both levels, one pair per call and in batches.
#include "algorithms/exact/exact.hpp"
#include "algorithms/exact/tests/pair_checks.hpp"
#include "cases/generator/exact_pairs.hpp"
#include "cases/oracle/oracle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace tritri;
using namespace exact_pairs;
using namespace tritri::exact_checks;
namespace ex = tritri::exact;

namespace {

// A point of the plane z = h: (x, y) in 2^-20 units within [-1, 1] (on the 2-D grid), or with
// `fine` set, one of them at 2^-40 units (off it when the pair's largest |x|, |y| is near 1).
V flat_point(GenRng& r, double h, bool fine) {
  const double x = std::ldexp(static_cast<double>(r.integer(-(1 << 20), 1 << 20)), -20);
  double y = std::ldexp(static_cast<double>(r.integer(-(1 << 20), 1 << 20)), -20);
  if (fine) y += std::ldexp(static_cast<double>(r.integer(-(1 << 10), 1 << 10)), -40);
  return V(x, y, h);
}

// A pair in one plane z = h off the 3-D grid (h = 0.1, or a 52-bit h): T2's first vertex on T1's
// vertex, on an edge's midpoint, inside, or anywhere; now and then T2 degenerate (three points on
// a line of T1's edge) or a point off the 2-D grid.
TrianglePair flat_z_pair(GenRng& r) {
  const double h = r.integer(0, 1) ? 0.1 : 1.0 + std::ldexp(static_cast<double>(r.integer(1, 1 << 20)), -52);
  const bool fine = r.integer(0, 7) == 0;
  TrianglePair p{Triangle{{flat_point(r, h, false), flat_point(r, h, false), flat_point(r, h, fine)}},
                 Triangle{{flat_point(r, h, false), flat_point(r, h, false), flat_point(r, h, false)}}};
  switch (r.integer(0, 4)) {
    case 0: p.t2[0] = p.t1[r.integer(0, 2)]; break;
    case 1: p.t2[0] = (p.t1[0] + p.t1[1]) * 0.5; break;
    case 2: p.t2[0] = (p.t1[0] + p.t1[1] + p.t1[2] * 2.0) * 0.25; break;
    case 3:  // degenerate T2: points of the line of T1's first edge
      p.t2[0] = p.t1[0], p.t2[1] = p.t1[1], p.t2[2] = (p.t1[0] + p.t1[1]) * 0.5;
      break;
    default: break;
  }
  return p;
}

}  // namespace

// Pairs in a plane z = h off the 3-D grid, both argument orders: every answer the oracle's (both
// levels, one pair per call, in batches on every ISA and in the scalar pass), and the route taken
// by exactly the pairs with (x, y) on the 2-D grid and both triangles proper there whose boxes
// meet (the overlap level's box exit comes first), counted as `grid` by the scalar pass where
// nothing else of these pairs is (off the 3-D grid). The count fails with the box's x extent
// tested for z's; the answers with the 2-D grid test left out (a pair one unit of o2 outside an
// edge line at 26 bits, in every order).
TEST(FlatZ, PairsInAPlaneZTakeTheRouteAndAgreeWithTheOracle) {
  GenRng r(97);
  std::vector<TrianglePair> pairs;
  for (int n = 0; n < 3000; ++n) {
    const TrianglePair p = flat_z_pair(r);
    pairs.push_back(p);
    pairs.push_back({p.t2, p.t1});
  }
  for (const TrianglePair& v : every_order(flat_pair_one_unit_apart(2))) pairs.push_back(v);
  std::size_t route = 0;
  for (const TrianglePair& p : pairs)
    route += grid2_reference(p) && proper_in_xy(p.t1) && proper_in_xy(p.t2) && !boxes_apart(p);
  std::vector<Overlap> out(pairs.size());
  ex::reset_stats();
  ex::overlap_batch_with(ex::Isa::scalar, pairs.data(), pairs.size(), out.data());
  EXPECT_EQ(ex::stats().grid, route);
  EXPECT_GT(route, pairs.size() / 2);
  for (std::size_t n = 0; n < pairs.size(); ++n) ASSERT_EQ(out[n] == Overlap::yes, oracle_label(pairs[n]).overlap) << n;
  expect_oracle(pairs, "z = h", oracle_label);
}

// A non-finite coordinate in a pair in a plane z = h: a NaN z leaves the box's z extent zero (the
// box skips it) and (x, y) on the 2-D grid, so only T1's values, which are then not zeros, keep
// the route from answering; the pair is declined at both levels. It fails with the zeros' test
// left out of the route's condition.
TEST(FlatZ, NonFiniteCoordinatesInAPlaneZAreDeclined) {
  GenRng r(98);
  for (int n = 0; n < 200; ++n) {
    TrianglePair p = flat_z_pair(r);
    const int v = r.integer(0, 5), k = r.integer(0, 2);
    (v < 3 ? p.t1[v] : p.t2[v - 3])[k] = n % 3 == 0 ? std::nan("") : (n % 3 == 1 ? HUGE_VAL : -HUGE_VAL);
    ASSERT_EQ(ex::overlap(p), Overlap::unsupported) << n;
    ASSERT_EQ(ex::relation(p).relation, Relation::unsupported) << n;
  }
}

// All six z infinite and equal, (x, y) on the 2-D grid: the box's z extent is inf - inf, not
// zero, but lo_z == hi_z holds, and neither a NaN nor a non-zero value is there to refuse the
// route for six points in one plane z = h before the filter's values: its own test that lo_z is
// finite declines the pair, at both levels, one pair per call and in batches. It fails with that
// test left out (detail/one_pair.hpp `flat_first`).
TEST(FlatZ, SixInfiniteZAreDeclined) {
  GenRng r(99);
  std::vector<TrianglePair> pairs;
  for (int n = 0; n < 200; ++n) {
    TrianglePair p = flat_z_pair(r);
    const double z = n % 2 ? HUGE_VAL : -HUGE_VAL;
    for (int v = 0; v < 3; ++v) p.t1[v][2] = z, p.t2[v][2] = z;
    ASSERT_EQ(ex::overlap(p), Overlap::unsupported) << n;
    ASSERT_EQ(ex::relation(p).relation, Relation::unsupported) << n;
    pairs.push_back(p);
  }
  std::vector<Overlap> out(pairs.size());
  ex::overlap_batch(pairs.data(), pairs.size(), out.data());
  for (std::size_t n = 0; n < pairs.size(); ++n) ASSERT_EQ(out[n], Overlap::unsupported) << n;
}
