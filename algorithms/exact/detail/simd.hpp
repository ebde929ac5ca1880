// The ISA wrappers and one instance of kernel.inc per instruction set:
//   sse2    2 lanes, the x86-64 baseline, compiled with the translation unit's own flags
//   avx2    4 lanes, compiled under target("avx2") (no FMA is enabled: not that it would
//           matter, every bound holds with or without fused operations, algorithms/exact/README.md)
//   avx512  8 lanes, target("avx512f")
// Each instance lives in its own namespace and target region, so no function compiled for a
// wider instruction set can be merged with (or picked instead of) a baseline one by the linker.
// Chosen at run time by __builtin_cpu_supports (dispatch in exactsimd.hpp).
#pragma once

#include "algorithms/exact/detail/predicates.hpp"
#include "tritri/answers.hpp"

#include <cstddef>
#include <cstdint>

// Lane counts up to which a block with no crossing lane skips the interval stage (a branch).
#if !defined(EXACTSIMD_SKIP_EMPTY_GD_MAX_LANES)
#define EXACTSIMD_SKIP_EMPTY_GD_MAX_LANES 4
#endif

#if (defined(__x86_64__) || defined(_M_X64)) && (defined(__GNUC__) || defined(__clang__)) && \
    !defined(EXACTSIMD_NO_SIMD)
#define EXACTSIMD_X86 1
#include <immintrin.h>
#else
#define EXACTSIMD_X86 0
#endif

namespace tritri::exactsimd {
// Set on an index handed from the second SIMD pass to the scalar pass: the pair is on the grid.
inline constexpr std::uint32_t kGridFlag = 0x80000000u;
}  // namespace tritri::exactsimd

#if EXACTSIMD_X86

// ---------------------------------------------------------------- SSE2 (baseline)
namespace tritri::exactsimd::isa_sse2 {
struct I {
  static constexpr int W = 2;
  using D = __m128d;
  using M = __m128d;
  static D set1(double x) { return _mm_set1_pd(x); }
  static D add(D a, D b) { return _mm_add_pd(a, b); }
  static D sub(D a, D b) { return _mm_sub_pd(a, b); }
  static D mul(D a, D b) { return _mm_mul_pd(a, b); }
  static D min(D a, D b) { return _mm_min_pd(a, b); }
  static D max(D a, D b) { return _mm_max_pd(a, b); }
  static D abs(D a) { return _mm_andnot_pd(_mm_set1_pd(-0.0), a); }
  static M gt(D a, D b) { return _mm_cmpgt_pd(a, b); }
  static M lt(D a, D b) { return _mm_cmplt_pd(a, b); }
  static M le(D a, D b) { return _mm_cmple_pd(a, b); }
  static M mand(M a, M b) { return _mm_and_pd(a, b); }
  static M mor(M a, M b) { return _mm_or_pd(a, b); }
  static M mxor(M a, M b) { return _mm_xor_pd(a, b); }
  static M mandnot(M a, M b) { return _mm_andnot_pd(b, a); }  // a & ~b
  static M mnot(M a) { return _mm_xor_pd(a, _mm_castsi128_pd(_mm_set1_epi32(-1))); }
  static D sel(M m, D a, D b) { return _mm_or_pd(_mm_and_pd(m, a), _mm_andnot_pd(m, b)); }
  static M ge(D a, D b) { return _mm_cmpge_pd(a, b); }
  static M eq(D a, D b) { return _mm_cmpeq_pd(a, b); }
  static M ne(D a, D b) { return _mm_cmpneq_pd(a, b); }
  static unsigned bits(M m) { return static_cast<unsigned>(_mm_movemask_pd(m)); }
  // v times the sign of s (s non-zero): v with its sign bit flipped where s is negative.
  static D xorsign(D v, D s) { return _mm_xor_pd(v, _mm_and_pd(s, _mm_set1_pd(-0.0))); }
  // 1.5 * 2^(e + 38) where 2^e <= m < 2^(e+1) (m normal): the grid test's rounding constant.
  static D grid_constant(D m) {
    const __m128i e = _mm_and_si128(_mm_castpd_si128(m), _mm_set1_epi64x(0x7ff0000000000000LL));
    return _mm_castsi128_pd(_mm_or_si128(_mm_add_epi64(e, _mm_set1_epi64x(38LL << 52)), _mm_set1_epi64x(1LL << 51)));
  }
  // c[s] = slot s (0..17) of the pairs at p[0], p[1].
  static void load_ptrs(const double* const* p, D* c) {
    for (int s = 0; s < 18; s += 2) {
      const __m128d x0 = _mm_loadu_pd(p[0] + s), x1 = _mm_loadu_pd(p[1] + s);
      c[s] = _mm_unpacklo_pd(x0, x1);
      c[s + 1] = _mm_unpackhi_pd(x0, x1);
    }
  }
  static void load(const double* p, D* c) {
    const double* ptrs[2] = {p, p + 18};
    load_ptrs(ptrs, c);
  }
};
#include "algorithms/exact/detail/kernel.inc"
}  // namespace tritri::exactsimd::isa_sse2

