// The ISA wrappers and one instance of kernel.inc per instruction set:
//   sse2    2 lanes, the x86-64 baseline, compiled with the translation unit's own flags
//   avx2    4 lanes, compiled under target("avx2") (no FMA is enabled: not that it would
//           matter, every bound holds with or without fused operations, algorithms/exact/README.md)
//   avx512  8 lanes, target("avx512f")
// Each instance lives in its own namespace and target region, so no function compiled for a
// wider instruction set can be merged with (or picked instead of) a baseline one by the linker.
// Chosen at run time by __builtin_cpu_supports (dispatch in exact.hpp).
#pragma once

#include "algorithms/exact/detail/predicates.hpp"
#include "tritri/answers.hpp"

#include <cstddef>
#include <cstdint>
#include <type_traits>

// Lane counts up to which a block with no crossing lane skips the interval stage (a branch).
#if !defined(TRITRI_EXACT_SKIP_EMPTY_GD_MAX_LANES)
#define TRITRI_EXACT_SKIP_EMPTY_GD_MAX_LANES 4
#endif

#if (defined(__x86_64__) || defined(_M_X64)) && (defined(__GNUC__) || defined(__clang__)) && \
    !defined(TRITRI_EXACT_NO_SIMD)
#define TRITRI_EXACT_X86 1
#include <immintrin.h>
#else
#define TRITRI_EXACT_X86 0
#endif

namespace tritri::exact {
// Set on an index handed from the second SIMD pass to the scalar pass: the pair is on the grid.
inline constexpr std::uint32_t kGridFlag = 0x80000000u;
}  // namespace tritri::exact

#if TRITRI_EXACT_X86

// A piece of kernel.inc's block functions, split out for reading: always inlined into them.
#define TRITRI_EXACT_PIECE [[gnu::always_inline]] inline

