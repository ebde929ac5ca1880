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
  if (r.coin()) {  // a rotation about a random axis, rounded to double
    const V u = cube(r, 1);
    const double n = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]), th = r.uniform(0, 6.28);
    const double ux = u[0] / n, uy = u[1] / n, uz = u[2] / n, co = std::cos(th), si = std::sin(th), ic = 1 - co;
    const double m[3][3] = {{co + ux * ux * ic, ux * uy * ic - uz * si, ux * uz * ic + uy * si},
                            {uy * ux * ic + uz * si, co + uy * uy * ic, uy * uz * ic - ux * si},
                            {uz * ux * ic - uy * si, uz * uy * ic + ux * si, co + uz * uz * ic}};
    for (Triangle* t : {&out.t1, &out.t2})
      for (auto& v : t->v) v = rotated(v, m);
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
