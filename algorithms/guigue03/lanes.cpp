// guigue03-lanes (README.md, "Lane control"): the published overlap test on SIMD lanes of pairs,
// lanes_kernel.inc compiled for each instruction set (algorithms/lanes/foreach_isa.hpp), answer for
// answer the port's, which it calls itself for tails and for the lanes it does not decide.
#include "algorithms/guigue03/guigue03.hpp"
#include "algorithms/lanes/isa.hpp"

namespace tritri::guigue03::lanes_kernel {
inline bool port(const TrianglePair& pair) { return overlap<double>(pair); }
#define TRITRI_LANES_KERNEL "algorithms/guigue03/lanes_kernel.inc"
#include "algorithms/lanes/foreach_isa.hpp"
}  // namespace tritri::guigue03::lanes_kernel
