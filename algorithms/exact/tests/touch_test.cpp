// Unit tests of exact's path for touching pairs after the filter (detail/crossing.hpp and
// one_pair.hpp's `crossing_known`): the tables against their definitions
// written again here, the two-lane values against det3_eval and GMP, and the one-pair answers
// against the oracle on touching pairs in every vertex order.
#include "algorithms/exact/exact.hpp"
#include "cases/generator/exact_pairs.hpp"
#include "cases/oracle/oracle.hpp"

#include <gmp.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

using namespace tritri;
using namespace exact_pairs;
namespace ex = tritri::exact;
namespace d = tritri::exact::detail;

namespace {

// The sign of det[a1 - a0, b1 - b0, c1 - c0], exactly (GMP rationals).
int det3_sign_gmp(const double* a0, const double* a1, const double* b0, const double* b1, const double* c0,
                  const double* c1) {
  mpq_t u[3], v[3], w[3], t, s, acc;
  for (auto* q : {u, v, w})
    for (int k = 0; k < 3; ++k) mpq_init(q[k]);
  mpq_inits(t, s, acc, nullptr);
  const auto diff = [](mpq_t out, double x, double y) {
    mpq_t a;
    mpq_init(a);
    mpq_set_d(out, x);
    mpq_set_d(a, y);
    mpq_sub(out, out, a);
    mpq_clear(a);
  };
  for (int k = 0; k < 3; ++k) diff(u[k], a1[k], a0[k]), diff(v[k], b1[k], b0[k]), diff(w[k], c1[k], c0[k]);
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    mpq_mul(t, v[i], w[j]);
    mpq_mul(s, v[j], w[i]);
    mpq_sub(t, t, s);
    mpq_mul(t, t, u[k]);
    mpq_add(acc, acc, t);
  }
  const int out = mpq_sgn(acc);
  for (auto* q : {u, v, w})
    for (int k = 0; k < 3; ++k) mpq_clear(q[k]);
  mpq_clears(t, s, acc, nullptr);
  return out;
}

// The triples crossing_known is asked about: not all zero, not one-sided.
bool allowed(const int (&s)[3]) {
  const bool zero = s[0] == 0 && s[1] == 0 && s[2] == 0;
  const bool pos = s[0] > 0 && s[1] > 0 && s[2] > 0, neg = s[0] < 0 && s[1] < 0 && s[2] < 0;
  return !zero && !pos && !neg;
}
void triple(int t, int (&s)[3]) { s[0] = t / 9 - 1, s[1] = t / 3 % 3 - 1, s[2] = t % 3 - 1; }

// classify.hpp's canonical order written again: the first l (from 0) and f (1 before -1) with
// f·s[l] >= 0 and the other two f·s <= 0, strictly so if s[l] = 0.
void lone(const int (&s)[3], int& l, int& f) {
  for (l = 0; l < 3; ++l)
    for (f = 1; f >= -1; f -= 2) {
      const int p = f * s[l], q = f * s[(l + 1) % 3], r = f * s[(l + 2) % 3];
      if (p >= 0 && q <= 0 && r <= 0 && (p > 0 || (q < 0 && r < 0))) return;
    }
  ADD_FAILURE() << "no lone vertex";
  l = 0, f = 1;
}

// The six points (as indices 0..5) of the canonical order for two allowed triples.
std::array<int, 6> canonical(const int (&s1)[3], const int (&s2)[3]) {
  int l1, f1, l2, f2;
  lone(s1, l1, f1);
  lone(s2, l2, f2);
  std::array<int, 6> o = {l1, (l1 + 1) % 3, (l1 + 2) % 3, 3 + l2, 3 + (l2 + 1) % 3, 3 + (l2 + 2) % 3};
  if (f2 < 0) std::swap(o[1], o[2]);
  if (f1 < 0) std::swap(o[4], o[5]);
  return o;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, 8) == 0 || (a != a && b != b); }

}  // namespace

TEST(Crossing, TableRowsAreTheCanonicalOrder) {
  // every allowed pair of triples: kCanon's row is the canonical order's six points, and the
  // index is kLoneFlip's; it fails with the two flips' sources exchanged in kCanon
  int rows = 0;
  for (int a = 0; a < 27; ++a)
    for (int b = 0; b < 27; ++b) {
      int s1[3], s2[3];
      triple(a, s1), triple(b, s2);
      if (!allowed(s1) || !allowed(s2)) continue;
      ASSERT_EQ(d::sign_index(s1), a);
      const std::array<int, 6> want = canonical(s1, s2);
      for (int k = 0; k < 6; ++k) EXPECT_EQ(d::kCanon[27 * a + b][k], 3 * want[k]) << a << " " << b << " " << k;
      ++rows;
    }
  EXPECT_EQ(rows, 24 * 24);
}

