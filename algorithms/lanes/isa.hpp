// The instruction sets a lane kernel is compiled for, which one runs, and the batch driver that
// hands a kernel its whole blocks of W pairs and the scalar port the rest.
//
// Chosen once per process: the widest set this CPU runs, or a narrower one named in the
// environment, TRITRI_ISA=scalar|sse2|avx2|avx512|neon (tritri/isa.hpp, README.md). Header-only: a kernel's
// folder is compiled twice (the v3fma build variant, algorithms/README.md), and each build gets
// its own copy of everything here.
#pragma once

#include "tritri/algorithm.hpp"
#include "tritri/answers.hpp"
#include "tritri/isa.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#if (defined(__x86_64__) || defined(_M_X64)) && (defined(__GNUC__) || defined(__clang__)) && \
    !defined(TRITRI_LANES_NO_SIMD)
#define TRITRI_LANES_X86 1
#include <immintrin.h>  // for the kernels (foreach_isa.hpp), included here outside any namespace
#else
#define TRITRI_LANES_X86 0
#endif
#if defined(__aarch64__) && defined(__ARM_NEON) && !defined(TRITRI_LANES_NO_SIMD)
#define TRITRI_LANES_NEON 1
#else
#define TRITRI_LANES_NEON 0
#endif

namespace tritri::lanes {

// A kernel loads a pair as 18 consecutive doubles (t1's three vertices, then t2's, x y z each).
static_assert(sizeof(TrianglePair) == 18 * sizeof(double), "TrianglePair must be 18 packed doubles");

// The instruction sets, their names, the machine's and the one asked for (TRITRI_ISA) are the
// API's: tritri/isa.hpp.
using tritri::Isa;
using tritri::kIsas;

// Doubles per vector: pairs per block.
constexpr std::size_t width(Isa isa) {
  constexpr std::array<std::size_t, 5> widths = {1, 2, 4, 8, 2};
  return widths[static_cast<std::size_t>(isa)];
}

inline Isa detected() { return machine_isa(); }
inline bool supported(Isa isa) { return isa_runs_here(isa); }
// The set the batch entry points use.
inline Isa active() { return requested_isa(); }

// Where this thread's lane batches went (cumulative; for an algorithm's PathCounters).
struct Stats {
  std::uint64_t pairs = 0;   // pairs given to a batch
  std::uint64_t scalar = 0;  // of which answered by the scalar port: tails and per-lane fallbacks
};
inline Stats& stats() {
  thread_local Stats s;
  return s;
}

// The counters of a lane batch entry (tritri bench records them per pool): pairs, those the
// scalar port answered, and the instruction set that ran, as "isa:NAME" = 1.
inline PathCounters path_counters() {
  return {[] { stats() = Stats{}; },
          [] {
            return CounterList{{"pairs", stats().pairs},
                               {"scalar", stats().scalar},
                               {"isa:" + std::string(to_string(active())), 1}};
          }};
}

// A kernel's blocks for one instruction set: answers n pairs, n a multiple of its width.
using BlockRun = void (*)(const TrianglePair* pairs, std::size_t n, Overlap* out);
// One per Isa (nullptr: not compiled on this architecture); foreach_isa.hpp fills it.
using Kernels = std::array<BlockRun, kIsas.size()>;

// The batch entry point: whole blocks through `kernels` on `isa`, the tail through the scalar
// port `Port` (a per-pair function returning bool), as the lanes would answer it.
template <auto Port>
void batch(const Kernels& kernels, Isa isa, const TrianglePair* pairs, std::size_t n, Overlap* out) {
  const BlockRun run = supported(isa) ? kernels[static_cast<std::size_t>(isa)] : nullptr;
  const std::size_t blocks = run ? n - n % width(isa) : 0;
  if (blocks) run(pairs, blocks, out);
  for (std::size_t i = blocks; i < n; ++i) out[i] = Port(pairs[i]) ? Overlap::yes : Overlap::no;
  stats().pairs += n;
  stats().scalar += n - blocks;
}

// The scalar port's answer for one lane that a kernel does not decide itself (kept out of line,
// outside every target region: it runs as the baseline port does).
template <auto Port>
[[gnu::noinline]] Overlap by_port(const TrianglePair& pair) {
  ++stats().scalar;
  return Port(pair) ? Overlap::yes : Overlap::no;
}

}  // namespace tritri::lanes
