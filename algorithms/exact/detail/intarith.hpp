// The production exact engine: signs of det3 and det2 (the forms: intexact.hpp) in integer
// arithmetic, for any finite doubles, without allocation.
//
// Every finite double is m·2^e with an integer m. A determinant's sign is unchanged when one
// of its columns (one axis: x, y or z) is multiplied by a positive number, so each axis a is
// scaled by its own 2^-q_a, q_a = the lowest set bit among the a-coordinates involved: the
// scaled coordinates are integers below 2^s_a in magnitude (s_a = the axis' bit span).
//   fast path  every axis scales to integers below 2^61 (axis_to_int61: x·2^(61-top) is an
//              integer for every value; i.e. a bit span of at most 61): differences fit int64
//              (< 2^62), the cross-product components (< 2^125) fit __int128, and the dot
//              product (< 2^189) is accumulated in 192-bit two's complement.
//   middle     every span <= 125: differences below 2^126 in __int128, products in 128-bit halves
//              (256 bits), the dot product in three (384).
//   wide path  any span: sign-magnitude multi-limb integers (64-bit limbs, schoolbook
//              products) in fixed stack buffers; spans up to the whole double range (2098
//              bits -> 33 limbs per coordinate, 100 per triple product).
// Exact zeros that need no arithmetic are caught first (Filtered calls this engine only when
// its bound does not decide): a difference column or row that is exactly zero, or two equal
// rows given by the same pair of points.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

namespace tritri::exact::intexact {

struct Counts {
  std::uint64_t fast3 = 0, middle3 = 0, wide3 = 0, fast2 = 0, middle2 = 0, wide2 = 0, structural = 0;
  std::uint64_t pair3 = 0;  // det3 signs from a pair's shared conversion (det3_pair_sign)
  std::uint64_t pair2 = 0;  // det2 signs from it (det2_pair_sign)
  std::uint64_t pair40 = 0;  // det3 signs from a pair's 40-bit conversion (det3_pair40_sign)
};
inline Counts& counts() {
  thread_local Counts c;
  return c;
}

// x = mant·2^exp with mant odd (or x == 0: mant 0). Finite x only.
struct Split {
  std::uint64_t mant;
  int exp;  // exponent of the last set bit
  int top;  // |x| < 2^top
  bool neg;
};

inline Split split_double(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  Split s{0, 0, -100000, (bits >> 63) != 0};
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  std::uint64_t m = bits & ((std::uint64_t{1} << 52) - 1);
  int e0;
  if (biased == 0) {
    if (m == 0) return s;
    e0 = -1074;
  } else {
    m |= std::uint64_t{1} << 52;
    e0 = biased - 1075;
  }
  const int tz = __builtin_ctzll(m);
  s.mant = m >> tz;
  s.exp = e0 + tz;
  s.top = e0 + 64 - __builtin_clzll(m);
  return s;
}

// ---------------------------------------------------------------- fast path

using i128 = __int128;
using u128 = unsigned __int128;

struct I192 {
  std::uint64_t w[3];  // two's complement, little-endian words
};

// m·u in 192-bit two's complement, without a branch on the signs (a branch on the sign of a
// random determinant's term is mispredicted half the time). With m = mh·2^64 + ml (mh signed,
// ml unsigned): m·u = mh·u·2^64 + ml·u, and ml·u = ml·(u mod 2^64) - [u < 0]·ml·2^64.
inline I192 mul_128_64(i128 m, std::int64_t u) {
  const std::uint64_t ml = static_cast<std::uint64_t>(m);
  const std::int64_t mh = static_cast<std::int64_t>(m >> 64);
  const u128 lo = static_cast<u128>(ml) * static_cast<std::uint64_t>(u);
  const std::uint64_t corr = ml & static_cast<std::uint64_t>(u >> 63);  // ml if u < 0, else 0
  const i128 hi = static_cast<i128>(mh) * u;                            // |hi| < 2^127
  const i128 up = static_cast<i128>(lo >> 64) - static_cast<i128>(corr) + hi;  // the value >> 64
  I192 r;
  r.w[0] = static_cast<std::uint64_t>(lo);
  r.w[1] = static_cast<std::uint64_t>(up);
  r.w[2] = static_cast<std::uint64_t>(up >> 64);
  return r;
}

inline I192 add192(const I192& a, const I192& b) {
  I192 r;
  const u128 s0 = static_cast<u128>(a.w[0]) + b.w[0];
  r.w[0] = static_cast<std::uint64_t>(s0);
  const u128 s1 = static_cast<u128>(a.w[1]) + b.w[1] + static_cast<std::uint64_t>(s0 >> 64);
  r.w[1] = static_cast<std::uint64_t>(s1);
  r.w[2] = a.w[2] + b.w[2] + static_cast<std::uint64_t>(s1 >> 64);
  return r;
}

inline int sign192(const I192& a) {
  if (a.w[2] >> 63) return -1;
  return (a.w[0] | a.w[1] | a.w[2]) != 0 ? 1 : 0;
}

// The scaled integer of x for axis bottom q (x a multiple of 2^q, |x| < 2^(q+62)).
inline std::int64_t scaled64(const Split& s, int q) {
  if (s.mant == 0) return 0;
  const std::int64_t v = static_cast<std::int64_t>(s.mant << (s.exp - q));
  return s.neg ? -v : v;
}

// Fast conversion of one axis: the n values as integers X_i = x_i·2^(61-top) where
// 2^(top-1) <= max|x_i| < 2^top, when every x_i is a multiple of 2^(top-61) (then |X_i| < 2^61).
// False when some x_i is not (its bits reach below 2^(top-61): the span exceeds 61) or when
// the scale 2^(61-top) is not a normal double (tiny maxima): the caller takes the general path.
// `m` is max|x_i| (+0 or -0 when all are zero), from the caller when it already has it.
inline bool axis_to_int61_with_max(const double* const* v, int n, double m, std::int64_t* x) {
  if (m == 0.0) {
    for (int i = 0; i < n; ++i) x[i] = 0;
    return true;
  }
  std::uint64_t bits;
  std::memcpy(&bits, &m, sizeof bits);
  const int e = static_cast<int>(bits >> 52);                 // biased exponent of m (m > 0, finite)
  if (e < 62) return false;                                   // 2^(61-top) would not be normal
  const std::uint64_t scale_bits = static_cast<std::uint64_t>(61 - (e - 1022) + 1023) << 52;
  double scale;
  std::memcpy(&scale, &scale_bits, sizeof scale);
  // s = x·scale is exact unless it underflows, and |s| < 2^61: it is an integer exactly when
  // truncating it to int64 and back gives s. The misses |double(X) - s| are summed: none is
  // negative and a non-zero difference of doubles is never 0, so the sum is 0 exactly when
  // every s is an integer (no branch per value). With scale >= 1 nothing underflows; below it a
  // non-zero x whose s underflowed to 0 is refused as well.
  double miss = 0.0;
  for (int i = 0; i < n; ++i) {
    const double s = *v[i] * scale;
    x[i] = static_cast<std::int64_t>(s);
    miss += std::fabs(static_cast<double>(x[i]) - s);
  }
  if (scale < 1.0)
    for (int i = 0; i < n; ++i) miss += static_cast<double>((x[i] == 0) & (*v[i] != 0.0));
  return miss == 0.0;
}

inline bool axis_to_int61(const double* const* v, int n, std::int64_t* x) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) {
    const double a = *v[i] < 0 ? -*v[i] : *v[i];
    m = a > m ? a : m;
  }
  return axis_to_int61_with_max(v, n, m, x);
}