// What the wrappers spell alike but for the intrinsics' prefix P (_mm, _mm256, _mm512) or
// comparison intrinsic: written once here, expanded inside each wrapper.
// The lane count W, the vector type D, the mask type M, broadcast and lane-wise arithmetic.
#define TRITRI_EXACT_LANES(lanes, vector, mask, P)          \
  static constexpr int W = lanes;                       \
  using D = vector;                                     \
  using M = mask;                                       \
  static D set1(double x) { return P##_set1_pd(x); }    \
  static D add(D a, D b) { return P##_add_pd(a, b); }   \
  static D sub(D a, D b) { return P##_sub_pd(a, b); }   \
  static D mul(D a, D b) { return P##_mul_pd(a, b); }   \
  static D min(D a, D b) { return P##_min_pd(a, b); }   \
  static D max(D a, D b) { return P##_max_pd(a, b); }
// Masks held in vectors, all bits of a lane set or clear (SSE2, AVX2).
#define TRITRI_EXACT_VECTOR_MASKS(P)                              \
  static M mand(M a, M b) { return P##_and_pd(a, b); }        \
  static M mor(M a, M b) { return P##_or_pd(a, b); }          \
  static M mxor(M a, M b) { return P##_xor_pd(a, b); }        \
  static M mandnot(M a, M b) { return P##_andnot_pd(b, a); } /* a & ~b */
// Comparisons through one intrinsic taking the predicate (AVX2's cmp_pd, AVX-512's cmp_pd_mask).
#define TRITRI_EXACT_PREDICATE_COMPARISONS(CMP)                    \
  static M gt(D a, D b) { return CMP(a, b, _CMP_GT_OQ); }      \
  static M lt(D a, D b) { return CMP(a, b, _CMP_LT_OQ); }      \
  static M le(D a, D b) { return CMP(a, b, _CMP_LE_OQ); }      \
  static M ge(D a, D b) { return CMP(a, b, _CMP_GE_OQ); }      \
  static M eq(D a, D b) { return CMP(a, b, _CMP_EQ_OQ); }      \
  static M ne(D a, D b) { return CMP(a, b, _CMP_NEQ_OQ); }
// The transposing loads, through the wrapper's alternate(pair, first, s): slots s and s+1 of
// pairs first, first + 2, ... (two doubles each, in that order), where pair(k) points at pair k.
// The in-lane unpacks of the even and the odd pairs' vectors then give slot s of pairs 0..W-1,
// and slot s+1.
//   load_ptrs  c[s] = slot s (0..17) of the pairs at p[0], ..., p[W-1]
//   load       the same for the W consecutive pairs at p (the offsets fold into the loads)
#define TRITRI_EXACT_LOADS(P)                                                               \
  template <class Pair>                                                                  \
  static void load_from(Pair pair, D* c) {                                               \
    for (int s = 0; s < 18; s += 2) {                                                    \
      const D even = alternate(pair, 0, s), odd = alternate(pair, 1, s);                 \
      c[s] = P##_unpacklo_pd(even, odd);                                                 \
      c[s + 1] = P##_unpackhi_pd(even, odd);                                             \
    }                                                                                    \
  }                                                                                      \
  static void load_ptrs(const double* const* p, D* c) {                                  \
    load_from([p](int k) { return p[k]; }, c);                                           \
  }                                                                                      \
  static void load(const double* p, D* c) {                                              \
    load_from([p](int k) { return p + 18 * k; }, c);                                     \
  }

// ---------------------------------------------------------------- SSE2 (baseline)
namespace tritri::exact::isa_sse2 {
struct I {
  TRITRI_EXACT_LANES(2, __m128d, __m128d, _mm)
  TRITRI_EXACT_VECTOR_MASKS(_mm)
  static D abs(D a) { return _mm_andnot_pd(_mm_set1_pd(-0.0), a); }
  static M gt(D a, D b) { return _mm_cmpgt_pd(a, b); }
  static M lt(D a, D b) { return _mm_cmplt_pd(a, b); }
  static M le(D a, D b) { return _mm_cmple_pd(a, b); }
  static M ge(D a, D b) { return _mm_cmpge_pd(a, b); }
  static M eq(D a, D b) { return _mm_cmpeq_pd(a, b); }
  static M ne(D a, D b) { return _mm_cmpneq_pd(a, b); }
  static M mnot(M a) { return _mm_xor_pd(a, _mm_castsi128_pd(_mm_set1_epi32(-1))); }
  static D sel(M m, D a, D b) { return _mm_or_pd(_mm_and_pd(m, a), _mm_andnot_pd(m, b)); }
  static unsigned bits(M m) { return static_cast<unsigned>(_mm_movemask_pd(m)); }
  // v times the sign of s (s non-zero): v with its sign bit flipped where s is negative.
  static D xorsign(D v, D s) { return _mm_xor_pd(v, _mm_and_pd(s, _mm_set1_pd(-0.0))); }
  // 1.5 * 2^(e + 38) where 2^e <= m < 2^(e+1) (m normal): the grid test's rounding constant.
  static D grid_constant(D m) {
    const __m128i e = _mm_and_si128(_mm_castpd_si128(m), _mm_set1_epi64x(0x7ff0000000000000LL));
    return _mm_castsi128_pd(_mm_or_si128(_mm_add_epi64(e, _mm_set1_epi64x(38LL << 52)), _mm_set1_epi64x(1LL << 51)));
  }
  template <class Pair>
  static D alternate(Pair pair, int first, int s) { return _mm_loadu_pd(pair(first) + s); }
  TRITRI_EXACT_LOADS(_mm)
};
#include "algorithms/exact/detail/kernel.inc"
}  // namespace tritri::exact::isa_sse2

// ---------------------------------------------------------------- AVX2
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
namespace tritri::exact::isa_avx2 {
struct I {
  TRITRI_EXACT_LANES(4, __m256d, __m256d, _mm256)
  TRITRI_EXACT_VECTOR_MASKS(_mm256)
  TRITRI_EXACT_PREDICATE_COMPARISONS(_mm256_cmp_pd)
  static D abs(D a) { return _mm256_andnot_pd(_mm256_set1_pd(-0.0), a); }
  static M mnot(M a) { return _mm256_xor_pd(a, _mm256_castsi256_pd(_mm256_set1_epi32(-1))); }
  static D sel(M m, D a, D b) { return _mm256_blendv_pd(b, a, m); }
  static unsigned bits(M m) { return static_cast<unsigned>(_mm256_movemask_pd(m)); }
  static D xorsign(D v, D s) { return _mm256_xor_pd(v, _mm256_and_pd(s, _mm256_set1_pd(-0.0))); }
  static D grid_constant(D m) {
    const __m256i e = _mm256_and_si256(_mm256_castpd_si256(m), _mm256_set1_epi64x(0x7ff0000000000000LL));
    return _mm256_castsi256_pd(
        _mm256_or_si256(_mm256_add_epi64(e, _mm256_set1_epi64x(38LL << 52)), _mm256_set1_epi64x(1LL << 51)));
  }
  template <class Pair>
  static D alternate(Pair pair, int first, int s) {  // [pair first | pair first + 2]
    return _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(pair(first) + s)), _mm_loadu_pd(pair(first + 2) + s),
                                1);
  }
  TRITRI_EXACT_LOADS(_mm256)
};
#include "algorithms/exact/detail/kernel.inc"
}  // namespace tritri::exact::isa_avx2
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
namespace tritri::exact::isa_avx512 {
struct I {
  TRITRI_EXACT_LANES(8, __m512d, __mmask8, _mm512)
  TRITRI_EXACT_PREDICATE_COMPARISONS(_mm512_cmp_pd_mask)
  static D abs(D a) { return _mm512_abs_pd(a); }
  static M mand(M a, M b) { return static_cast<M>(a & b); }
  static M mor(M a, M b) { return static_cast<M>(a | b); }
  static M mxor(M a, M b) { return static_cast<M>(a ^ b); }
  static M mandnot(M a, M b) { return static_cast<M>(a & ~b); }
  static M mnot(M a) { return static_cast<M>(~a); }
  static D sel(M m, D a, D b) { return _mm512_mask_blend_pd(m, b, a); }
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
  template <class Pair>
  static D alternate(Pair pair, int first, int s) {  // [pair first | first + 2 | first + 4 | first + 6]
    return _mm512_insertf64x4(_mm512_castpd256_pd512(half(pair(first), pair(first + 2), s)),
                              half(pair(first + 4), pair(first + 6), s), 1);
  }
  TRITRI_EXACT_LOADS(_mm512)
};
#include "algorithms/exact/detail/kernel.inc"
}  // namespace tritri::exact::isa_avx512
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC diagnostic pop
#pragma GCC pop_options
#endif

#undef TRITRI_EXACT_PIECE
#undef TRITRI_EXACT_LANES
#undef TRITRI_EXACT_VECTOR_MASKS
#undef TRITRI_EXACT_PREDICATE_COMPARISONS
#undef TRITRI_EXACT_LOADS

#endif  // TRITRI_EXACT_X86
