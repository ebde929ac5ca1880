// The lane layer itself: the instruction-set choice, and V's operations on every set this machine
// runs (ops_test_kernel.inc, compiled per set as a kernel is), NaN, infinities and signed zeros
// included, with tails and per-lane fallbacks to the scalar port.
#include "algorithms/lanes/isa.hpp"
#include "cases/util/random.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace tritri::lanes::ops_test {
// The scalar answer the kernel must give: its checks all hold (yes), except where the first
// coordinate is negative, where V::by_port asks this function.
inline bool port(const TrianglePair& pair) { return !(pair.t1[0][0] < 0); }
#define TRITRI_LANES_KERNEL "algorithms/lanes/ops_test_kernel.inc"
#include "algorithms/lanes/foreach_isa.hpp"
}  // namespace tritri::lanes::ops_test
// The same kernel with AVX-512's masks as mask-register bits (TRITRI_LANES_MASK_BITS, ops.inc).
namespace tritri::lanes::ops_test_bits {
using ops_test::port;
#define TRITRI_LANES_MASK_BITS
#define TRITRI_LANES_KERNEL "algorithms/lanes/ops_test_kernel.inc"
#include "algorithms/lanes/foreach_isa.hpp"
}  // namespace tritri::lanes::ops_test_bits

namespace tritri::lanes {
namespace {

TEST(LaneIsa, NamesWidthsAndSupport) {
  EXPECT_EQ(to_string(Isa::avx2), "avx2");
  EXPECT_EQ(width(Isa::scalar), 1u);
  EXPECT_EQ(width(Isa::sse2), 2u);
  EXPECT_EQ(width(Isa::avx512), 8u);
  EXPECT_TRUE(supported(Isa::scalar));
  EXPECT_TRUE(supported(detected()));
#if TRITRI_LANES_X86
  EXPECT_TRUE(supported(Isa::sse2));
  EXPECT_FALSE(supported(Isa::neon));
#endif
  EXPECT_EQ(isa_from_setting("scalar"), Isa::scalar);
}

TEST(LaneIsa, AnUnknownOverrideIsAUsageError) {
  EXPECT_EXIT(isa_from_setting("avx3"), testing::ExitedWithCode(2), "TRITRI_ISA=avx3: unknown instruction set");
}

// Values that break careless lane code: NaN, infinities, signed zeros, subnormals, ties.
std::vector<TrianglePair> awkward_pairs(std::size_t n) {
  const double special[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity(), 0.0, -0.0, 4.9e-324, -1.0, 1.0};
  Rng rng(7);
  std::vector<TrianglePair> pairs(n);
  for (TrianglePair& p : pairs) {
    double* x = p.t1[0].data();  // 18 packed doubles (isa.hpp)
    for (int s = 0; s < 18; ++s) {
      const int pick = rng.between(0, 11);
      const double uniform = rng.uniform(-2, 2);
      x[s] = pick < 8 ? special[pick] : uniform;
    }
  }
  return pairs;
}

TEST(LaneOps, AgreeWithTheScalarOperationsOnEveryInstructionSet) {
  const std::vector<TrianglePair> pairs = awkward_pairs(8 * 40 + 7);  // a tail on every width
  int sets = 0;
  for (Isa isa : kIsas) {
    if (!supported(isa) || !ops_test::kKernels[static_cast<std::size_t>(isa)]) continue;
    ++sets;
    for (const bool bits : {false, true})
    for (std::size_t n : {pairs.size(), pairs.size() - 1, std::size_t{3}}) {
      std::vector<Overlap> out(n, Overlap::unsupported);
      stats() = Stats{};
      (bits ? ops_test_bits::batch : ops_test::batch)(isa, pairs.data(), n, out.data());
      std::uint64_t by_port = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const bool tail = i >= n - n % width(isa);
        by_port += tail || pairs[i].t1[0][0] < 0;
        ASSERT_EQ(out[i], ops_test::port(pairs[i]) ? Overlap::yes : Overlap::no)
            << to_string(isa) << (bits ? " (mask bits)" : "") << ": pair " << i << " of " << n;
      }
      EXPECT_EQ(stats().pairs, n);
      EXPECT_EQ(stats().scalar, by_port) << to_string(isa);
    }
  }
  EXPECT_GE(sets, 1) << "no instruction set with lanes on this machine";
}

}  // namespace
}  // namespace tritri::lanes