// ---------------------------------------------------------------- middle path: 128-bit halves

// Two's complement integers in 128-bit halves: the compiler's add/adc and mul pairs, no limb loops
// (algorithms/exact/README.md, "The middle path in 128-bit halves").
struct I256 {  // hi·2^128 + lo
  u128 lo;
  i128 hi;
};
struct I384 {  // w2·2^256 + w1·2^128 + w0
  u128 w0, w1;
  i128 w2;
};

// a·b exactly, for any a and |b| < 2^126. With a = ah·2^64 + al (ah signed, al unsigned) and b
// likewise: a·b = ah·bh·2^128 + (ah·bl + bh·al)·2^64 + al·bl, where |ah·bl| <= 2^63·(2^64 - 1) and
// |bh·al| < 2^126 fit __int128; the middle terms' low words and al·bl's high word sum below 3·2^64.
inline I256 mul_wide(i128 a, i128 b) {
  const std::uint64_t al = static_cast<std::uint64_t>(a), bl = static_cast<std::uint64_t>(b);
  const std::int64_t ah = static_cast<std::int64_t>(a >> 64), bh = static_cast<std::int64_t>(b >> 64);
  const u128 t0 = static_cast<u128>(al) * bl;
  const i128 t1 = static_cast<i128>(ah) * static_cast<i128>(bl), t2 = static_cast<i128>(bh) * static_cast<i128>(al);
  const u128 mid = (t0 >> 64) + static_cast<std::uint64_t>(t1) + static_cast<std::uint64_t>(t2);
  I256 r;
  r.lo = static_cast<u128>(static_cast<std::uint64_t>(t0)) | (mid << 64);
  r.hi = static_cast<i128>(ah) * bh + (t1 >> 64) + (t2 >> 64) + static_cast<i128>(mid >> 64);
  return r;
}

inline I256 sub256(const I256& a, const I256& b) {
  return {a.lo - b.lo, a.hi - b.hi - static_cast<i128>(a.lo < b.lo)};
}

inline int sign256(const I256& a) { return a.hi < 0 ? -1 : ((a.hi != 0) | (a.lo != 0)); }

// acc += v·2^128 (v signed: its sign extended into w2).
inline void add_at128(I384& acc, i128 v) {
  const u128 w1 = acc.w1 + static_cast<u128>(v);
  acc.w2 += static_cast<i128>(w1 < acc.w1) - static_cast<i128>(v < 0);
  acc.w1 = w1;
}

