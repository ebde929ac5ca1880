// The production exact engine's determinants: signs of
//   det3(A0,A1, B0,B1, C0,C1) = det[A1-A0, B1-B0, C1-C0]   (orient3d is det3(a,b, a,c, a,d))
//   det2(a, b, c; i, j)       = (b-a)_i (c-a)_j - (b-a)_j (c-a)_i
// in integer arithmetic, for any finite doubles, without allocation. The integer types and the
// reasons for the three paths (fast, middle, wide) are in intarith.hpp.
#pragma once

#include "algorithms/exact/detail/intarith.hpp"

#include <cstdint>
#include <cstring>

namespace tritri::exact::intexact {

// The binary exponents of x's leading and last set bits (x finite, non-zero): |x| < 2^(lead+1)
// and x is a multiple of 2^last.
inline void bit_range(double x, int& lead, int& last) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  std::uint64_t mant = bits & ((std::uint64_t{1} << 52) - 1);
  int e0;  // exponent of mantissa bit 0
  if (biased == 0) {
    e0 = -1074;
  } else {
    mant |= std::uint64_t{1} << 52;
    e0 = biased - 1075;
  }
  last = e0 + __builtin_ctzll(mant);
  lead = e0 + 63 - __builtin_clzll(mant);
}

// ---------------------------------------------------------------- the determinants

// The exponent range of n split values s[0], s[stride], ...: q the lowest exponent of a last
// set bit, top the highest bound (|x| < 2^top); both 0 when every value is zero.
inline void exponent_range(const Split* s, int n, int stride, int& q, int& top) {
  q = 100000;
  top = -100000;
  for (int i = 0; i < n; ++i) {
    const Split& v = s[i * stride];
    if (v.mant == 0) continue;
    if (v.exp < q) q = v.exp;
    if (v.top > top) top = v.top;
  }
  if (top == -100000) q = 0, top = 0;
}

// det3's structural zeros: a column of equal coordinates, a zero row, or two rows from the
// same two points.
inline bool det3_structural_zero(const double* const p[6]) {
  auto same = [](const double* a, const double* b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; };
  for (int k = 0; k < 3; ++k)
    if (p[0][k] == p[1][k] && p[2][k] == p[3][k] && p[4][k] == p[5][k]) return true;
  for (int r = 0; r < 3; ++r)
    if (same(p[2 * r], p[2 * r + 1])) return true;
  for (int r = 0; r < 3; ++r)
    for (int t = r + 1; t < 3; ++t)
      if (same(p[2 * r], p[2 * t]) && same(p[2 * r + 1], p[2 * t + 1])) return true;
  return false;
}

// sign det[d[0], d[1], d[2]] of integer rows below 2^62 in magnitude: cross terms < 2^125 in
// __int128, the dot product < 2^189 in 192-bit two's complement.
inline int det3_rows_sign(const std::int64_t (&d)[3][3]) {
  I192 acc{{0, 0, 0}};
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const i128 m = static_cast<i128>(d[1][i]) * d[2][j] - static_cast<i128>(d[1][j]) * d[2][i];  // |m| < 2^125
    acc = add192(acc, mul_128_64(m, d[0][k]));                                               // |acc| < 2^189
  }
  return sign192(acc);
}

// The fast path: when every axis converts to integers below 2^61, sets sign and returns true.
inline bool det3_fast(const double* const p[6], int& sign) {
  std::int64_t x[3][6];  // x[axis][point]
  for (int k = 0; k < 3; ++k) {
    const double* v[6] = {&p[0][k], &p[1][k], &p[2][k], &p[3][k], &p[4][k], &p[5][k]};
    if (!axis_to_int61(v, 6, x[k])) return false;
  }
  ++counts().fast3;
  std::int64_t d[3][3];  // d[row][axis], |d| < 2^62
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) d[r][k] = x[k][2 * r + 1] - x[k][2 * r];
  sign = det3_rows_sign(d);
  return true;
}

