// The front of one_pair.hpp's `finish`: the shared-vertex comparisons on the filter's candidates,
// and for pairs whose values are exact (the grid test made before the finiteness test and the flat
// test: a pass proves both unnecessary) the six signs read from the filter's values at once. Proved in algorithms/exact/README.md, "The grid test
// first: finiteness, flat pairs and the signs from it".
#pragma once

#include "algorithms/exact/detail/pair_box.hpp"

#include <array>
#include <cstdint>
#include <cstring>

namespace tritri::exact::detail {

// The exact signs of the filter's six values as crossing.hpp's sign_index of each triangle's triple,
// both at once in two lanes (lane 0: T1's s1 against π2, lane 1: T2's s2 against π1), each value
// certain or exact: a value beyond the bound has the sign of its exact value, and on the grid every
// value is the exact one. (v < 0) - (v > 0) of the all-ones masks is sgn(v), NaN (0) included;
// then 9 sgn(s0) + 3 sgn(s1) + sgn(s2) + 13 by shifts (SSE2 has no 64-bit multiply).
inline Long2 value_sign_indices(const double s1[3], const double s2[3]) {
  const Double2 s[3] = {{s1[0], s2[0]}, {s1[1], s2[1]}, {s1[2], s2[2]}};
  Long2 g[3];
  for (int k = 0; k < 3; ++k) g[k] = (s[k] < 0.0) - (s[k] > 0.0);
  const Long2 thirteen = {13, 13};
  return ((g[0] << 3) + g[0]) + ((g[1] << 1) + g[1]) + (g[2] + thirteen);
}

// The three values are zeros (of either sign): x == 0.0 exactly when its bits without the sign
// bit are zero, so the or of the three, shifted past the sign bit, is zero exactly when all three
// compare equal to 0.0 (a NaN has exponent bits set). One branch, where three comparisons with
// zero had cost a parity test each.
inline bool all_zero3(const double s[3]) {
  std::uint64_t b[3];
  std::memcpy(b, s, sizeof b);
  return ((b[0] | b[1] | b[2]) << 1) == 0u;
}

// shared_vertices (one_pair.hpp) when all nine pairs (i, j) are candidates (coplanar and nearly
// coplanar pairs): bit 3i + j, T1's vertex i equals T2's vertex j, by the same comparisons in the
// same order, unrolled: each pair's coordinates at constant offsets, where the loop over the
// candidates' bits had cost a bit search and two table look-ups per pair. kFirst: the first found.
template <bool kFirst>
inline unsigned all_nine_shared(const double* c) {
  unsigned bits = 0;
#pragma GCC unroll 9
  for (int k = 0; k < 9; ++k) {
    const double *a = c + 3 * (k / 3), *b = c + 9 + 3 * (k % 3);
    if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) {
      bits |= 1u << k;
      if (kFirst) break;
    }
  }
  return bits;
}

// The bits 3i + j that shared_vertices can set, from the filter's values: a vertex of T2 is on
// π2, so T1's vertex i equal to T2's vertex j has an exact value 0 against π2, and likewise
// against π1; B bounds the error of both values, so neither is certain (algorithms/exact/README.md,
// "The fixed cost of `finish`").
// One look-up per pair: the bit arithmetic had cost about 12 instructions.
inline constexpr auto kCandidates = [] {
  std::array<unsigned short, 64> t{};
  for (unsigned open = 0; open < 64; ++open) {
    // T1's bit i to bits 3i..3i+2, T2's three bits repeated at 0, 3 and 6
    const unsigned rows = ((open & 1u) | (open & 2u) << 2 | (open & 4u) << 4) * 7u;
    t[open] = static_cast<unsigned short>(rows & (open >> 3) * 0x49u);
  }
  return t;
}();
inline unsigned shared_candidates(unsigned open) { return kCandidates[open & 63u]; }

// Bit 3i + j, among the bits of `candidates`: T1's vertex i equals T2's vertex j (exact comparison
// of the coordinates: -0 equals +0). Most candidates differ in x, so y and z are read only after.
// kFirst: only whether there is one (the overlap level), the first found alone.
template <bool kFirst>
inline unsigned shared_vertices(const double* c, unsigned candidates) {
  if (candidates == 0x1ffu) return all_nine_shared<kFirst>(c);  // every value within the bound
  static constexpr unsigned char kRow[9] = {0, 0, 0, 3, 3, 3, 6, 6, 6}, kCol[9] = {9, 12, 15, 9, 12, 15, 9, 12, 15};
  unsigned bits = 0;
  for (unsigned m = candidates; m != 0u; m &= m - 1u) {
    const int k = __builtin_ctz(m);
    const double* a = c + kRow[k];
    const double* b = c + kCol[k];
    if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) {
      bits |= 1u << k;
      if (kFirst) break;
    }
  }
  return bits;
}

}  // namespace tritri::exact::detail
