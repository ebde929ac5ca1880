// For the tests only: a second, independent exact engine (the algorithm uses intexact.hpp),
// exact signs of the two determinant forms every decision of the algorithm reduces to:
//
//   det3(A0,A1, B0,B1, C0,C1) = det[A1-A0, B1-B0, C1-C0]   (orient3d is det3(a,b, a,c, a,d))
//   det2(a, b, c; i, j)       = (b-a)_i (c-a)_j - (b-a)_j (c-a)_i
//
// for any finite double coordinates. Two engines, both written here:
//
//  1. Floating-point expansions (sums of non-overlapping doubles, in the style of Shewchuk's
//     adaptive predicates): each coordinate difference is an exact two-term expansion
//     (two_diff), products are formed with two_product and scale_expansion, sums with
//     grow_expansion, and the sign is the sign of the largest component. Exact only while no
//     intermediate underflows or overflows, so it is used only inside a window: after scaling
//     the involved coordinates by one power of two 2^s, every nonzero coordinate has magnitude
//     below 2^300 and is a multiple of 2^-300 (its last significant bit at or above 2^-300).
//     Then every product of up to three differences is a multiple of 2^-900 (> 2^-1074: no
//     bit is lost to underflow) and below 2^910 (no overflow), and the Veltkamp split (which
//     needs |x| < 2^995) never overflows. Scaling by 2^s is exact for every coordinate (the
//     scaled values stay normal), and it multiplies det3 by 2^(3s) and det2 by 2^(2s), so the
//     signs are unchanged.
//  2. GMP integers, for coordinates whose bit span does not fit the window (e.g. 1e300 next to
//     1e-300 in one determinant): every coordinate is an integer m·2^e, all are brought to
//     the smallest e, and the determinant is evaluated in mpz. Thread-local mpz temporaries,
//     initialised once: no allocation per call once they have grown.
//
// The expansion code must not be contracted into fused multiply-adds or reassociated: every
// product that feeds an error-free transformation passes through `opaque`, which the compiler
// cannot see through; -ffast-math is refused.
#pragma once

#include "algorithms/exact/detail/predicates.hpp"

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__FAST_MATH__)
#error "exact needs IEEE arithmetic: do not compile it with -ffast-math"
#endif

namespace tritri::exact::expansion {

// ---- counters of the exact engines (per thread; read by tests and the timing program) ----
struct EngineCounts {
  std::uint64_t expansion3 = 0, expansion2 = 0, gmp3 = 0, gmp2 = 0;
};
inline EngineCounts& engine_counts() {
  thread_local EngineCounts c;
  return c;
}

// A value the optimiser cannot look into: stops a product from being fused into a later
// addition (fp contraction), which would break the error-free transformations below.
inline double opaque(double x) {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
  __asm__("" : "+x"(x));
#elif defined(__GNUC__) && defined(__aarch64__)
  __asm__("" : "+w"(x));
#else
  volatile double v = x;
  x = v;
#endif
  return x;
}

// ---- error-free transformations ----

// s + e == a + b exactly, s = fl(a + b) (Knuth's TwoSum; no condition on the magnitudes).
inline void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bv = s - a;
  const double av = s - bv;
  e = (a - av) + (b - bv);
}

// s + e == a - b exactly, s = fl(a - b).
inline void two_diff(double a, double b, double& s, double& e) {
  s = a - b;
  const double bv = a - s;
  const double av = s + bv;
  e = (a - av) + (bv - b);
}

// Veltkamp's split: a == hi + lo, each with at most 26 significant bits (|a| < 2^995).
inline void split(double a, double& hi, double& lo) {
  const double c = opaque(134217729.0 * a);  // (2^27 + 1) a
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}

// p + e == a * b exactly, p = fl(a * b) (no underflow, |a|, |b| < 2^995).
inline void two_product(double a, double b, double& p, double& e) {
  p = opaque(a * b);
#if defined(__FMA__)
  e = std::fma(a, b, -p);
#else
  double ah, al, bh, bl;
  split(a, ah, al);
  split(b, bh, bl);
  // Every product of halves is exact (26 x 26 bits), so these subtractions are exact too.
  const double e1 = p - ah * bh;
  const double e2 = e1 - al * bh;
  const double e3 = e2 - ah * bl;
  e = al * bl - e3;
#endif
}