// ---------------------------------------------------------------- one conversion per pair

// A pair's six points (18 coordinates, point v's axis k at c[3v + k]) converted once, axis by
// axis, as axis_to_int61 converts (one scale per axis, from the largest of the six values).
// Any positive scale per axis leaves a determinant's sign unchanged, so every det3 whose
// points are among the six is the fast path's determinant of these integers: each |x| < 2^61,
// so the differences, cross terms and dot product keep det3_fast's ranges, whichever four
// points it takes (algorithms/exact/README.md, "Zeros off the grid").
struct PairInt61 {
  std::int64_t x[3][6];  // x[axis][point]
};

// Loads the conversion; false when some axis has a span above 61 bits or a tiny maximum (then
// `out` is unusable and the caller takes the per-determinant engine).
inline bool pair_to_int61(const double* c, PairInt61& out) {
  for (int k = 0; k < 3; ++k) {
    const double* v[6] = {c + k, c + 3 + k, c + 6 + k, c + 9 + k, c + 12 + k, c + 15 + k};
    if (!axis_to_int61(v, 6, out.x[k])) return false;
  }
  return true;
}

// The same with each axis' largest |coordinate| over the six points given (`mag`, exact: the
// one-pair filter's box has it).
inline bool pair_to_int61(const double* c, const double (&mag)[3], PairInt61& out) {
  for (int k = 0; k < 3; ++k) {
    const double* v[6] = {c + k, c + 3 + k, c + 6 + k, c + 9 + k, c + 12 + k, c + 15 + k};
    if (!axis_to_int61_with_max(v, 6, mag[k], out.x[k])) return false;
  }
  return true;
}

// sign det[P1-P0, P3-P2, P5-P4] for the points with indices i[0..5] (0..5) of a converted pair.
inline int det3_pair_sign(const PairInt61& p, const int (&i)[6]) {
  ++counts().pair3;
  std::int64_t d[3][3];
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) d[r][k] = p.x[k][i[2 * r + 1]] - p.x[k][i[2 * r]];
  return det3_rows_sign(d);
}

// ---------------------------------------------------------------- the 40-bit tier

// A pair whose every coordinate along axis k is a multiple of 2^q_k, q_k = e_k - 39 for
// 2^e_k <= m_k < 2^(e_k+1) (m_k: the axis' largest |coordinate|, raised to 2^-1022 if below,
// below 2^1011), loaded into `out` as the integers x / 2^q_k, each below 2^40 in magnitude: one
// magic-number pass gives the test and the integers (y = x + C_k, C_k = 1.5·2^(q_k+52), lands in
// C_k's binade, where the spacing is 2^q_k). False when some coordinate is off its axis' unit or
// an axis' maximum is out of range; `out` is then unusable. Proof: algorithms/exact/README.md,
// "Zeros off the grid, 40 bits per axis".
inline bool pair_to_int40(const double* c, const double (&mag)[3], PairInt61& out) {
  using D2 = double __attribute__((vector_size(16)));
  using L2 = long long __attribute__((vector_size(16)));
  const double top = mag[0] > mag[1] ? mag[0] : mag[1];
  if (!((top > mag[2] ? top : mag[2]) < 0x1p1011)) return false;
  const D2 least = {0x1p-1022, 0x1p-1022};  // normal: its exponent field is e_k
  D2 mxy = {mag[0], mag[1]}, mz = {mag[2], mag[2]};
  mxy = mxy > least ? mxy : least;
  mz = mz > least ? mz : least;
  // C_k's bits: m_k's exponent field plus 13 (q_k + 52 = e_k + 13), and the bit below the leading one
  const L2 exponent = {0x7ff0000000000000ll, 0x7ff0000000000000ll}, up = {13ll << 52, 13ll << 52},
           half = {1ll << 51, 1ll << 51};
  const L2 cxy = ((reinterpret_cast<L2>(mxy) & exponent) + up) | half;
  const L2 cz = ((reinterpret_cast<L2>(mz) & exponent) + up) | half;
  const L2 big2[3] = {cxy, L2{cz[0], cxy[0]}, L2{cxy[1], cz[0]}};  // x y | z x | y z, repeated
  L2 ok = {-1, -1};
  for (int i = 0; i < 9; ++i) {
    D2 v;
    std::memcpy(&v, c + 2 * i, sizeof v);
    const D2 big = reinterpret_cast<D2>(big2[i % 3]);
    const D2 y = v + big;
    ok &= (y - big) == v;
    const L2 n = reinterpret_cast<L2>(y) - big2[i % 3];  // (y - C_k) / 2^q_k: one binade
    out.x[(2 * i) % 3][(2 * i) / 3] = n[0];
    out.x[(2 * i + 1) % 3][(2 * i + 1) / 3] = n[1];
  }
  return (ok[0] & ok[1]) != 0;
}

