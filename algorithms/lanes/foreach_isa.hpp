// Compiles one lane kernel once per instruction set of this architecture, each copy in its own
// namespace and target region, and collects their entry points in a lanes::Kernels table.
//
// Use, in a .cpp (not a header: the copies must live in one translation unit), after including
// algorithms/lanes/isa.hpp at the top (this file is included inside a namespace, so it includes
// nothing itself):
//   #define TRITRI_LANES_KERNEL "algorithms/<folder>/lanes_kernel.inc"
//   #include "algorithms/lanes/foreach_isa.hpp"
// The kernel file sees the lane type V (ops.inc) and defines
//   void run(const TrianglePair* pairs, std::size_t n, Overlap* out)   // n a multiple of V::W
// in each of the namespaces isa_sse2, isa_avx2, isa_avx512 (x86-64) or isa_neon (aarch64), inside
// the namespace the include stands in, where the scalar port is `bool port(const TrianglePair&)`.
// Defined there: the table `kKernels`; the batch entry on a chosen instruction set (whole blocks
// in lanes, the tail through `port`),
//   void batch(lanes::Isa, const TrianglePair* pairs, std::size_t n, Overlap* out)
// and the registration of a port's variant answering through it on lanes::active(),
//   void register_lanes(Registry&, Algorithm variant)   // called from the folder's register_*
//
// Why regions and not one template: a function compiled for AVX2 may only be called after the
// CPU check, so every function of the AVX2 copy (the kernel's and V's) must be compiled under
// target("avx2") and must not be merged by the linker with a baseline one of the same name; a
// template instantiated for a wider set from baseline code would be either refused (intrinsics)
// or compiled for the baseline. The same arrangement as algorithms/exact/detail/simd.hpp.
// No include guard: one use per translation unit.

#if !defined(TRITRI_LANES_X86)
#error "include algorithms/lanes/isa.hpp, outside any namespace, before algorithms/lanes/foreach_isa.hpp"
#endif
#if !defined(TRITRI_LANES_KERNEL)
#error "define TRITRI_LANES_KERNEL (the kernel file) before including algorithms/lanes/foreach_isa.hpp"
#endif

// A target region as a pair of macros (_Pragma), so that each instance below is one include.
#define TRITRI_LANES_STRING(x) #x
#if defined(__clang__)
#define TRITRI_LANES_BEGIN_TARGET(t) \
  _Pragma(TRITRI_LANES_STRING(clang attribute push(__attribute__((target(t))), apply_to = function)))
#define TRITRI_LANES_END_TARGET _Pragma("clang attribute pop")
#else
#define TRITRI_LANES_BEGIN_TARGET(t) _Pragma("GCC push_options") _Pragma(TRITRI_LANES_STRING(GCC target(t)))
#define TRITRI_LANES_END_TARGET _Pragma("GCC pop_options")
#endif

#if TRITRI_LANES_X86
#define TRITRI_LANES_ID 1  // SSE2: the x86-64 baseline, the translation unit's own flags
#include "algorithms/lanes/instance.inc"
#define TRITRI_LANES_ID 2  // AVX2, without FMA: the kernels round as the scalar ports do
#include "algorithms/lanes/instance.inc"
#define TRITRI_LANES_ID 3  // AVX-512, the F subset
#include "algorithms/lanes/instance.inc"
inline constexpr tritri::lanes::Kernels kKernels = {nullptr, &isa_sse2::run, &isa_avx2::run, &isa_avx512::run,
                                                    nullptr};
#elif TRITRI_LANES_NEON
#define TRITRI_LANES_ID 4  // NEON: the aarch64 baseline
#include "algorithms/lanes/instance.inc"
inline constexpr tritri::lanes::Kernels kKernels = {nullptr, nullptr, nullptr, nullptr, &isa_neon::run};
#else
inline constexpr tritri::lanes::Kernels kKernels = {};  // the scalar port alone
#endif

inline void batch(tritri::lanes::Isa isa, const tritri::TrianglePair* pairs, std::size_t n, tritri::Overlap* out) {
  tritri::lanes::batch<&port>(kKernels, isa, pairs, n, out);
}

void register_lanes(tritri::Registry& registry, tritri::Algorithm variant) {
  using tritri::TrianglePair, tritri::Overlap;
  variant.set_batch<tritri::Level::overlap>(tritri::Scalar::double_, [](const TrianglePair* p, std::size_t n, Overlap* out) {
    batch(tritri::lanes::active(), p, n, out);
  });
  // One pair per call is the port itself: a lane control is a way of running it over many pairs.
  variant.set_one_pair<tritri::Level::overlap>([](const TrianglePair& p) { return port(p) ? Overlap::yes : Overlap::no; });
  variant.counters = tritri::lanes::path_counters();
  registry.add(std::move(variant));
}

#undef TRITRI_LANES_KERNEL
#undef TRITRI_LANES_STRING
#undef TRITRI_LANES_BEGIN_TARGET
#undef TRITRI_LANES_END_TARGET
