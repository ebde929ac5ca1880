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

// The one-pair filter's step 3 (one_pair.hpp `filter_pair`): the canonical order's six points for
// the sign bits `sp` (one_pair.hpp's kSplit order: T1's positive bits, then T2's, each in 1..6;
// every sign certain, so non-zero): kPick[sp] = (p1, q1, r1, p2, q2, r2) as coordinate offsets,
// kCanon's row for those signs, indexed by the filter's bits directly. Rows of one-sided patterns
// are never read (the filter has exited).
inline constexpr auto kPick = [] {
  std::array<std::array<unsigned char, 8>, 64> t{};
  for (unsigned sp = 0; sp < 64; ++sp) {
    int s1[3], s2[3];
    for (unsigned k = 0; k < 3; ++k) s1[k] = (sp >> k & 1u) ? 1 : -1, s2[k] = (sp >> (3 + k) & 1u) ? 1 : -1;
    const auto& row = kCanon[27 * sign_index(s1) + sign_index(s2)];
    for (int k = 0; k < 6; ++k) t[sp][k] = row[k];
  }
  return t;
}();

// Guigue–Devillers' G1 = [p1,q1,p2,q2] and G2 = [p1,r1,r2,p2] on six certain non-zero signs
// (`sp` as kPick's), both in two lanes by `gd_lanes` on kPick's row: each lane det3_eval's
// operations in its order, so its values bit for bit and the pair's bound covers them
// (algorithms/exact/README.md, "One pair per call", "G1 and G2 in two lanes").
[[gnu::always_inline]] inline Double2 gd_values(const double* c, unsigned sp) {
  return gd_lanes(c, kPick[sp].data());
}

}  // namespace tritri::exact::detail
