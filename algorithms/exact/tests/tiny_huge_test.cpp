// Unit tests of the one-pair path's signs for values within the pair's bound off the grid
// (one_pair.hpp `sign_o3_within`: the 40- and 61-bit conversions, else `Filtered::o3` with its
// per-call and dynamic bounds; algorithms/exact/README.md, "Zeros off the grid") on a tiny triangle
// against a huge one, where the pair's bound is set by the huge one: exact zeros, values far below
// the bound, rounded rotations of them. Every sign against GMP, the answers against the oracle.
#include "algorithms/exact/exact.hpp"
#include "cases/generator/exact_pairs.hpp"
#include "cases/oracle/oracle.hpp"

#include <gmp.h>
#include <gtest/gtest.h>

#include <cmath>

using namespace tritri;
using namespace exact_pairs;
namespace ex = tritri::exact;
namespace d = tritri::exact::detail;

namespace {

// The sign of o3(a, b, c, x) = det[b - a, c - a, x - a], exactly (GMP rationals).
int o3_sign_gmp(const double* a, const double* b, const double* c, const double* x) {
  mpq_t m[3][3], t, s, acc;
  mpq_inits(t, s, acc, nullptr);
  const double* rows[3] = {b, c, x};
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) {
      mpq_init(m[r][k]);
      mpq_set_d(m[r][k], rows[r][k]);
      mpq_set_d(t, a[k]);
      mpq_sub(m[r][k], m[r][k], t);
    }
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    mpq_mul(t, m[1][i], m[2][j]);
    mpq_mul(s, m[1][j], m[2][i]);
    mpq_sub(t, t, s);
    mpq_mul(t, t, m[0][k]);
    mpq_add(acc, acc, t);
  }
  const int out = mpq_sgn(acc);
  for (auto& row : m)
    for (auto& q : row) mpq_clear(q);
  mpq_clears(t, s, acc, nullptr);
  return out;
}

V rotated(const V& v, const double (&m)[3][3]) {
  return V(m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
           m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]);
}

// Both triangles by one rotation about a random axis, rounded to double.
void rotate_rounded(GenRng& r, TrianglePair& p) {
  const V u = cube(r, 1);
  const double n = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]), th = r.uniform(0, 6.28);
  const double ux = u[0] / n, uy = u[1] / n, uz = u[2] / n, co = std::cos(th), si = std::sin(th), ic = 1 - co;
  const double m[3][3] = {{co + ux * ux * ic, ux * uy * ic - uz * si, ux * uz * ic + uy * si},
                          {uy * ux * ic + uz * si, co + uy * uy * ic, uy * uz * ic - ux * si},
                          {uz * ux * ic - uy * si, uz * uy * ic + ux * si, co + uz * uz * ic}};
  for (Triangle* t : {&p.t1, &p.t2})
    for (auto& v : t->v) v = rotated(v, m);
}

// T2 2^-k the size of T1 (k from 10 to 45), at a point of T1 (a vertex, an edge point or an inside
// point in eighths): touching it, crossing it or just above it; half of them then rotated by a
// rounded random rotation (no longer exactly touching: values near zero of either sign), and
// every one scaled by 2^s.
TrianglePair tiny_against_huge(GenRng& r) {
  const auto iv = [&r](int lo, int hi) { return static_cast<double>(r.integer(lo, hi)); };
  const V a(iv(-4, 4), iv(-4, 4), iv(-4, 4)), b = a + V(8 * iv(1, 3), iv(-2, 2), iv(-2, 2)),
          c = a + V(8 * iv(-1, 3), 8 * iv(1, 3), iv(-2, 2));
  const int wa = static_cast<int>(r.integer(0, 8)), wb = static_cast<int>(r.integer(0, 8 - wa));
  const V x = (wa * a + wb * b + (8 - wa - wb) * c) / 8.0;
  const double eps = std::ldexp(1.0, -static_cast<int>(r.integer(10, 45)));
  const int kind = static_cast<int>(r.integer(0, 2));  // touching, crossing, above
  const V lift = kind == 2 ? V(0, 0, eps * iv(1, 3)) : V(0, 0, 0);
  const V p = x + lift + (kind == 1 ? eps * V(iv(-3, 3), iv(-3, 3), iv(1, 3)) : V(0, 0, 0));
  TrianglePair out{Triangle{{a, b, c}}, Triangle{{p, x + lift + eps * int_vec(r, 5), x + lift + eps * int_vec(r, 5)}}};
  if (r.coin()) rotate_rounded(r, out);
  return scaled(out, static_cast<int>(r.integer(-300, 300)));
}

