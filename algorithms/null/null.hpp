// The timing floor: not a triangle–triangle test.
//
// It reads all 18 coordinates of the pair and returns one bit derived from them, so a
// benchmark loop that calls it pays for the loads, the call and the answer store, and nothing
// else. Subtracting its time from another algorithm's estimates that algorithm's own work.
// Its answers have nothing to do with geometry: its check results are meaningless, and its
// baseline records them only so that the strict baseline test covers every registered entry.
#pragma once

#include "tritri/geometry.hpp"

#include <bit>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace tritri::null_floor {

// The bit patterns of all 18 coordinates folded with XOR, answering the top bit of the folded
// mantissa: each coordinate is read and can flip the answer, none can be skipped by the
// compiler, and the answer is one the branch predictor cannot learn from the pair's layout.
// XOR rather than a floating-point sum: a sum is a chain of 18 dependent additions, whose
// latency (about a nanosecond) is not part of reading a pair and would inflate the floor.
template <class T>
bool overlap(const PairT<T>& pair) {
  static_assert(std::is_floating_point_v<T>);
  using Bits = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
  Bits folded = 0;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) folded ^= std::bit_cast<Bits>(pair.t1[i][k]) ^ std::bit_cast<Bits>(pair.t2[i][k]);
  // The highest stored mantissa bit: bit 51 of a double, 22 of a float. It is the same bit of
  // the value in both formats, so float and double agree on pairs exact in float.
  return (folded >> (std::numeric_limits<T>::digits - 2)) & 1;
}

}  // namespace tritri::null_floor
