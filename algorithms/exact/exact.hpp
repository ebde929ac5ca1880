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
//              the integer engine (intexact.hpp). Where the one-pair path alone is measured
//              faster on the thread's recent pairs, a chunk takes it instead of the lanes
//              (detail/route_choice.hpp); *_batch_with always take the lanes.
//   One pair overlap / relation: the same first pass for one pair in Guigue–Devillers' order with
//              their early exits (one_pair.hpp), then the same exact scalar classification.
//   No allocation per pair, no virtual calls; the only indirect choice is the ISA, once per
//   batch chunk.
//
// Build requirements: C++20, Eigen (the tritri API types), no -ffast-math; no library.
// Compile with -ffp-contract=off as tritri does (the bounds hold either way; algorithms/exact/README.md).
#pragma once

#include "algorithms/exact/detail/one_pair.hpp"
#include "algorithms/exact/detail/route_choice.hpp"
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
  std::uint64_t direct = 0;    // of `pairs`, sent straight to the one-pair path by the route choice
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
// Pending pairs per second pass before the scalar pass takes what it leaves: the handover below
// stays on the stack (13 KB) and in the cache between the two.
inline constexpr std::size_t kSlice = 128;

// What the second pass computed for each pair of a slice, by the pair's slot (its place in the
// slice's pending list), for the scalar pass (`handover_pass`): the pair's bound B, its six
// plane values, evaluated as the one-pair filter evaluates them, which of them are within B, and
// the box of its six points.
// Written for every slot of a block with a pair the second pass leaves, read only for those.
struct Handover {
  double bound[kSlice];
  double s1[3][kSlice];  // T1's vertex k against π2
  double s2[3][kSlice];  // T2's vertex k against π1
  double lo[3][kSlice];  // the minimum and the maximum of the six points per axis
  double hi[3][kSlice];
  std::uint64_t open[kSlice];  // PairSigns::open: bit k for s1[k], 3 + k for s2[k], within the bound
};

// One instruction set's SIMD passes at one level (detail/kernel.inc, detail/kernel_pass2.inc).
template <class Out>
struct Passes {
  // The n pairs (n a multiple of the lanes): writes the decided answers and the indices of the
  // others to `pending`; returns their count.
  std::size_t (*first)(const TrianglePair* pairs, std::size_t n, Out* out, std::uint32_t* pending);
  // The `count` (at most kSlice) pairs at those indices: writes the decided answers, the slots
  // of the rest to `rest` (with kGridFlag where the pair is on the grid) and their values to
  // the handover; returns the count of the rest.
  std::size_t (*second)(const TrianglePair* pairs, Out* out, const std::uint32_t* pending, std::size_t count,
                        std::uint32_t* rest, Handover* handover);
};
struct Kernel {
  Passes<Overlap> overlap;
  Passes<RelationAnswer> relation;
};

// The kernels, once per instruction set of this architecture on the lane layer's V.
#define TRITRI_LANES_KERNEL "algorithms/exact/detail/kernel.inc"
#define TRITRI_LANES_MASK_BITS  // AVX-512: masks in mask registers (README "AVX-512's pass 1: masks in mask registers")
#include "algorithms/lanes/each_isa.hpp"
// By Isa; nullptr where no kernel is compiled (scalar, another architecture's sets).
inline constexpr std::array<const Kernel*, kIsas.size()> kKernels = TRITRI_LANES_TABLE(kKernel);

// Where the scalar pass's pairs were decided, counted locally and added to the thread's stats once.
struct RouteCounts {
  std::uint64_t n[5] = {};
  void add_to(Stats& st) const {
    st.filter += n[static_cast<int>(Route::filter)];
    st.shared += n[static_cast<int>(Route::shared)];
    st.grid += n[static_cast<int>(Route::grid)];
    st.filtered += n[static_cast<int>(Route::filtered)];
    st.declined += n[static_cast<int>(Route::declined)];
  }
};

// `count` pairs, each from scratch: the one-pair filter, then `finish` (where no SIMD kernel
// runs). `at(k)`: the index of the k-th of them in `pairs` and `out`.
template <bool kRelation, class Out, class At>
__attribute__((noinline)) void exact_pass(const TrianglePair* pairs, Out* out, std::size_t count, At at) {
  RouteCounts routes;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t j = at(k);
    Route route = Route::filtered;
    const RelationAnswer a = decide<kRelation>(pairs[j], false, &route);
    if constexpr (kRelation) out[j] = a;
    else out[j] = to_overlap(a);
    ++routes.n[static_cast<int>(route)];
  }
  routes.add_to(stats());
}