// T2 exactly in T1's plane and 2^-k its size (integer combinations of T1's edges at a point of
// it), half of them then rotated (rounded: T1's vertices within rounding of π2, of either sign,
// where the pair's bound and not T2's own extents bound the values' errors), scaled by 2^s.
TrianglePair tiny_in_its_plane(GenRng& r) {
  const auto iv = [&r](int lo, int hi) { return static_cast<double>(r.integer(lo, hi)); };
  const V a(iv(-4, 4), iv(-4, 4), iv(-4, 4)), b = a + V(8 * iv(1, 3), iv(-2, 2), iv(-2, 2)),
          c = a + V(8 * iv(-1, 3), 8 * iv(1, 3), iv(-2, 2));
  const V x = (2 * a + 3 * b + 3 * c) / 8.0;
  const double eps = std::ldexp(1.0, -static_cast<int>(r.integer(10, 45)));
  TrianglePair out{Triangle{{a, b, c}}, Triangle{}};
  for (auto& v : out.t2.v) v = x + eps * (iv(-4, 4) * (b - a) + iv(-4, 4) * (c - a));
  if (r.coin()) rotate_rounded(r, out);
  return scaled(out, static_cast<int>(r.integer(-300, 300)));
}

// T2 2^-k the size of T1 (k from 10 to 45) on random doubles (off every grid), at a random point y
// of T1: touching it at y, crossing it, in its plane (y plus rounded combinations of T1's edges),
// or just above it; scaled by 2^s.
TrianglePair tiny_on_doubles(GenRng& r) {
  const V a = cube(r, 1), b = cube(r, 1), c = cube(r, 1);
  double wa = r.uniform(), wb = r.uniform();
  if (wa + wb > 1) wa = 1 - wa, wb = 1 - wb;
  const V y = a + wa * (b - a) + wb * (c - a);
  const double eps = std::ldexp(1.0, -static_cast<int>(r.integer(10, 45)));
  const auto in_plane = [&] { return y + eps * (r.uniform(-1, 1) * (b - a) + r.uniform(-1, 1) * (c - a)); };
  TrianglePair out{Triangle{{a, b, c}}, Triangle{{y, y + eps * cube(r, 1), y + eps * cube(r, 1)}}};
  switch (r.integer(0, 3)) {
    case 1: out.t2[0] = y - eps * cube(r, 1); break;  // across π1, most of the time
    case 2: out.t2 = Triangle{{in_plane(), in_plane(), in_plane()}}; break;
    case 3: out.t2[0] = y + eps * (out.t2[1] - y + out.t2[2] - y); break;
    default: break;
  }
  return scaled(out, static_cast<int>(r.integer(-300, 300)));
}

}  // namespace

TEST(TinyAgainstHuge, SignsWithinThePairsBoundAreGmps) {
  // every o3 of four of the six points whose value is within the pair's bound: sign_o3_within's
  // sign and Filtered::o3's against GMP. It fails with Filtered's dynamic bound an eighth of
  // kPerm3·P (planted and seen failing).
  GenRng r(2026);
  long within = 0, zeros = 0;
  for (int n = 0; n < 1500; ++n) {
    const TrianglePair p = tiny_against_huge(r);
    const double* c = p.t1[0].data();
    const d::Box box = d::union_of(d::box_of(c), d::box_of(c + 9));
    const double bound = d::bound_of_box(box);
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        for (int cc = 0; cc < 6; ++cc)
          for (int x = 0; x < 6; ++x) {
            if (a == b || a == cc || a == x || b == cc || b == x || cc == x) continue;
            const double *pa = c + 3 * a, *pb = c + 3 * b, *pc = c + 3 * cc, *px = c + 3 * x;
            const double v = ex::det3_eval(pa, px, pa, pb, pa, pc).value;
            if (v > bound || v < -bound) continue;
            const int exact = o3_sign_gmp(pa, pb, pc, px);
            ++within, zeros += exact == 0;
            ASSERT_EQ(ex::Filtered::o3(pa, pb, pc, px), exact) << n << " " << a << b << cc << x;
            d::LazyGrid g{c, box, -1};
            ASSERT_EQ(d::sign_o3_within(v, g, a, b, cc, x), exact) << n << " " << a << b << cc << x;
          }
  }
  EXPECT_GT(within, 50000) << within;
  EXPECT_GT(zeros, within / 10) << zeros;
}

