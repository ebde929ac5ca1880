// The timing floor: not a triangle–triangle test.
//
// It reads all 18 coordinates of the pair and returns one bit derived from them, so a
// benchmark loop that calls it pays for the loads, the call and the answer store, and nothing
// else. Subtracting its time from another algorithm's estimates that algorithm's own work.
// Its answers have nothing to do with geometry: its check results are meaningless, and its
// baseline records them only so that the strict baseline test covers every registered entry.
#pragma once

#include "tritri/geometry.hpp"

namespace tritri::null_floor {

// A sum of every coordinate: each one is read, none can be skipped by the compiler, and the
// sign bit of the sum is an answer the branch predictor cannot learn from the pair's layout.
template <class T>
bool overlap(const PairT<T>& pair) {
  T sum = T(0);
  for (int i = 0; i < 3; ++i) sum = sum + pair.t1[i][0] + pair.t1[i][1] + pair.t1[i][2];
  for (int i = 0; i < 3; ++i) sum = sum + pair.t2[i][0] + pair.t2[i][1] + pair.t2[i][2];
  return sum < T(0);
}

}  // namespace tritri::null_floor