// ---- expansions: components in increasing magnitude, non-overlapping, zeros removed ----

// Room for the longest expansion met: det3 of three two-term differences is a sum of three
// products of a two-term value with a 16-term cross-product component: at most 3 x 64 terms.
constexpr int kMaxTerms = 192;

struct Expansion {
  int n = 0;
  double c[kMaxTerms];
  double sign_value() const { return n == 0 ? 0.0 : c[n - 1]; }
};

// h = e + b (Shewchuk's GROW-EXPANSION with zero elimination). h must not alias e.
inline int grow(int en, const double* e, double b, double* h) {
  double q = b;
  int hn = 0;
  for (int i = 0; i < en; ++i) {
    double s, t;
    two_sum(q, e[i], s, t);
    if (t != 0.0) h[hn++] = t;
    q = s;
  }
  if (q != 0.0 || hn == 0) h[hn++] = q;
  if (hn == 1 && h[0] == 0.0) hn = 0;
  return hn;
}

// out = e + f, by growing e with each component of f.
inline void add(const Expansion& e, const Expansion& f, Expansion& out) {
  Expansion a = e, b;
  for (int j = 0; j < f.n; ++j) {
    b.n = grow(a.n, a.c, f.c[j], b.c);
    a.n = b.n;
    std::memcpy(a.c, b.c, sizeof(double) * static_cast<std::size_t>(b.n));
  }
  out = a;
}

// h = e * b (Shewchuk's SCALE-EXPANSION, with TwoSum in place of FastTwoSum, zero elimination).
inline int scale(int en, const double* e, double b, double* h) {
  if (en == 0 || b == 0.0) return 0;
  double q, l;
  two_product(e[0], b, q, l);
  int hn = 0;
  if (l != 0.0) h[hn++] = l;
  for (int i = 1; i < en; ++i) {
    double big, small, s, t;
    two_product(e[i], b, big, small);
    two_sum(q, small, s, t);
    if (t != 0.0) h[hn++] = t;
    two_sum(big, s, q, t);
    if (t != 0.0) h[hn++] = t;
  }
  if (q != 0.0 || hn == 0) h[hn++] = q;
  if (hn == 1 && h[0] == 0.0) hn = 0;
  return hn;
}

// out = e * f for short f (a difference: one or two components).
inline void multiply(const Expansion& e, const Expansion& f, Expansion& out) {
  out.n = 0;
  Expansion part;
  for (int j = 0; j < f.n; ++j) {
    part.n = scale(e.n, e.c, f.c[j], part.c);
    Expansion sum;
    add(out, part, sum);
    out = sum;
  }
}

inline void negate(Expansion& e) {
  for (int i = 0; i < e.n; ++i) e.c[i] = -e.c[i];
}

inline Expansion difference(double a, double b) {
  Expansion d;
  double s, t;
  two_diff(a, b, s, t);
  d.n = 0;
  if (t != 0.0) d.c[d.n++] = t;
  if (s != 0.0) d.c[d.n++] = s;
  return d;
}

inline Expansion of(double a) {
  Expansion d;
  d.n = 0;
  if (a != 0.0) d.c[d.n++] = a;
  return d;
}

// x*y - z*w, each factor an expansion of at most two terms.
inline void cross_term(const Expansion& x, const Expansion& y, const Expansion& z, const Expansion& w,
                       Expansion& out) {
  Expansion p, q;
  multiply(x, y, p);
  multiply(z, w, q);
  negate(q);
  add(p, q, out);
}

inline int sign_of(double v) { return (v > 0.0) - (v < 0.0); }

// ---- the window ----

// The decoding of a double's bits is the engine's own (intarith.hpp, intexact.hpp); the
// arithmetic on them here is independent of it.
using intexact::bit_range;
using intexact::Split;
using intexact::split_double;

