// exact: an exact triangle–triangle overlap and relation test for tritri, decided from
// orientation signs in SIMD lanes of pairs, with semi-static error bounds and an exact second pass.
//
//   Exact      for every finite double input the answers are the oracle's (CGAL Epeck, as
//              cases/oracle/oracle.hpp): closed triangles (touching counts), Yu–He's
//              relation codes, zero-area triangles judged as their point/segment hulls and
//              answered {Relation::degenerate, dimension}. Non-finite input: unsupported.
//   Batch      overlap_batch / relation_batch: pairs are evaluated W at a time (SSE2: 2, AVX2:
//              4, AVX-512: 8 lanes, picked at run time) without branches on the data: the six
//              plane signs, Guigue–Devillers' two interval signs, each certain when its value
//              exceeds the pair's semi-static bound. Undecided lanes (a sign within the bound:
//              touching, coplanar, degenerate, near-singular, or magnitudes outside the
//              filter's range) are compacted and decided by the exact scalar classification
//              (classify.hpp) with plain double predicates when the pair lies on a small
//              integer grid (exact there), otherwise with filtered predicates that fall back to
//              the integer engine (intexact.hpp).
//   One pair overlap / relation: the same first pass for one pair in Guigue–Devillers' order with
//              their early exits (one_pair.hpp), then the same exact scalar classification.
//   No allocation per pair, no virtual calls; the only indirect choice is the ISA, once per
//   batch chunk.
//
// Build requirements: C++20, Eigen (the tritri API types), no -ffast-math; no library.
// Compile with -ffp-contract=off as tritri does (the bounds hold either way; algorithms/exact/README.md).
#pragma once

#include "algorithms/exact/detail/one_pair.hpp"
#include "algorithms/exact/detail/simd.hpp"
#include "tritri/answers.hpp"
#include "tritri/isa.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace tritri::exact {

// The batch kernels load a pair as 18 consecutive doubles (kernel.inc).
static_assert(sizeof(TrianglePair) == 18 * sizeof(double), "TrianglePair must be 18 packed doubles");

enum class Isa : std::uint8_t { scalar = 0, sse2 = 1, avx2 = 2, avx512 = 3 };

inline const char* to_string(Isa isa) {
  switch (isa) {
    case Isa::scalar: return "scalar";
    case Isa::sse2: return "sse2";
    case Isa::avx2: return "avx2";
    case Isa::avx512: return "avx512";
  }
  return "?";
}

// The widest instruction set this machine runs that exact's kernels are compiled for here (the
// machine's, tritri/isa.hpp: same names and order for these four).
inline Isa detected_isa() {
#if TRITRI_EXACT_X86
  return static_cast<Isa>(tritri::machine_isa());
#else
  return Isa::scalar;
#endif
}

// The instruction set the batch entry points use: the detected one, or the narrower one the
// environment asks every lane algorithm for (TRITRI_ISA, tritri/isa.hpp; same names and order).
inline Isa active_isa() {
  static const Isa isa = static_cast<Isa>(
      std::min(static_cast<int>(tritri::requested_isa()), static_cast<int>(detected_isa())));
  return isa;
}

inline bool supported(Isa isa) { return static_cast<int>(isa) <= static_cast<int>(detected_isa()); }

// Where the pairs of this thread's batches were decided (cumulative; reset with reset_stats()).
struct Stats {
  std::uint64_t pairs = 0;     // pairs given to a batch entry point
  std::uint64_t pending = 0;   // of which left undecided by the first SIMD pass (or in its tail)
  std::uint64_t scalar = 0;    // of those, left undecided by the second (grid) SIMD pass too
  std::uint64_t filter = 0;    // of those, decided by the one-pair filter (pairs that skipped SIMD)
  std::uint64_t shared = 0;    // decided by the shared-vertex and shared-edge shortcuts
  std::uint64_t grid = 0;      // decided with plain double on an integer grid
  std::uint64_t filtered = 0;  // decided with filtered predicates (+ exact engines when needed)
  std::uint64_t declined = 0;  // non-finite input
};
inline Stats& stats() {
  thread_local Stats s;
  return s;
}
inline void reset_stats() {
  stats() = Stats{};
  intexact::counts() = intexact::Counts{};
}

