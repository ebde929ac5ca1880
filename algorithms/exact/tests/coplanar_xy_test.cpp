// Unit tests of the coplanar step's (x, y) projection off the 3-D grid (detail/coplanar.hpp's
// `coplanar_known`; algorithms/exact/README.md, "Coplanar pairs off the 3-D grid: (x, y) first"):
// the 2-D grid test with m from the pair's box against the test written again here on the 12
// coordinates themselves, and the one-pair and batch answers against the oracle on coplanar pairs
// off the 3-D grid, touching or not, in planes whose (x, y) projection is on the 2-D grid, off
// it, or degenerate.
#include "algorithms/exact/exact.hpp"
#include "algorithms/exact/tests/pair_checks.hpp"
#include "cases/generator/exact_pairs.hpp"
#include "cases/oracle/oracle.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

using namespace tritri;
using namespace exact_pairs;
using namespace tritri::exact_checks;
namespace ex = tritri::exact;
namespace d = tritri::exact::detail;

namespace {

// One coordinate at scale 2^e: an integer of up to `bits` bits, a tie with another coordinate, a
// signed zero, or an integer above 2^40 (a huge axis whose units the other axis must not set).
double coordinate(GenRng& r, int e, int bits) {
  switch (r.integer(0, 7)) {
    case 0: return r.integer(0, 1) ? 0.0 : -0.0;
    case 1: return std::ldexp(0x1p40 + static_cast<double>(r.integer(-3, 3)), e);
    default: return std::ldexp(static_cast<double>(r.integer(-(1 << bits), 1 << bits)), e);
  }
}

// Points of a plane z = level + 2^-30 (a x + b y) (exactly, for |x|, |y| <= 1 at 2^-20 units and
// |a|, |b| <= 2), or of the plane y = x with z free (its (x, y) projection degenerate).
V in_plane(int kind, double x, double y, int a, int b) {
  if (kind == 0) return V(x, y, 0.1);
  if (kind == 1) return V(x, y, 1.0 + std::ldexp(a * x + b * y, -30));
  return V(x, x, y + 0.1);
}

// Coplanar pairs off the 3-D grid: T2's first vertex on T1's vertex, on an edge's midpoint, an
// edge of T2 on the line of T1's edge beyond it, or anywhere; coordinates at 2^-20 units.
TrianglePair coplanar_off_grid(GenRng& r, int kind) {
  auto pt = [&] {
    return std::array<double, 2>{std::ldexp(2.0 * r.integer(-(1 << 19), 1 << 19), -20),
                                 std::ldexp(2.0 * r.integer(-(1 << 19), 1 << 19), -20)};
  };
  std::array<double, 2> a = pt(), b = pt(), c = pt(), p = pt(), q = pt(), s = pt();
  switch (r.integer(0, 3)) {
    case 0: p = a; break;
    case 1: p = {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2}; break;
    case 2:
      p = {2 * b[0] - a[0], 2 * b[1] - a[1]};
      q = {3 * b[0] - 2 * a[0], 3 * b[1] - 2 * a[1]};
      if (std::fabs(q[0]) > 1 || std::fabs(q[1]) > 1) q = pt();
      break;
    default: break;
  }
  const int ca = r.integer(-2, 2), cb = r.integer(-2, 2);
  auto put = [&](const std::array<double, 2>& w) { return in_plane(kind, w[0], w[1], ca, cb); };
  return {Triangle{{put(a), put(b), put(c)}}, Triangle{{put(p), put(q), put(s)}}};
}

}  // namespace