// sign det[P1-P0, P3-P2, P5-P4] for a pair loaded by pair_to_int40 (every |X| < 2^40): the
// differences below 2^41, a cofactor below 2^83, each term below 2^124 and their sum below 2^126,
// all in __int128.
inline int det3_pair40_sign(const PairInt61& p, const int (&i)[6]) {
  ++counts().pair40;
  std::int64_t d[3][3];
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) d[r][k] = p.x[k][i[2 * r + 1]] - p.x[k][i[2 * r]];
  i128 acc = 0;
  for (int k = 0; k < 3; ++k) {
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    const i128 m = static_cast<i128>(d[1][a]) * d[2][b] - static_cast<i128>(d[1][b]) * d[2][a];
    acc += m * d[0][k];
  }
  return (acc > 0) - (acc < 0);
}

// sign o2(a, b, v; i, j) = (b-a)_i (v-a)_j - (b-a)_j (v-a)_i for the points with indices a, b, v
// (0..5) of a converted pair: every |X| < 2^61, so the differences are below 2^62 (int64), the
// products below 2^124 and their difference below 2^125 (__int128). A positive scale per axis
// leaves the sign unchanged.
inline int det2_pair_sign(const PairInt61& p, int i, int j, int a, int b, int v) {
  ++counts().pair2;
  const std::int64_t bi = p.x[i][b] - p.x[i][a], bj = p.x[j][b] - p.x[j][a];
  const std::int64_t vi = p.x[i][v] - p.x[i][a], vj = p.x[j][v] - p.x[j][a];
  const i128 m = static_cast<i128>(bi) * vj - static_cast<i128>(bj) * vi;
  return (m > 0) - (m < 0);
}

// The middle path: |X| < 2^125, differences < 2^126 (__int128), cross terms < 2^253 (I256), the
// dot product < 2^381 (I384). s: the six points split, q: each axis's lowest exponent.
inline int det3_middle(const Split (&s)[6][3], const int (&q)[3]) {
  ++counts().middle3;
  i128 d[3][3];
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) d[r][k] = int128_from(s[2 * r + 1][k], q[k]) - int128_from(s[2 * r][k], q[k]);
  I384 acc{0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    add_product(acc, sub256(mul_wide(d[1][i], d[2][j]), mul_wide(d[1][j], d[2][i])), d[0][k]);
  }
  return sign384(acc);
}

// The wide path: any finite doubles, in Big.
inline int det3_wide(const Split (&s)[6][3], const int (&q)[3]) {
  ++counts().wide3;
  Big d[3][3];
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) {
      Big a, b;
      big_from(a, s[2 * r + 1][k], q[k]);
      big_from(b, s[2 * r][k], q[k]);
      big_add(a, b, true, d[r][k]);
    }
  Big buf[2], m1, m2, m, t;
  Big* acc = &buf[0];
  Big* next = &buf[1];
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    big_mul(d[1][i], d[2][j], m1);
    big_mul(d[1][j], d[2][i], m2);
    big_add(m1, m2, true, m);
    big_mul(m, d[0][k], t);
    big_add(*acc, t, false, *next);  // no copy of the limbs: swap the roles of the buffers
    Big* swap = acc;
    acc = next;
    next = swap;
  }
  return acc->n == 0 ? 0 : (acc->neg ? -1 : 1);
}

