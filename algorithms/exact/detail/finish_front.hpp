// The front of one_pair.hpp's `finish` for pairs whose values are exact: the grid test made
// before the finiteness test and the flat test (a pass proves both unnecessary), the six signs
// read from the filter's values at once. Proved in algorithms/exact/README.md, "The grid test
// first: finiteness, flat pairs and the signs from it".
#pragma once

#include "algorithms/exact/detail/pair_box.hpp"

#include <cstdint>
#include <cstring>

namespace tritri::exact::detail {

// The signs of the filter's six values (T1's against π2, then T2's against π1), each certain or
// exact: a value beyond the bound has the sign of its exact value, and on the grid every value is
// the exact one.
inline void value_signs(const double s1[3], const double s2[3], int known[6]) {
  // two at a time: (v < 0) - (v > 0) of the all-ones masks is sgn(v), NaN (0) included
  const Double2 v[3] = {{s1[0], s1[1]}, {s1[2], s2[0]}, {s2[1], s2[2]}};
  for (int k = 0; k < 3; ++k) {
    const Long2 s = (v[k] < 0.0) - (v[k] > 0.0);
    known[2 * k] = static_cast<int>(s[0]), known[2 * k + 1] = static_cast<int>(s[1]);
  }
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

}  // namespace tritri::exact::detail
