// exact: an exact triangle–triangle overlap and relation test for tritri, decided from
// orientation signs in SIMD lanes of pairs, with semi-static error bounds and an exact second pass.
//
//   Exact      for every finite double input the answers are the oracle's (CGAL Epeck, as
//              cases/oracle/oracle.hpp): closed triangles (touching counts), Yu–He's
//              relation codes, zero-area triangles judged as their point/segment hulls and
//              answered {Relation::degenerate, dimension}. Non-finite input: unsupported.
//   Batch      overlap_batch / relation_batch: pairs are evaluated W at a time on the lane layer
//              (algorithms/lanes: SSE2 2, AVX2 4, AVX-512 8, NEON 2 lanes, picked at run time as
//              for every lane algorithm, TRITRI_ISA) without branches on the data: the six
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
#include "algorithms/lanes/isa.hpp"
#include "tritri/answers.hpp"
#include "tritri/isa.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace tritri::exact {

// The batch kernels load a pair as 18 consecutive doubles (kernel.inc).
static_assert(sizeof(TrianglePair) == 18 * sizeof(double), "TrianglePair must be 18 packed doubles");

// The instruction sets are the lane layer's (algorithms/lanes/isa.hpp): one detection and one
// override, TRITRI_ISA, for every lane algorithm.
using Isa = tritri::Isa;
// The API's name of `isa` as a C string, for printing (the tests, the fuzz harness).
inline const char* to_string(Isa isa) { return tritri::to_string(isa).data(); }
inline Isa detected_isa() { return lanes::detected(); }
// The set the batch entry points use: the detected one, or the narrower one TRITRI_ISA names.
inline Isa active_isa() { return lanes::active(); }
inline bool supported(Isa isa) { return lanes::supported(isa); }

// Set on an index handed from the second SIMD pass to the scalar pass: the pair is on the grid.
inline constexpr std::uint32_t kGridFlag = 0x80000000u;

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

// One instruction set's SIMD passes at one level (detail/kernel.inc, detail/kernel_pass2.inc).
template <class Out>
struct Passes {
  // The n pairs (n a multiple of the lanes): writes the decided answers and the indices of the
  // others to `pending`; returns their count.
  std::size_t (*first)(const TrianglePair* pairs, std::size_t n, Out* out, std::uint32_t* pending);
  // The `count` pairs at those indices: writes the decided answers and the rest's indices (with
  // kGridFlag where the pair is on the grid) to `rest`; returns their count.
  std::size_t (*second)(const TrianglePair* pairs, Out* out, const std::uint32_t* pending, std::size_t count,
                        std::uint32_t* rest);
};
struct Kernel {
  Passes<Overlap> overlap;
  Passes<RelationAnswer> relation;
};

// The kernels, once per instruction set of this architecture on the lane layer's V.
#define TRITRI_LANES_KERNEL "algorithms/exact/detail/kernel.inc"
#include "algorithms/lanes/each_isa.hpp"
// By Isa; nullptr where no kernel is compiled (scalar, another architecture's sets).
inline constexpr std::array<const Kernel*, kIsas.size()> kKernels = TRITRI_LANES_TABLE(kKernel);

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
  const Kernel* kernel = kKernels[static_cast<std::size_t>(isa)];
  const std::size_t lanes = kernel ? lanes::width(isa) : 0;  // none: every pair to the exact pass
  const Passes<Out>* passes = nullptr;
  if (kernel) {
    if constexpr (kRelation) passes = &kernel->relation;
    else passes = &kernel->overlap;
  }
  for (std::size_t start = 0; start < n; start += kChunk) {
    const std::size_t m = n - start < kChunk ? n - start : kChunk;
    const std::size_t simd = lanes ? m - m % lanes : 0;
    std::size_t np = passes ? passes->first(pairs + start, simd, out + start, pending) : 0;
    for (std::size_t j = simd; j < m; ++j) pending[np++] = static_cast<std::uint32_t>(j);
    stats().pending += np;
    std::size_t nr = np;
    if (passes) nr = passes->second(pairs + start, out + start, pending, np, rest);
    else std::memcpy(rest, pending, np * sizeof(std::uint32_t));
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