// acc += m·d for |m| < 2^254 and |d| < 2^126: m·d = m.hi·d·2^128 + m.lo·d, and m.lo (unsigned) is
// the signed lo + 2^128 where its top bit is set, so m.lo·d = mul_wide(lo, d) + [top bit]·d·2^128.
inline void add_product(I384& acc, const I256& m, i128 d) {
  const I256 low = mul_wide(static_cast<i128>(m.lo), d), high = mul_wide(m.hi, d);
  const u128 w0 = acc.w0 + low.lo;
  add_at128(acc, low.hi);
  add_at128(acc, static_cast<i128>(w0 < acc.w0));  // the carry out of w0
  acc.w0 = w0;
  add_at128(acc, static_cast<i128>(m.lo >> 127) * d);
  const u128 w1 = acc.w1 + high.lo;
  acc.w2 += high.hi + static_cast<i128>(w1 < acc.w1);
  acc.w1 = w1;
}

inline int sign384(const I384& a) { return a.w2 < 0 ? -1 : ((a.w2 != 0) | (a.w1 != 0) | (a.w0 != 0)); }

// x·2^-q (x a multiple of 2^q, |x| < 2^(q+125)).
inline i128 int128_from(const Split& s, int q) {
  const i128 v = s.mant == 0 ? 0 : static_cast<i128>(static_cast<u128>(s.mant) << (s.exp - q));
  return s.neg ? -v : v;
}

// ---------------------------------------------------------------- wide path

// Sign-magnitude integer with up to kCap 64-bit limbs.
struct Big {
  static constexpr int kCap = 104;
  int n = 0;  // limbs in use (no leading zero limbs)
  bool neg = false;
  std::uint64_t d[kCap];
};

inline void trim(Big& a) {
  while (a.n > 0 && a.d[a.n - 1] == 0) --a.n;
  if (a.n == 0) a.neg = false;
}

inline void big_from(Big& out, const Split& s, int q) {
  out.n = 0;
  out.neg = s.neg;
  if (s.mant == 0) {
    out.neg = false;
    return;
  }
  const int shift = s.exp - q;  // >= 0
  const int limb = shift / 64, bit = shift % 64;
  for (int i = 0; i < limb; ++i) out.d[i] = 0;
  out.d[limb] = s.mant << bit;
  out.d[limb + 1] = bit == 0 ? 0 : s.mant >> (64 - bit);
  out.n = limb + 2;
  trim(out);
}

inline int cmp_mag(const Big& a, const Big& b) {
  if (a.n != b.n) return a.n < b.n ? -1 : 1;
  for (int i = a.n - 1; i >= 0; --i)
    if (a.d[i] != b.d[i]) return a.d[i] < b.d[i] ? -1 : 1;
  return 0;
}

// out = |a| + |b| (magnitudes), sign left to the caller
inline void add_mag(const Big& a, const Big& b, Big& out) {
  const int n = a.n > b.n ? a.n : b.n;
  std::uint64_t carry = 0;
  for (int i = 0; i < n; ++i) {
    const u128 s = static_cast<u128>(i < a.n ? a.d[i] : 0) + (i < b.n ? b.d[i] : 0) + carry;
    out.d[i] = static_cast<std::uint64_t>(s);
    carry = static_cast<std::uint64_t>(s >> 64);
  }
  out.n = n;
  if (carry) out.d[out.n++] = carry;
}

// out = |a| - |b|, requires |a| >= |b|
inline void sub_mag(const Big& a, const Big& b, Big& out) {
  std::uint64_t borrow = 0;
  for (int i = 0; i < a.n; ++i) {
    const std::uint64_t bi = i < b.n ? b.d[i] : 0;
    const std::uint64_t t = a.d[i] - bi;
    const std::uint64_t nb = (a.d[i] < bi) || (t < borrow);
    out.d[i] = t - borrow;
    borrow = nb;
  }
  out.n = a.n;
  trim(out);
}

// out = a + (negate_b ? -b : b); out may not alias a or b
inline void big_add(const Big& a, const Big& b, bool negate_b, Big& out) {
  const bool bneg = b.n != 0 && (b.neg != negate_b);
  if (a.neg == bneg) {
    add_mag(a, b, out);
    out.neg = a.neg;
  } else if (cmp_mag(a, b) >= 0) {
    sub_mag(a, b, out);
    out.neg = a.neg;
  } else {
    sub_mag(b, a, out);
    out.neg = bneg;
  }
  trim(out);
}

inline void big_mul(const Big& a, const Big& b, Big& out) {
  if (a.n == 0 || b.n == 0) {
    out.n = 0;
    out.neg = false;
    return;
  }
  const int n = a.n + b.n;
  for (int i = 0; i < n; ++i) out.d[i] = 0;
  for (int i = 0; i < a.n; ++i) {
    std::uint64_t carry = 0;
    for (int j = 0; j < b.n; ++j) {
      const u128 t = static_cast<u128>(a.d[i]) * b.d[j] + out.d[i + j] + carry;
      out.d[i + j] = static_cast<std::uint64_t>(t);
      carry = static_cast<std::uint64_t>(t >> 64);
    }
    out.d[i + b.n] = carry;
  }
  out.n = n;
  out.neg = a.neg != b.neg;
  trim(out);
}

}  // namespace tritri::exact::intexact