TEST(TinyAgainstHuge, AnswersAgreeWithTheOracle) {
  GenRng r(7);
  for (int n = 0; n < 2000; ++n) {
    TrianglePair p = tiny_against_huge(r);
    if (r.coin()) std::swap(p.t1, p.t2);
    const OracleRecord o = oracle_label(p);
    const RelationAnswer a = ex::relation(p);
    ASSERT_EQ(a.relation, o.relation) << n << ": " << to_string(a.relation) << " vs " << to_string(o.relation);
    ASSERT_EQ(a.dimension, o.dimension) << n;
    ASSERT_EQ(ex::overlap(p) == Overlap::yes, o.overlap) << n;
  }
}

TEST(TinyAgainstHuge, APlanesOwnBoundGivesGmpsSign) {
  // plane_bound.hpp (algorithms/exact/README.md, "A plane's own bound: a small plane triangle"):
  // every plane value (plane_values, both lanes) beyond its plane's own bound has GMP's sign, on
  // tiny pairs in either order, and the bound decides a third or more of those within the pair's
  // B; plane_bound asks it only for `open` with the plane's three bits and not all of the other's.
  // It fails with the pair's extents E replaced by the plane triangle's own e in own_plane_bound
  // (planted and seen failing).
  GenRng r(99);
  long within = 0, decided = 0;
  for (int n = 0; n < 6000; ++n) {
    TrianglePair p = n % 3 == 0 ? tiny_against_huge(r) : n % 3 == 1 ? tiny_in_its_plane(r) : tiny_on_doubles(r);
    if (n % 2) std::swap(p.t1, p.t2);
    const double* c = p.t1[0].data();
    const d::Box box = d::union_of(d::box_of(c), d::box_of(c + 9));
    const double bound = d::bound_of_box(box);
    ASSERT_LT(bound, HUGE_VAL) << n;  // the precondition: every extent at most kMax3
    const double own[2] = {d::own_plane_bound(c + 9, box), d::own_plane_bound(c, box)};  // π2's, π1's
    d::Double2 s[3];
    d::plane_values(c, s);
    for (int lane = 0; lane < 2; ++lane)  // lane 0: T1's vertices against π2, lane 1: T2's against π1
      for (int k = 0; k < 3; ++k) {
        const double v = s[k][lane];
        const double* abc = lane == 0 ? c + 9 : c;
        const bool in = !(v > bound || v < -bound);
        within += in;
        if (!(std::fabs(v) > own[lane])) continue;
        decided += in;
        ASSERT_EQ(ex::sgn(v), o3_sign_gmp(abc, abc + 3, abc + 6, c + 9 * lane + 3 * k)) << n << " " << lane << k;
      }
    for (unsigned open = 0; open < 64; ++open) {  // the three bits of the plane, not all of the other's
      const bool pi2 = (open & 7u) == 7u && (open & 070u) != 070u, pi1 = (open & 070u) == 070u && (open & 7u) != 7u;
      ASSERT_EQ(d::plane_bound(c + 9, box, bound, open, 007u), pi2 ? own[0] : bound) << open;
      ASSERT_EQ(d::plane_bound(c, box, bound, open, 070u), pi1 ? own[1] : bound) << open;
    }
  }
  EXPECT_GT(within, 15000) << within;
  EXPECT_GT(decided, within / 3) << decided << " of " << within;
}

TEST(TinyAgainstHuge, PairsOnDoublesAgreeWithTheOracle) {
  // the one-pair path, with a plane's own bound where `finish` asks it, against the oracle
  GenRng r(11);
  for (int n = 0; n < 2000; ++n) {
    TrianglePair p = tiny_on_doubles(r);
    if (r.coin()) std::swap(p.t1, p.t2);
    const OracleRecord o = oracle_label(p);
    const RelationAnswer a = ex::relation(p);
    ASSERT_EQ(a.relation, o.relation) << n << ": " << to_string(a.relation) << " vs " << to_string(o.relation);
    ASSERT_EQ(ex::overlap(p) == Overlap::yes, o.overlap) << n;
  }
}