// ---------------------------------------------------------------- AVX2
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
namespace tritri::exactsimd::isa_avx2 {
struct I {
  static constexpr int W = 4;
  using D = __m256d;
  using M = __m256d;
  static D set1(double x) { return _mm256_set1_pd(x); }
  static D add(D a, D b) { return _mm256_add_pd(a, b); }
  static D sub(D a, D b) { return _mm256_sub_pd(a, b); }
  static D mul(D a, D b) { return _mm256_mul_pd(a, b); }
  static D min(D a, D b) { return _mm256_min_pd(a, b); }
  static D max(D a, D b) { return _mm256_max_pd(a, b); }
  static D abs(D a) { return _mm256_andnot_pd(_mm256_set1_pd(-0.0), a); }
  static M gt(D a, D b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
  static M lt(D a, D b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
  static M le(D a, D b) { return _mm256_cmp_pd(a, b, _CMP_LE_OQ); }
  static M mand(M a, M b) { return _mm256_and_pd(a, b); }
  static M mor(M a, M b) { return _mm256_or_pd(a, b); }
  static M mxor(M a, M b) { return _mm256_xor_pd(a, b); }
  static M mandnot(M a, M b) { return _mm256_andnot_pd(b, a); }
  static M mnot(M a) { return _mm256_xor_pd(a, _mm256_castsi256_pd(_mm256_set1_epi32(-1))); }
  static D sel(M m, D a, D b) { return _mm256_blendv_pd(b, a, m); }
  static M ge(D a, D b) { return _mm256_cmp_pd(a, b, _CMP_GE_OQ); }
  static M eq(D a, D b) { return _mm256_cmp_pd(a, b, _CMP_EQ_OQ); }
  static M ne(D a, D b) { return _mm256_cmp_pd(a, b, _CMP_NEQ_OQ); }
  static unsigned bits(M m) { return static_cast<unsigned>(_mm256_movemask_pd(m)); }
  static D xorsign(D v, D s) { return _mm256_xor_pd(v, _mm256_and_pd(s, _mm256_set1_pd(-0.0))); }
  static D grid_constant(D m) {
    const __m256i e = _mm256_and_si256(_mm256_castpd_si256(m), _mm256_set1_epi64x(0x7ff0000000000000LL));
    return _mm256_castsi256_pd(
        _mm256_or_si256(_mm256_add_epi64(e, _mm256_set1_epi64x(38LL << 52)), _mm256_set1_epi64x(1LL << 51)));
  }
  // Slots s and s+1 of pairs 0..3: A = [p0 | p2], B = [p1 | p3] (two doubles each), then the
  // in-lane unpacks give [p0 p1 p2 p3] for slot s and for slot s+1.
  static void load_ptrs(const double* const* p, D* c) {
    for (int s = 0; s < 18; s += 2) {
      const __m256d a = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p[0] + s)), _mm_loadu_pd(p[2] + s), 1);
      const __m256d b = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p[1] + s)), _mm_loadu_pd(p[3] + s), 1);
      c[s] = _mm256_unpacklo_pd(a, b);
      c[s + 1] = _mm256_unpackhi_pd(a, b);
    }
  }
  static void load(const double* p, D* c) {
    const double* ptrs[4] = {p, p + 18, p + 36, p + 54};
    load_ptrs(ptrs, c);
  }
};
#include "algorithms/exact/detail/kernel.inc"
}  // namespace tritri::exactsimd::isa_avx2
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