// The 2-D grid test with m = max(mag[0], mag[1]) from the pair's box (box_magnitudes of the
// filter's union of the triangles' boxes) decides as the test on the 12 coordinates themselves:
// axes at scales 2^-40..2^40 apart, ties, signed zeros, an axis above 2^40 units. It fails with m
// from x alone (mag[i] for max(mag[i], mag[j])).
TEST(CoplanarXy, TheTwoDimensionalGridFromThePairsBoxIsTheDirectTest) {
  GenRng r(61);
  long on = 0, off = 0;
  for (int n = 0; n < 200000; ++n) {
    const int ex_ = r.integer(-40, 40), ey = r.integer(-40, 40), bits = r.integer(4, 30);
    TrianglePair p;
    for (Triangle* t : {&p.t1, &p.t2})
      for (auto& v : t->v) v = V(coordinate(r, ex_, bits), coordinate(r, ey, bits), coordinate(r, 0, 8));
    double mag[3];
    const double* c = p.t1[0].data();
    d::box_magnitudes(d::union_of(d::box_of(c), d::box_of(c + 9)), mag);
    const bool got = d::on_grid2(d::project_of(c, 2), mag, 0, 1), want = grid2_reference(p);
    ASSERT_EQ(got, want) << n;
    (want ? on : off) += 1;
  }
  EXPECT_GT(on, 5000);
  EXPECT_GT(off, 20000);
}

// Coplanar pairs off the 3-D grid decided in (x, y) when that projection is on the 2-D grid and
// both orientations there are non-zero, else as before: flat pairs at z = 0.1, a plane near z =
// 1 with 51-bit z, the plane y = x (its (x, y) orientations zero: the largest component's
// projection), all against the oracle, one pair per call and in batches; and a flat pair one
// unit of o2 outside an edge line at 26 bits (off the 2-D grid: rounded to 0 in double), in
// every order and on every axis. It fails with (x, y) taken off the 3-D grid without the 2-D grid
// test.
TEST(CoplanarXy, PairsOffTheThreeDGridAgreeWithTheOracle) {
  GenRng r(62);
  for (int kind = 0; kind < 3; ++kind) {
    std::vector<TrianglePair> pairs;
    for (int n = 0; n < 400; ++n) pairs.push_back(coplanar_off_grid(r, kind));
    for (int n = 0; n < 8; ++n)
      for (const auto& v : every_order(coplanar_off_grid(r, kind))) pairs.push_back(v);
    expect_oracle(pairs, kind == 0 ? "flat" : kind == 1 ? "near z" : "y = x", oracle_label);
  }
  std::vector<TrianglePair> edge;
  for (int k = 0; k < 3; ++k) {
    const TrianglePair t = flat_pair_one_unit_apart(k);
    ASSERT_FALSE(oracle_label(t).overlap);
    for (const auto& v : every_order(t)) edge.push_back(v);
  }
  expect_oracle(edge, "one unit outside at 26 bits", oracle_label);
}

// The projection by loads (projected.hpp's project_of) holds, for every axis k dropped, the same
// doubles in the same lanes as project(T1, T2, k + 1, k + 2), bit for bit: random coordinates with
// signed zeros, infinities and NaN. It fails with k = 1's x taken from the load at y.
TEST(CoplanarGrid, TheProjectionByLoadsIsTheProjection) {
  GenRng r(71);
  const double special[] = {0.0, -0.0, __builtin_inf(), -__builtin_inf(), __builtin_nan(""), 0x1p-1074, -1.5};
  for (int n = 0; n < 20000; ++n) {
    double c[18];
    for (double& x : c) x = r.integer(0, 5) == 0 ? special[r.integer(0, 6)] : std::ldexp(r.uniform(-1.0, 1.0), r.integer(-30, 30));
    const ex::P t1[3] = {c, c + 3, c + 6}, t2[3] = {c + 9, c + 12, c + 15};
    for (int k = 0; k < 3; ++k) {
      const d::Projected got = d::project_of(c, k), want = d::project(t1, t2, (k + 1) % 3, (k + 2) % 3);
      ASSERT_EQ(std::memcmp(&got, &want, sizeof got), 0) << n << " k " << k;
    }
  }
}

