// Compiles one lane kernel file once per instruction set of this architecture, each copy in its
// own namespace and target region with its own lane type V (ops.inc): the part of foreach_isa.hpp
// that any kernel shares, whatever its entry points (the lane controls' `run`, exact's two
// passes, algorithms/exact/exact.hpp).
//
// Use, after including algorithms/lanes/isa.hpp at the top (this file is included inside a
// namespace, so it includes nothing itself):
//   #define TRITRI_LANES_KERNEL "algorithms/<folder>/<kernel>.inc"
//   #include "algorithms/lanes/each_isa.hpp"
// The kernel file is then compiled in the namespaces isa_sse2, isa_avx2, isa_avx512 (x86-64) or
// isa_neon (aarch64) inside the namespace the include stands in; there it sees V and names what
// its enclosing namespaces hold. TRITRI_LANES_TABLE(name) is then the initializer of a table by
// Isa (tritri/isa.hpp's order) of &isa_*::name, nullptr for a set not compiled here.
//
// A kernel written with the named comparisons (V::lt ...) may also define TRITRI_LANES_MASK_BITS
// before the include: its AVX-512 masks are then mask-register bits, not lane vectors (ops.inc).
//
// Why regions and not one template: a function compiled for AVX2 may only be called after the
// CPU check, so every function of the AVX2 copy (the kernel's and V's) must be compiled under
// target("avx2") and must not be merged by the linker with a baseline one of the same name; a
// template instantiated for a wider set from baseline code would be either refused (intrinsics)
// or compiled for the baseline. No include guard: one use per kernel file and namespace.

#if !defined(TRITRI_LANES_X86)
#error "include algorithms/lanes/isa.hpp, outside any namespace, before algorithms/lanes/each_isa.hpp"
#endif
#if !defined(TRITRI_LANES_KERNEL)
#error "define TRITRI_LANES_KERNEL (the kernel file) before including algorithms/lanes/each_isa.hpp"
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
#define TRITRI_LANES_ID 2  // AVX2, without FMA: the kernels round as the scalar code does
#include "algorithms/lanes/instance.inc"
#define TRITRI_LANES_ID 3  // AVX-512, the F subset
#include "algorithms/lanes/instance.inc"
#define TRITRI_LANES_TABLE(name) {nullptr, &isa_sse2::name, &isa_avx2::name, &isa_avx512::name, nullptr}
#elif TRITRI_LANES_NEON
#define TRITRI_LANES_ID 4  // NEON: the aarch64 baseline
#include "algorithms/lanes/instance.inc"
#define TRITRI_LANES_TABLE(name) {nullptr, nullptr, nullptr, nullptr, &isa_neon::name}
#else
#define TRITRI_LANES_TABLE(name) {}  // no lanes: the scalar code alone
#endif

#undef TRITRI_LANES_KERNEL
#undef TRITRI_LANES_MASK_BITS
#undef TRITRI_LANES_STRING
#undef TRITRI_LANES_BEGIN_TARGET
#undef TRITRI_LANES_END_TARGET