// ---------------------------------------------------------------- AVX-512
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx512f"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx512f")
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"  // GCC 12: _mm512_undefined_pd() in the intrinsics
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
namespace tritri::exactsimd::isa_avx512 {
struct I {
  static constexpr int W = 8;
  using D = __m512d;
  using M = __mmask8;
  static D set1(double x) { return _mm512_set1_pd(x); }
  static D add(D a, D b) { return _mm512_add_pd(a, b); }
  static D sub(D a, D b) { return _mm512_sub_pd(a, b); }
  static D mul(D a, D b) { return _mm512_mul_pd(a, b); }
  static D min(D a, D b) { return _mm512_min_pd(a, b); }
  static D max(D a, D b) { return _mm512_max_pd(a, b); }
  static D abs(D a) { return _mm512_abs_pd(a); }
  static M gt(D a, D b) { return _mm512_cmp_pd_mask(a, b, _CMP_GT_OQ); }
  static M lt(D a, D b) { return _mm512_cmp_pd_mask(a, b, _CMP_LT_OQ); }
  static M le(D a, D b) { return _mm512_cmp_pd_mask(a, b, _CMP_LE_OQ); }
  static M mand(M a, M b) { return static_cast<M>(a & b); }
  static M mor(M a, M b) { return static_cast<M>(a | b); }
  static M mxor(M a, M b) { return static_cast<M>(a ^ b); }
  static M mandnot(M a, M b) { return static_cast<M>(a & ~b); }
  static M mnot(M a) { return static_cast<M>(~a); }
  static D sel(M m, D a, D b) { return _mm512_mask_blend_pd(m, b, a); }
  static M ge(D a, D b) { return _mm512_cmp_pd_mask(a, b, _CMP_GE_OQ); }
  static M eq(D a, D b) { return _mm512_cmp_pd_mask(a, b, _CMP_EQ_OQ); }
  static M ne(D a, D b) { return _mm512_cmp_pd_mask(a, b, _CMP_NEQ_OQ); }
  static unsigned bits(M m) { return static_cast<unsigned>(m) & 0xffu; }
  static D xorsign(D v, D s) {
    return _mm512_castsi512_pd(_mm512_xor_si512(
        _mm512_castpd_si512(v), _mm512_and_si512(_mm512_castpd_si512(s), _mm512_set1_epi64(INT64_MIN))));
  }
  static D grid_constant(D m) {
    const __m512i e = _mm512_and_si512(_mm512_castpd_si512(m), _mm512_set1_epi64(0x7ff0000000000000LL));
    return _mm512_castsi512_pd(
        _mm512_or_si512(_mm512_add_epi64(e, _mm512_set1_epi64(38LL << 52)), _mm512_set1_epi64(1LL << 51)));
  }
  static __m256d half(const double* p0, const double* p2, int s) {  // [pair 0 | pair 2], slots s, s+1
    return _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p0 + s)), _mm_loadu_pd(p2 + s), 1);
  }
  static void load_ptrs(const double* const* p, D* c) {
    for (int s = 0; s < 18; s += 2) {
      const __m512d a = _mm512_insertf64x4(_mm512_castpd256_pd512(half(p[0], p[2], s)), half(p[4], p[6], s), 1);
      const __m512d b = _mm512_insertf64x4(_mm512_castpd256_pd512(half(p[1], p[3], s)), half(p[5], p[7], s), 1);
      c[s] = _mm512_unpacklo_pd(a, b);
      c[s + 1] = _mm512_unpackhi_pd(a, b);
    }
  }
  static void load(const double* p, D* c) {
    const double* ptrs[8] = {p, p + 18, p + 36, p + 54, p + 72, p + 90, p + 108, p + 126};
    load_ptrs(ptrs, c);
  }
};
#include "algorithms/exact/detail/kernel.inc"
}  // namespace tritri::exactsimd::isa_avx512
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC diagnostic pop
#pragma GCC pop_options
#endif

#endif  // EXACTSIMD_X86