// sign det[A1-A0, B1-B0, C1-C0]; p: the six points (3 doubles each), finite.
inline int det3_sign(const double* const p[6]) {
  if (det3_structural_zero(p)) return ++counts().structural, 0;
  if (int sign; det3_fast(p, sign)) return sign;
  Split s[6][3];
  int q[3], top[3];
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 6; ++i) s[i][k] = split_double(p[i][k]);
    exponent_range(&s[0][k], 6, 3, q[k], top[k]);
  }
  if (top[0] - q[0] <= 125 && top[1] - q[1] <= 125 && top[2] - q[2] <= 125) return det3_middle(s, q);
  return det3_wide(s, q);
}

// sign of (b-a)_i (c-a)_j - (b-a)_j (c-a)_i.
inline int det2_sign(const double* a, const double* b, const double* c, int i, int j) {
  if ((a[i] == b[i] && a[j] == b[j]) || (a[i] == c[i] && a[j] == c[j]) || (b[i] == c[i] && b[j] == c[j]) ||
      (a[i] == b[i] && a[i] == c[i]) || (a[j] == b[j] && a[j] == c[j]))
    return ++counts().structural, 0;
  {
    std::int64_t x[2][3];
    const double* vi[3] = {&a[i], &b[i], &c[i]};
    const double* vj[3] = {&a[j], &b[j], &c[j]};
    if (axis_to_int61(vi, 3, x[0]) && axis_to_int61(vj, 3, x[1])) {
      ++counts().fast2;
      const std::int64_t bi = x[0][1] - x[0][0], bj = x[1][1] - x[1][0];
      const std::int64_t ci = x[0][2] - x[0][0], cj = x[1][2] - x[1][0];
      const i128 v = static_cast<i128>(bi) * cj - static_cast<i128>(bj) * ci;
      return (v > 0) - (v < 0);
    }
  }
  Split s[3][2];
  int q[2], top[2];
  const double* pts[3] = {a, b, c};
  for (int k = 0; k < 2; ++k) {
    const int axis = k == 0 ? i : j;
    for (int v = 0; v < 3; ++v) s[v][k] = split_double(pts[v][axis]);
    exponent_range(&s[0][k], 3, 2, q[k], top[k]);
  }
  if (top[0] - q[0] <= 125 && top[1] - q[1] <= 125) {
    ++counts().middle2;
    const i128 bi = int128_from(s[1][0], q[0]) - int128_from(s[0][0], q[0]);
    const i128 bj = int128_from(s[1][1], q[1]) - int128_from(s[0][1], q[1]);
    const i128 ci = int128_from(s[2][0], q[0]) - int128_from(s[0][0], q[0]);
    const i128 cj = int128_from(s[2][1], q[1]) - int128_from(s[0][1], q[1]);
    return sign256(sub256(mul_wide(bi, cj), mul_wide(bj, ci)));
  }
  ++counts().wide2;
  Big bi, bj, ci, cj, x, y, p1, p2, r;
  auto diff = [&](int v, int k, Big& out) {
    big_from(x, s[v][k], q[k]);
    big_from(y, s[0][k], q[k]);
    big_add(x, y, true, out);
  };
  diff(1, 0, bi);
  diff(1, 1, bj);
  diff(2, 0, ci);
  diff(2, 1, cj);
  big_mul(bi, cj, p1);
  big_mul(bj, ci, p2);
  big_add(p1, p2, true, r);
  return r.n == 0 ? 0 : (r.neg ? -1 : 1);
}

}  // namespace tritri::exact::intexact