// The pairs the second pass left (`rest`: slots of `pending`, with kGridFlag), from its values:
// `finish` on the bound, the plane values and the box the second pass computed, without the
// one-pair filter (algorithms/exact/README.md, "The scalar pass from pass 2's values").
template <bool kRelation, class Out>
__attribute__((noinline)) void handover_pass(const TrianglePair* pairs, Out* out, const std::uint32_t* pending,
                                             const std::uint32_t* rest, std::size_t count, const Handover& h) {
  RouteCounts routes;
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint32_t slot = rest[k] & ~kGridFlag;
    const std::uint32_t j = pending[slot];
    PairSigns ps;
    ps.bound = h.bound[slot];
    for (int v = 0; v < 3; ++v) ps.s1[v] = h.s1[v][slot], ps.s2[v] = h.s2[v][slot];
    ps.open = static_cast<unsigned>(h.open[slot]);
    ps.box.lo = Double2{h.lo[0][slot], h.lo[1][slot]};
    ps.box.hi = Double2{h.hi[0][slot], h.hi[1][slot]};
    ps.box.lo_z = h.lo[2][slot];
    ps.box.hi_z = h.hi[2][slot];
    Route route = Route::filtered;
    const RelationAnswer a = finish_pair<kRelation>(pairs[j], ps, (rest[k] & kGridFlag) != 0u, &route);
    if constexpr (kRelation) out[j] = a;
    else out[j] = to_overlap(a);
    ++routes.n[static_cast<int>(route)];
  }
  routes.add_to(stats());
}

// One chunk (m pairs) through the SIMD passes and the scalar pass for what they leave; returns
// how many reached the scalar pass.
template <bool kRelation, class Out>
std::size_t lanes_chunk(const Passes<Out>* passes, std::size_t lanes, const TrianglePair* pairs, std::size_t m,
                        Out* out) {
  std::uint32_t pending[kChunk], rest[kSlice];
  Handover handover;
  const std::size_t simd = lanes ? m - m % lanes : 0;
  const std::size_t np = passes ? passes->first(pairs, simd, out, pending) : 0;
  // the tail (fewer pairs than lanes; every pair where no kernel runs) through the one-pair
  // path: a block of pass 2 would carry it in mostly empty lanes (algorithms/exact/README.md,
  // "The batch's tail")
  exact_pass<kRelation>(pairs, out, m - simd, [simd](std::size_t k) { return simd + k; });
  std::size_t scalar = m - simd;
  for (std::size_t s = 0; s < np; s += kSlice) {
    const std::size_t count = np - s < kSlice ? np - s : kSlice;
    const std::size_t nr = passes->second(pairs, out, pending + s, count, rest, &handover);
    handover_pass<kRelation>(pairs, out, pending + s, rest, nr, handover);
    scalar += nr;
  }
  Stats& st = stats();
  st.pending += np + (m - simd);
  st.scalar += scalar;
  return scalar;
}

// One chunk with every pair through the one-pair path (the filter, then `finish`).
template <bool kRelation, class Out>
void one_pair_chunk(const TrianglePair* pairs, std::size_t m, Out* out) {
  stats().direct += m;
  exact_pass<kRelation>(pairs, out, m, [](std::size_t k) { return k; });
}

// `chooser`: each chunk's route, the lanes or one pair at a time (route_choice.hpp); nullptr:
// the lanes always (the `*_batch_with` entries, so that a test or exact_diff runs the set it
// names).
template <bool kRelation, class Out>
void batch(Isa isa, const TrianglePair* pairs, std::size_t n, Out* out, RouteChooser* chooser) {
  stats().pairs += n;
  const Kernel* kernel = kKernels[static_cast<std::size_t>(isa)];
  const std::size_t lanes = kernel ? lanes::width(isa) : 0;  // none: every pair to the exact pass
  const Passes<Out>* passes = nullptr;
  if (kernel) {
    if constexpr (kRelation) passes = &kernel->relation;
    else passes = &kernel->overlap;
  }
  if (!passes) chooser = nullptr;  // one route only
  for (std::size_t start = 0; start < n; start += kChunk) {
    const std::size_t m = n - start < kChunk ? n - start : kChunk;
    // small chunks run on the current route untimed (RouteChooser::kMinPairs)
    const bool timed = chooser && m >= RouteChooser::kMinPairs;
    const BatchRoute route = !chooser ? BatchRoute::lanes : timed ? chooser->next() : chooser->current();
    std::size_t scalar = 0;
    const std::uint64_t t0 = timed ? ticks() : 0;
    if (route == BatchRoute::one_pair) one_pair_chunk<kRelation>(pairs + start, m, out + start);
    else scalar = lanes_chunk<kRelation>(passes, lanes, pairs + start, m, out + start);
    if (timed) chooser->record(route, m, ticks() - t0, scalar);
  }
}

// The thread's route choice for one level.
template <bool kRelation>
RouteChooser& route_chooser() {
  thread_local RouteChooser c;
  return c;
}

}  // namespace detail

// ---- batches ----

inline void overlap_batch_with(Isa isa, const TrianglePair* pairs, std::size_t n, Overlap* out) {
  detail::batch<false>(supported(isa) ? isa : detected_isa(), pairs, n, out, nullptr);
}
inline void relation_batch_with(Isa isa, const TrianglePair* pairs, std::size_t n, RelationAnswer* out) {
  detail::batch<true>(supported(isa) ? isa : detected_isa(), pairs, n, out, nullptr);
}

// The active set, each chunk on the route that has been the faster on this thread's recent
// pairs: the lanes, or one pair at a time (detail/route_choice.hpp). The answers are the same.
inline void overlap_batch(const TrianglePair* pairs, std::size_t n, Overlap* out) {
  detail::batch<false>(active_isa(), pairs, n, out, &detail::route_chooser<false>());
}
inline void relation_batch(const TrianglePair* pairs, std::size_t n, RelationAnswer* out) {
  detail::batch<true>(active_isa(), pairs, n, out, &detail::route_chooser<true>());
}

}  // namespace tritri::exact