constexpr int kWindowTop = 300;     // after scaling, every |coordinate| < 2^300
constexpr int kWindowBottom = -300; // and every coordinate is a multiple of 2^-300

// The power of two that brings n coordinates into the window, or false when their bit span
// is too wide (or a coordinate is not finite).
inline bool window_shift(const double* const* c, int n, int& shift) {
  int top = -100000, bottom = 100000;
  for (int i = 0; i < n; ++i) {
    const double x = *c[i];
    if (x == 0.0) continue;
    if (!std::isfinite(x)) return false;
    int lead, last;
    bit_range(x, lead, last);
    top = std::max(top, lead + 1);  // |x| < 2^(lead+1)
    bottom = std::min(bottom, last);
  }
  if (top == -100000) {  // all zero
    shift = 0;
    return true;
  }
  if (top - bottom > kWindowTop - kWindowBottom) return false;
  if (top <= kWindowTop && bottom >= kWindowBottom) {
    shift = 0;
  } else {
    shift = -(top + bottom) / 2;  // centre the span in [-300, 300]
    if (top + shift > kWindowTop) shift = kWindowTop - top;
    if (bottom + shift < kWindowBottom) shift = kWindowBottom - bottom;
  }
  return true;
}

// ---- GMP ----

struct GmpScratch {
  static constexpr int kCount = 24;
  mpz_t z[kCount];
  GmpScratch() {
    for (auto& x : z) mpz_init2(x, 256);
  }
  ~GmpScratch() {
    for (auto& x : z) mpz_clear(x);
  }
  GmpScratch(const GmpScratch&) = delete;
  GmpScratch& operator=(const GmpScratch&) = delete;
};
inline GmpScratch& gmp_scratch() {
  thread_local GmpScratch s;
  return s;
}

// out = x · 2^-base, an integer because every coordinate's last set bit is at or above base.
inline void to_mpz(mpz_t out, double x, int base) {
  const Split s = split_double(x);  // x = mant·2^exp, mant odd; 0 when x is
  mpz_set_ui(out, static_cast<unsigned long>(s.mant >> 32));
  mpz_mul_2exp(out, out, 32);
  mpz_add_ui(out, out, static_cast<unsigned long>(s.mant & 0xffffffffu));
  if (s.mant == 0) return;
  mpz_mul_2exp(out, out, static_cast<mp_bitcnt_t>(s.exp - base));
  if (s.neg) mpz_neg(out, out);
}

inline int lowest_bit(const double* const* c, int n) {
  int bottom = 100000;
  for (int i = 0; i < n; ++i) {
    if (*c[i] == 0.0) continue;
    int lead, last;
    bit_range(*c[i], lead, last);
    bottom = std::min(bottom, last);
  }
  return bottom == 100000 ? 0 : bottom;
}

// sign det[A1-A0, B1-B0, C1-C0] with GMP. p: the six points, each 3 coordinates.
inline int det3_sign_gmp(const double* const p[6]) {
  ++engine_counts().gmp3;
  const double* c[18];
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 3; ++k) c[3 * i + k] = &p[i][k];
  const int base = lowest_bit(c, 18);
  GmpScratch& g = gmp_scratch();
  mpz_t* z = g.z;
  // z[0..8]: the three difference vectors; z[9..11] their cross terms; z[12] the sum.
  for (int v = 0; v < 3; ++v)
    for (int k = 0; k < 3; ++k) {
      to_mpz(z[20], p[2 * v + 1][k], base);
      to_mpz(z[21], p[2 * v][k], base);
      mpz_sub(z[3 * v + k], z[20], z[21]);
    }
  mpz_t *a = &z[0], *b = &z[3], *cc = &z[6];
  // m = b x c
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    mpz_mul(z[20], b[i], cc[j]);
    mpz_mul(z[21], b[j], cc[i]);
    mpz_sub(z[9 + k], z[20], z[21]);
  }
  mpz_set_ui(z[12], 0);
  for (int k = 0; k < 3; ++k) mpz_addmul(z[12], a[k], z[9 + k]);
  return mpz_sgn(z[12]);
}

