// The one-pair path's grid test, axis by axis, and, when the pair fails it, which of its six points
// are on that grid (algorithms/exact/README.md, "The grid case, axis by axis" and "A value's own
// points on the grid"). Asked through one_pair.hpp's LazyGrid.
#pragma once

#include "algorithms/exact/detail/pair_box.hpp"

#include <array>
#include <cstring>

namespace tritri::exact::detail {

// The grid test's nine comparisons: on[i] for coordinates 2i and 2i + 1, each fl(fl(x + C_k) - C_k)
// = x with C_k = 1.5·2^(q_k+52) built from m_k's exponent bits; false (on[] unset) when an axis is
// out of range (m_k at least 2^300, or NaN). `mag`: each axis' largest |coordinate|.
[[gnu::always_inline]] inline bool grid_comparisons(const double* c, const double (&mag)[3], Long2 (&on)[9]) {
  const Double2 mxy = {mag[0], mag[1]}, mz = {mag[2], mag[2]}, top = {0x1p300, 0x1p300}, least = {0x1p-344, 0x1p-344};
  if ((lt2(mxy, top) & lt2(mz, top)) != 3u) return false;  // one branch; false for NaN
  // C_k from max(m_k, 2^-344)'s exponent bits, x and y in one register: the exponent plus 38, and
  // the bit below the leading one
  const Long2 exponent = {0x7ff0000000000000ll, 0x7ff0000000000000ll}, up = {38ll << 52, 38ll << 52},
              half = {1ll << 51, 1ll << 51};
  const Double2 cxy = reinterpret_cast<Double2>(((reinterpret_cast<Long2>(max2(mxy, least)) & exponent) + up) | half);
  const Double2 cz = reinterpret_cast<Double2>(((reinterpret_cast<Long2>(max2(mz, least)) & exponent) + up) | half);
  // two coordinates at a time, read once: x y | z x | y z, three times over
  const Double2 big2[3] = {cxy, Double2{cz[0], cxy[0]}, Double2{cxy[1], cz[0]}};
  for (int i = 0; i < 9; ++i) {
    Double2 v;
    std::memcpy(&v, c + 2 * i, sizeof v);
    on[i] = (v + big2[i % 3]) - big2[i % 3] == v;
  }
  return true;
}

// m where the six-bit mask m has four bits or more, else 0: a det3 takes four points.
inline constexpr auto kFourOrMore = [] {
  std::array<unsigned char, 64> t{};
  for (unsigned m = 0; m < 64; ++m) t[m] = static_cast<unsigned char>(__builtin_popcount(m) >= 4 ? m : 0u);
  return t;
}();

// From the grid test's nine comparisons: bit p set where point p's three coordinates are on the
// grid, kept only when four points or more are (algorithms/exact/README.md, "A value's own points
// on the grid"). Fewer than 12 coordinates on it leave fewer than four points: counted first (the
// masks are -1 or 0 per lane), as most pairs off the grid have few. Points 2t and 2t + 1 are
// coordinates 6t..6t + 5, on[3t..3t + 2]: lane 0 of x & y & z takes point 2t's three, lane 1
// point 2t + 1's.
inline unsigned grid_points(const Long2 (&on)[9]) {
  Long2 n = on[0];
  for (int i = 1; i < 9; ++i) n += on[i];
  if (n[0] + n[1] > -12) return 0u;
  unsigned bits = 0u;
  for (int t = 0; t < 3; ++t) {
    const Long2 a = on[3 * t], b = on[3 * t + 1], cc = on[3 * t + 2];
    const Long2 x = __builtin_shufflevector(a, b, 0, 3), y = __builtin_shufflevector(a, cc, 1, 2),
                z = __builtin_shufflevector(b, cc, 0, 3);
    bits |= mask_bits2(x & y & z) << 2 * t;
  }
  return kFourOrMore[bits];
}

// The grid test axis by axis: each axis k its own unit 2^q_k, q_k = e_k - 14 for 2^e_k <= m_k <
// 2^(e_k+1), m_k = max(the axis' largest |coordinate|, 2^-344) below 2^300, and every coordinate x
// along k a multiple of 2^q_k (grid_comparisons). Every monomial of a det3 or det2 of the pair's
// points takes one factor per axis, so all of a value's terms share one unit and every value the
// filter computed is exact (algorithms/exact/README.md, "The grid case, axis by axis"); a pair on
// the kernel's grid (one q for all axes) passes it. `mag`: box_magnitudes (finite input). When it
// fails, `points` is grid_points' mask (0 when an axis is out of range), made from the comparisons
// still in registers.
inline bool on_grid(const double* c, const double (&mag)[3], unsigned& points, bool want_points = true) {
  points = 0u;
  Long2 on[9];
  if (!grid_comparisons(c, mag, on)) return false;
  Long2 grid = on[0];
  for (int i = 1; i < 9; ++i) grid &= on[i];
  if (all2(grid)) return true;
  if (want_points) points = grid_points(on);
  return false;
}

// The bits of grid_points' mask for the points with indices a, b, cc, d (0..5).
inline unsigned point_bits(int a, int b, int cc, int d) { return 1u << a | 1u << b | 1u << cc | 1u << d; }

}  // namespace tritri::exact::detail