TEST(Crossing, GdLanesAreDet3EvalAndTheBoundDecidesTheirSigns) {
  // gd_lanes against det3_eval on the canonical points, bit for bit, for every allowed pair of
  // triples, on random, small-integer (touching), perturbed and wide pairs and odd coordinates;
  // where a lane is beyond the pair's bound its sign is GMP's sign of G1 = o3(p1, q1, p2, q2) or
  // G2 = o3(p1, r1, r2, p2); on small-integer pairs (on the grid) every lane's sign is GMP's. It
  // fails with the two flips' sources exchanged in kCanon.
  GenRng r(41);
  std::vector<TrianglePair> pairs;
  for (int i = 0; i < 150; ++i) pairs.push_back(i % 3 ? random_pair(r) : perturbed(small_int_pair(r), r));
  for (int i = 0; i < 150; ++i) pairs.push_back(small_int_pair(r));
  for (int i = 0; i < 75; ++i) pairs.push_back(scaled(wide_pair(r), static_cast<int>(r.integer(-360, 340))));
  const double odd[] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN(), 0x1p1000};
  for (int i = 0; i < 54; ++i) {
    TrianglePair p = pairs[static_cast<std::size_t>(150 + i)];
    p.t1[0].data()[i % 18] = odd[i / 18];
    pairs.push_back(p);
  }
  long decided = 0, exact = 0;
  for (std::size_t n = 0; n < pairs.size(); ++n) {
    const double* c = pairs[n].t1[0].data();
    const double b = d::bound_of_box(d::union_of(d::box_of(c), d::box_of(c + 9)));
    const bool on_grid = n >= 150 && n < 300;
    for (int ta = 0; ta < 27; ++ta)
      for (int tb = 0; tb < 27; ++tb) {
        int s1[3], s2[3];
        triple(ta, s1), triple(tb, s2);
        if (!allowed(s1) || !allowed(s2)) continue;
        const std::array<int, 6> o = canonical(s1, s2);
        const double *p1 = c + 3 * o[0], *q1 = c + 3 * o[1], *r1 = c + 3 * o[2];
        const double *p2 = c + 3 * o[3], *q2 = c + 3 * o[4], *r2 = c + 3 * o[5];
        const d::Double2 g = d::gd_lanes(c, d::kCanon[27 * ta + tb].data());
        const double g1 = g[0], g2 = g[1];  // by value: clang refuses the address of a lane
        ASSERT_TRUE(same_bits(g1, ex::det3_eval(p1, q2, p1, q1, p1, p2).value)) << n << " " << ta << " " << tb;
        ASSERT_TRUE(same_bits(g2, ex::det3_eval(p1, p2, p1, r1, p1, r2).value)) << n << " " << ta << " " << tb;
        if (!std::isfinite(b) || !d::finite18(c)) continue;
        const int e1 = det3_sign_gmp(p1, q1, p1, p2, p1, q2), e2 = det3_sign_gmp(p1, r1, p1, r2, p1, p2);
        for (const auto& [v, e] : {std::pair{g1, e1}, std::pair{g2, e2}}) {
          if (v > b || v < -b) {
            ASSERT_EQ((v > 0) - (v < 0), e) << n << " " << ta << " " << tb;
            ++decided;
          }
          if (on_grid) {
            ASSERT_EQ((v > 0) - (v < 0), e) << n << " " << ta << " " << tb;
            ++exact;
          }
        }
      }
  }
  EXPECT_GT(decided, 100000) << decided;
  EXPECT_GT(exact, 100000) << exact;
}

namespace {

// A touching pair: T1 with integer vertices in z = 0; T2 with its first vertex on a vertex, an
// edge or inside T1 (barycentric weights in eighths), and its other two above, across or in the
// plane; then an integer frame and, for a third of them, a move off the 15-bit grid (a shift by
// 2^-30 of a unit, on the 40-bit one) or a scaling by 2^k.
TrianglePair touching(GenRng& r) {
  const auto iv = [&r](int lo, int hi) { return static_cast<double>(r.integer(lo, hi)); };
  const V a(0, 0, 0), b(8 * iv(1, 3), 0, 0), c(8 * iv(-1, 3), 8 * iv(1, 3), 0);
  const int kind = static_cast<int>(r.integer(0, 2));
  int wa = 8, wb = 0;
  if (kind == 1) wa = static_cast<int>(r.integer(1, 7));                                   // on edge ab
  if (kind == 2) wa = static_cast<int>(r.integer(1, 6)), wb = static_cast<int>(r.integer(1, 7 - wa));  // inside
  const V x = (wa * a + wb * b + (8 - wa - wb) * c) / 8.0;
  const auto off = [&](bool flat) { return V(iv(-6, 6), iv(-6, 6), flat ? 0.0 : iv(-6, 6)); };
  const bool flat = r.integer(0, 4) == 0;
  TrianglePair p{Triangle{{a, b, c}}, Triangle{{x, x + off(flat), x + off(flat)}}};
  double m[3][3];
  do
    for (auto& row : m)
      for (double& e : row) e = iv(-2, 2);
  while (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]) ==
         0);
  for (Triangle* t : {&p.t1, &p.t2})
    for (auto& v : t->v) v = V(m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
                               m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]);
  const int move = static_cast<int>(r.integer(0, 5));
  if (move == 0) p = translated(p, V(0x1p-30, -0x1p-30, 0x1p-29));
  if (move == 1) p = scaled(p, static_cast<int>(r.integer(-300, 300)));
  return p;
}

}  // namespace

TEST(Crossing, TouchingPairsInEveryOrderAgreeWithTheOracle) {
  // vertex-on-vertex, -edge and -face pairs, their planes crossing or not, on the grid, off it on
  // the 40-bit one, scaled: the one-pair answers at both levels against the oracle, in all 72
  // orders (every kCanon row a touching pair reaches). It fails with the two flips' sources
  // exchanged in kCanon, or with T1's zero read at q1 instead of p1 in `crossing_known`.
  GenRng r(43);
  long checked = 0, touch = 0;
  for (int n = 0; n < 150; ++n)
    for (const TrianglePair& p : every_order(touching(r))) {
      const OracleRecord o = oracle_label(p);
      const RelationAnswer a = ex::relation(p);
      ASSERT_EQ(a.relation, o.relation) << n << ": " << to_string(a.relation) << " vs " << to_string(o.relation);
      ASSERT_EQ(a.dimension, o.dimension) << n;
      ASSERT_EQ(ex::overlap(p) == Overlap::yes, o.overlap) << n;
      touch += o.relation == Relation::touch_point || o.relation == Relation::touch_segment;
      ++checked;
    }
  EXPECT_EQ(checked, 150 * 72);
  EXPECT_GT(touch, 2000);
}