// all_zero3 (finish_front.hpp) is the three comparisons with 0.0: signed zeros, subnormals,
// infinities, NaN of both signs in every place. It fails without the shift past the sign bit.
TEST(CoplanarGrid, ThreeZerosByTheirBitsAreThreeComparisons) {
  const double v[] = {0.0, -0.0, 0x1p-1074, -0x1p-1074, 1.0, -2.0, __builtin_inf(), -__builtin_inf(),
                      __builtin_nan(""), -__builtin_nan(""), 0x1p-1022, 0x1.fffffffffffffp1023};
  for (double a : v)
    for (double b : v)
      for (double e : v) {
        const double s[3] = {a, b, e};
        ASSERT_EQ(d::all_zero3(s), a == 0.0 && b == 0.0 && e == 0.0) << a << " " << b << " " << e;
      }
}

namespace {

// Small-integer points a + s·u + t·v of one plane (on the 3-D grid): a general plane, z = c, x = c
// or y = c (T1's n_z zero: the normal's projection after (x, y)).
struct Frame {
  V a, u, v;
  V at(int s, int t) const { return a + u * static_cast<double>(s) + v * static_cast<double>(t); }
};
Frame plane_frame(GenRng& r, int kind) {
  Frame f{V(r.integer(-4, 4), r.integer(-4, 4), r.integer(-4, 4)), V(r.integer(-2, 2), r.integer(-2, 2), r.integer(-2, 2)),
          V(r.integer(-2, 2), r.integer(-2, 2), r.integer(-2, 2))};
  if (kind == 1) f.u[2] = 0, f.v[2] = 0;
  if (kind == 2) f.u = V(0, 1, r.integer(-2, 2)), f.v = V(0, r.integer(-2, 2), 1 + r.integer(0, 1));
  if (kind == 3) f.u = V(1, 0, r.integer(-2, 2)), f.v = V(r.integer(-2, 2), 0, 1 + r.integer(0, 1));
  return f;
}

}  // namespace

// Pairs on the 3-D grid whose T1 has its three plane values zero (finish's branch straight to the
// coplanar step, README "Coplanar pairs on the grid straight from the filter's zeros") and pairs
// beside them that must not take it: coplanar pairs sharing a vertex, touching along an edge or
// overlapping; T1 or T2 degenerate in the plane (the classification after the step); T1 with two
// vertices in T2's plane and the third lifted off it (two zeros: its projection may meet T2 where
// the triangles do not). Every order, one pair per call and in batches, against the oracle. It
// fails with all_zero3 reading two of the three values.
TEST(CoplanarGrid, ZerosOnTheGridAgreeWithTheOracle) {
  GenRng r(72);
  std::vector<TrianglePair> pairs;
  for (int n = 0; n < 160; ++n) {
    Frame f = plane_frame(r, n % 4);
    const auto pt = [&] { return f.at(r.integer(-2, 4), r.integer(-2, 4)); };
    TrianglePair p{Triangle{{f.at(0, 0), f.at(4, 0), f.at(0, 4)}}, Triangle{{pt(), pt(), pt()}}};
    switch (n % 5) {
      case 1: p.t2[0] = p.t1[1]; break;                           // a common vertex
      case 2: p.t2[0] = f.at(2, 0), p.t2[1] = f.at(2, 2); break;  // along T1's edges
      case 3: p.t1[2] = p.t1[0] + (p.t1[1] - p.t1[0]) * 2.0; break;  // T1 a segment in the plane
      case 4: {  // T1's third vertex off the plane by the plane's normal
        const V w = f.u.cross(f.v);
        p.t1[2] = pt() + w * static_cast<double>(r.integer(0, 1) ? 1 : -1);
        p.t1[0] = pt(), p.t1[1] = pt();
        break;
      }
      default: break;
    }
    pairs.push_back(p);
  }
  std::vector<TrianglePair> all;
  for (const TrianglePair& p : pairs)
    for (const auto& v : every_order(p)) all.push_back(v);
  expect_oracle(all, "zeros on the grid", oracle_label);
  std::vector<Overlap> ov(all.size());
  ex::overlap_batch_with(ex::Isa::scalar, all.data(), all.size(), ov.data());
  for (std::size_t n = 0; n < all.size(); ++n) ASSERT_EQ(ov[n] == Overlap::yes, oracle_label(all[n]).overlap) << "scalar #" << n;
}
