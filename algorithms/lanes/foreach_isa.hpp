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
// The copies themselves, their namespaces and target regions: each_isa.hpp.
// No include guard: one use per translation unit.

#include "algorithms/lanes/each_isa.hpp"

inline constexpr tritri::lanes::Kernels kKernels = TRITRI_LANES_TABLE(run);

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