// sign of (b-a)_i (c-a)_j - (b-a)_j (c-a)_i with GMP.
inline int det2_sign_gmp(const double* a, const double* b, const double* c, int i, int j) {
  ++engine_counts().gmp2;
  const double* cs[6] = {&a[i], &a[j], &b[i], &b[j], &c[i], &c[j]};
  const int base = lowest_bit(cs, 6);
  mpz_t* z = gmp_scratch().z;
  for (int k = 0; k < 6; ++k) to_mpz(z[k], *cs[k], base);
  mpz_sub(z[6], z[2], z[0]);  // (b-a)_i
  mpz_sub(z[7], z[3], z[1]);  // (b-a)_j
  mpz_sub(z[8], z[4], z[0]);  // (c-a)_i
  mpz_sub(z[9], z[5], z[1]);  // (c-a)_j
  mpz_mul(z[10], z[6], z[9]);
  mpz_mul(z[11], z[7], z[8]);
  return mpz_cmp(z[10], z[11]) > 0 ? 1 : (mpz_cmp(z[10], z[11]) < 0 ? -1 : 0);
}

// ---- expansion engine ----

// sign det[A1-A0, B1-B0, C1-C0] by expansions; the coordinates are already in the window.
inline int det3_sign_expansion_scaled(const double* const p[6]) {
  Expansion d[3][3];  // d[v][k]: component k of difference vector v
  for (int v = 0; v < 3; ++v)
    for (int k = 0; k < 3; ++k) d[v][k] = difference(p[2 * v + 1][k], p[2 * v][k]);
  Expansion total;
  total.n = 0;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    if (d[0][k].n == 0) continue;
    Expansion m, term, sum;
    cross_term(d[1][i], d[2][j], d[1][j], d[2][i], m);
    multiply(m, d[0][k], term);
    add(total, term, sum);
    total = sum;
  }
  return sign_of(total.sign_value());
}

inline int det2_sign_expansion_scaled(const double* a, const double* b, const double* c, int i, int j) {
  const Expansion bi = difference(b[i], a[i]), bj = difference(b[j], a[j]);
  const Expansion ci = difference(c[i], a[i]), cj = difference(c[j], a[j]);
  Expansion out;
  cross_term(bi, cj, bj, ci, out);
  return sign_of(out.sign_value());
}

// ---- the exact signs: window -> expansions, else GMP ----

inline int det3_sign(const double* const p[6]) {
  const double* c[18];
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 3; ++k) c[3 * i + k] = &p[i][k];
  int shift;
  if (!window_shift(c, 18, shift)) return det3_sign_gmp(p);
  ++engine_counts().expansion3;
  if (shift == 0) return det3_sign_expansion_scaled(p);
  double q[6][3];
  const double* qp[6];
  for (int i = 0; i < 6; ++i) {
    for (int k = 0; k < 3; ++k) q[i][k] = std::ldexp(p[i][k], shift);
    qp[i] = q[i];
  }
  return det3_sign_expansion_scaled(qp);
}

inline int det2_sign(const double* a, const double* b, const double* c, int i, int j) {
  const double* cs[6] = {&a[i], &a[j], &b[i], &b[j], &c[i], &c[j]};
  int shift;
  if (!window_shift(cs, 6, shift)) return det2_sign_gmp(a, b, c, i, j);
  ++engine_counts().expansion2;
  if (shift == 0) return det2_sign_expansion_scaled(a, b, c, i, j);
  double q[3][3] = {};
  for (int k : {i, j}) {
    q[0][k] = std::ldexp(a[k], shift);
    q[1][k] = std::ldexp(b[k], shift);
    q[2][k] = std::ldexp(c[k], shift);
  }
  return det2_sign_expansion_scaled(q[0], q[1], q[2], i, j);
}

}  // namespace tritri::exact::expansion

namespace tritri::exact {

// The predicate policy on this engine, for classify<Exact, ...> in the tests: an independent
// implementation to cross-check the integer engine of the algorithm (IntExact).
using Exact = ExactSigns<expansion::det3_sign, expansion::det2_sign>;

}  // namespace tritri::exact
