// The front of one_pair.hpp's `finish` for pairs whose values are exact: the grid test made
// before the finiteness test and the flat test (a pass proves both unnecessary), the six signs
// read from the filter's values at once, as bits. Proved in algorithms/exact/README.md, "The grid test
// first: finiteness, flat pairs and the signs from it".
#pragma once

#include "algorithms/exact/detail/pair_box.hpp"

#include <cstring>

namespace tritri::exact::detail {

// The grid test axis by axis: each axis k its own unit 2^q_k, q_k = e_k - 14 for 2^e_k <= m_k <
// 2^(e_k+1), m_k = max(the axis' largest |coordinate|, 2^-344) below 2^300, and every coordinate x
// along k a multiple of 2^q_k: fl(fl(x + C_k) - C_k) = x with C_k = 1.5·2^(q_k+52) built from m_k's
// exponent bits. Every monomial of a det3 or det2 of the pair's points takes one factor per axis,
// so all of a value's terms share one unit and every value the filter computed is exact
// (algorithms/exact/README.md, "The grid case, axis by axis"); a pair on the kernel's grid (one q
// for all axes) passes it. `mag`: each axis' largest |coordinate| (box_magnitudes, finite input).
inline bool on_grid(const double* c, const double (&mag)[3]) {
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
  Long2 grid = {-1, -1};
  for (int i = 0; i < 9; ++i) {
    Double2 v;
    std::memcpy(&v, c + 2 * i, sizeof v);
    grid &= (v + big2[i % 3]) - big2[i % 3] == v;
  }
  return all2(grid);
}

// Six signs as bits: bit k of pos (neg) set where sign k is positive (negative), k = 0..2 T1's
// vertices against π2, 3..5 T2's against π1. `finish` decides on these (one_sided, the crossing
// step's kCanon row, the zeros) with a mask operation each.
struct SignBits {
  unsigned pos, neg;
};

// The signs of the filter's six values (T1's against π2, then T2's against π1), each certain or
// exact (a value beyond the bound has the sign of its exact value, and on the grid every value is
// the exact one), as bits: ordered comparisons with 0 (false for NaN: no bit), two values per
// comparison and one movmskpd each, where six ints had cost a conversion each and every later test
// a comparison per sign.
inline SignBits value_sign_bits(const double s1[3], const double s2[3]) {
  const Double2 v[3] = {{s1[0], s1[1]}, {s1[2], s2[0]}, {s2[1], s2[2]}}, zero = {0.0, 0.0};
#if defined(__SSE2__)
  // four masks' bits at once: the low halves of two comparisons' lanes (each lane all ones or all
  // zeros) side by side, then one movmskps
  const auto four = [](__m128d a, __m128d b) {
    return static_cast<unsigned>(_mm_movemask_ps(_mm_shuffle_ps(_mm_castpd_ps(a), _mm_castpd_ps(b), 0x88)));
  };
  const auto lt = [](Double2 a, Double2 b) { return _mm_cmplt_pd(reinterpret_cast<__m128d>(a), reinterpret_cast<__m128d>(b)); };
  return {four(lt(zero, v[0]), lt(zero, v[1])) | lt2(zero, v[2]) << 4, four(lt(v[0], zero), lt(v[1], zero)) | lt2(v[2], zero) << 4};
#else
  return {lt2(zero, v[0]) | lt2(zero, v[1]) << 2 | lt2(zero, v[2]) << 4,
          lt2(v[0], zero) | lt2(v[1], zero) << 2 | lt2(v[2], zero) << 4};
#endif
}

// The bits of three exact signs (-1, 0, 1), placed at bits at, at + 1, at + 2.
inline SignBits sign_bits(const int (&s)[3], int at) {
  SignBits b{0, 0};
  for (int k = 0; k < 3; ++k) b.pos |= static_cast<unsigned>(s[k] > 0) << (at + k), b.neg |= static_cast<unsigned>(s[k] < 0) << (at + k);
  return b;
}

// The six signs as ints (the classification's form) from their bits.
inline void signs_of_bits(SignBits b, int known[6]) {
  for (int k = 0; k < 6; ++k) known[k] = static_cast<int>(b.pos >> k & 1u) - static_cast<int>(b.neg >> k & 1u);
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
