// moller97-lanes (README.md, "Lane control"): the published test (divisions, EPSILON snap) on SIMD lanes of pairs,
// lanes_kernel.inc compiled for each instruction set (algorithms/lanes/foreach_isa.hpp), answer for
// answer the port's, which it calls itself for tails and for the lanes it does not decide.
#include "algorithms/moller97/moller97.hpp"
#include "algorithms/lanes/isa.hpp"

namespace tritri::moller97::lanes_kernel {
inline bool port(const TrianglePair& pair) { return overlap<double, true>(pair); }
#define TRITRI_LANES_KERNEL "algorithms/moller97/lanes_kernel.inc"
#include "algorithms/lanes/foreach_isa.hpp"
}  // namespace tritri::moller97::lanes_kernel
