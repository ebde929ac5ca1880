// Crossing planes after the plane signs are exact (one_pair.hpp's `crossing_known`): the canonical
// order of classify.hpp's `crossing` for any two allowed sign triples, zeros included, as one table
// row per pair of triples, and Guigue–Devillers' G1, G2 on its points in two lanes. Proved in
// algorithms/exact/README.md, "Crossing planes from exact signs: one table row, G1 and G2 in two
// lanes".
#pragma once

#include "algorithms/exact/detail/classify.hpp"
#include "algorithms/exact/detail/pair_box.hpp"

#include <array>
#include <utility>

namespace tritri::exact::detail {

// kLoneFlip's index of a triple of exact signs (each -1, 0 or 1): 9(s0 + 1) + 3(s1 + 1) + s2 + 1.
constexpr int sign_index(const int s[3]) { return 9 * s[0] + 3 * s[1] + s[2] + 13; }

// A sign triple given as bits (`code` = pos | neg << 3: bit k of pos / neg set where s_k > 0 / < 0,
// never both) as one byte: its sign_index, plus kOneSided when the triple is one-sided and kAllZero
// when all three are 0 (the triples crossing_known is not asked about). One look-up per triangle,
// where the three ints had cost a comparison each per test and three multiply-adds for the index
// (algorithms/exact/README.md, "On the grid, crossing planes at once").
inline constexpr unsigned kOneSided = 32u, kAllZero = 64u;
inline constexpr auto kTriCode = [] {
  std::array<unsigned char, 64> t{};
  for (unsigned code = 0; code < 64; ++code) {
    const int s[3] = {int(code & 1u) - int(code >> 3 & 1u), int(code >> 1 & 1u) - int(code >> 4 & 1u),
                      int(code >> 2 & 1u) - int(code >> 5 & 1u)};
    t[code] = static_cast<unsigned char>(sign_index(s) | (one_sided(s) ? kOneSided : 0u) | (zero_count(s) == 3 ? kAllZero : 0u));
  }
  return t;
}();

// kTriCode of T1's (`second` false) or T2's triple among six signs as bits (bit k of pos / neg: T1's
// vertex k for k < 3, T2's vertex k - 3 otherwise).
inline unsigned tri_code(unsigned pos, unsigned neg, bool second) {
  return second ? kTriCode[(pos >> 3) | (neg & 070u)] : kTriCode[(pos & 7u) | (neg & 7u) << 3];
}

// kCanon[27 sign_index(s1) + sign_index(s2)] = (p1, q1, r1, p2, q2, r2) as coordinate offsets
// 3i of the pair's points i (T1's 0..2, T2's 3..5): each triangle's lone vertex first (kLoneFlip), then its
// successors, q and r of one triangle exchanged when the other's lone vertex is negative. The
// points `crossing` picks, looked up once: the two look-ups, three successors and two swaps per
// call had cost about 60 instructions.
inline constexpr auto kCanon = [] {
  std::array<std::array<unsigned char, 6>, 729> t{};
  for (int a = 0; a < 27; ++a)
    for (int b = 0; b < 27; ++b) {
      const LoneFlip e1 = kLoneFlip[a], e2 = kLoneFlip[b];
      unsigned char p[6] = {static_cast<unsigned char>(e1.l), static_cast<unsigned char>((e1.l + 1) % 3),
                            static_cast<unsigned char>((e1.l + 2) % 3), static_cast<unsigned char>(3 + e2.l),
                            static_cast<unsigned char>(3 + (e2.l + 1) % 3), static_cast<unsigned char>(3 + (e2.l + 2) % 3)};
      if (e2.f < 0) std::swap(p[1], p[2]);  // flips π1 so that p2 is on its positive side
      if (e1.f < 0) std::swap(p[4], p[5]);  // flips π2 so that p1 is on its positive side
      for (int k = 0; k < 6; ++k) t[27 * a + b][k] = static_cast<unsigned char>(3 * p[k]);
    }
  return t;
}();

// G1 = o3(p1, q1, p2, q2) in lane 0 as det3_eval(p1, q2, p1, q1, p1, p2) and G2 = o3(p1, r1, r2, p2)
// in lane 1 as det3_eval(p1, p2, p1, r1, p1, r2) (cyclic exchanges of the rows: the same exact
// values), each lane det3_eval's operations in its order, so its value bit for bit and the pair's
// bound covers it (README "Crossing planes from exact signs: one table row, G1 and G2 in two
// lanes"). `o`: a kCanon row.
[[gnu::always_inline]] inline Double2 gd_lanes(const double* c, const unsigned char* o) {
  const double *p1 = c + o[0], *q1 = c + o[1], *r1 = c + o[2], *p2 = c + o[3], *q2 = c + o[4], *r2 = c + o[5];
  const auto two = [p1](const double* a, const double* b, int i) { return Double2{a[i], b[i]} - p1[i]; };
  const Double2 ux = two(q2, p2, 0), uy = two(q2, p2, 1), uz = two(q2, p2, 2);
  const Double2 vx = two(q1, r1, 0), vy = two(q1, r1, 1), vz = two(q1, r1, 2);
  const Double2 wx = two(p2, r2, 0), wy = two(p2, r2, 1), wz = two(p2, r2, 2);
  return (ux * (vy * wz - vz * wy) + uy * (vz * wx - vx * wz)) + uz * (vx * wy - vy * wx);
}

// Crossing planes (classify.hpp's `crossing`) from the six exact plane signs, both triangles
// proper, neither sign triple one-sided nor all zero, given as their kCanon row (`row`) and their
// zeros (bit k: sign k is 0, T1's three then T2's): the canonical order by that row, G1 and G2 in
// two lanes against the pair's bound (one branch per exit, as the filter's step 3; the values are
// finite when B is, and no comparison with B = +inf holds), then their exact signs from `sign(v, a,
// b, cc, d)`, the exact sign of o3 of the pair's points a, b, cc, d (0..5) given its value v in
// det3_eval's shape (algorithms/exact/README.md, "Crossing planes from exact signs: one table row,
// G1 and G2 in two lanes").
template <bool kRelation, class Sign>
[[gnu::always_inline]] inline Relation crossing_known(const double* c, unsigned row, unsigned zeros, double bound,
                                                     Sign&& sign) {
  const unsigned char* o = kCanon[row].data();
  const Double2 gg = gd_lanes(c, o);
  const double hi = dmax(gg[0], gg[1]);
  if (hi > bound) return Relation::disjoint;
  int g1 = -1, g2 = -1;  // both certainly negative unless a value is within the bound
  if (!(hi < -bound)) {
    g1 = sign(gg[0], o[0] / 3, o[1] / 3, o[3] / 3, o[4] / 3);
    if (g1 > 0) return Relation::disjoint;
    g2 = sign(gg[1], o[0] / 3, o[2] / 3, o[5] / 3, o[3] / 3);
    if (g2 > 0) return Relation::disjoint;
  }
  if (!kRelation) return Relation::cross;  // meets
  // p1 (offset o[0]) or p2 (o[3]) on the other plane: its sign is 0
  if (g1 == 0 || g2 == 0 || (zeros >> (o[0] / 3) & 1u) || (zeros >> (o[3] / 3) & 1u)) return Relation::touch_point;
  const bool edge_on_line = __builtin_popcount(zeros & 7u) == 2 || __builtin_popcount(zeros >> 3) == 2;
  return edge_on_line ? Relation::touch_segment : Relation::cross;
}

}  // namespace tritri::exact::detail