// ---- one pair ----

inline Overlap overlap(const TrianglePair& pair) { return detail::overlap_one_pair(pair); }
inline RelationAnswer relation(const TrianglePair& pair) { return detail::relation_one_pair(pair); }

namespace detail {

inline constexpr std::size_t kChunk = 4096;  // pairs per SIMD pass before its exact pass

template <bool kRelation, class Out>
__attribute__((noinline)) void exact_pass(const TrianglePair* pairs, Out* out, const std::uint32_t* pending,
                                          std::size_t count) {
  Stats& st = stats();
  st.scalar += count;
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint32_t j = pending[k] & ~kGridFlag;
    Route route = Route::filtered;
    const RelationAnswer a = decide<kRelation>(pairs[j], (pending[k] & kGridFlag) != 0u, &route);
    if constexpr (kRelation) out[j] = a;
    else out[j] = to_overlap(a);
    st.filter += route == Route::filter;
    st.shared += route == Route::shared;
    st.grid += route == Route::grid;
    st.filtered += route == Route::filtered;
    st.declined += route == Route::declined;
  }
}

template <bool kRelation, class Out>
void batch(Isa isa, const TrianglePair* pairs, std::size_t n, Out* out) {
  std::uint32_t pending[kChunk], rest[kChunk];
  stats().pairs += n;
  int lanes = 0;  // scalar: every pair goes to the exact pass
#if TRITRI_EXACT_X86
  if (isa == Isa::sse2) lanes = isa_sse2::I::W;
  if (isa == Isa::avx2) lanes = isa_avx2::I::W;
  if (isa == Isa::avx512) lanes = isa_avx512::I::W;
#endif
  for (std::size_t start = 0; start < n; start += kChunk) {
    const std::size_t m = n - start < kChunk ? n - start : kChunk;
    const std::size_t simd = lanes ? m - m % static_cast<std::size_t>(lanes) : 0;
    std::size_t np = 0;
#if TRITRI_EXACT_X86
    switch (isa) {
      case Isa::sse2: np = isa_sse2::run<kRelation>(pairs + start, simd, out + start, pending, 0, 0); break;
      case Isa::avx2: np = isa_avx2::run<kRelation>(pairs + start, simd, out + start, pending, 0, 0); break;
      case Isa::avx512: np = isa_avx512::run<kRelation>(pairs + start, simd, out + start, pending, 0, 0); break;
      case Isa::scalar: break;
    }
#endif
    for (std::size_t j = simd; j < m; ++j) pending[np++] = static_cast<std::uint32_t>(j);
    stats().pending += np;
    std::size_t nr = np;
#if TRITRI_EXACT_X86
    switch (isa) {
      case Isa::sse2: nr = isa_sse2::run2<kRelation>(pairs + start, out + start, pending, np, rest); break;
      case Isa::avx2: nr = isa_avx2::run2<kRelation>(pairs + start, out + start, pending, np, rest); break;
      case Isa::avx512: nr = isa_avx512::run2<kRelation>(pairs + start, out + start, pending, np, rest); break;
      case Isa::scalar: std::memcpy(rest, pending, np * sizeof(std::uint32_t)); break;
    }
#else
    std::memcpy(rest, pending, np * sizeof(std::uint32_t));
#endif
    exact_pass<kRelation>(pairs + start, out + start, rest, nr);
  }
}

}  // namespace detail

// ---- batches ----

inline void overlap_batch_with(Isa isa, const TrianglePair* pairs, std::size_t n, Overlap* out) {
  detail::batch<false>(supported(isa) ? isa : detected_isa(), pairs, n, out);
}
inline void relation_batch_with(Isa isa, const TrianglePair* pairs, std::size_t n, RelationAnswer* out) {
  detail::batch<true>(supported(isa) ? isa : detected_isa(), pairs, n, out);
}

inline void overlap_batch(const TrianglePair* pairs, std::size_t n, Overlap* out) {
  overlap_batch_with(active_isa(), pairs, n, out);
}
inline void relation_batch(const TrianglePair* pairs, std::size_t n, RelationAnswer* out) {
  relation_batch_with(active_isa(), pairs, n, out);
}

}  // namespace tritri::exact
