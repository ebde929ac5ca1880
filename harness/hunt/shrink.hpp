// Shrinking a failure toward the simplest pair that still shows it: a vertex at the origin, small
// integers or few significant bits per coordinate, scaled by powers of two, few distinct values.
// Each step is kept only while the caller's test still holds (the hunt: the algorithm still
// gives the same wrong answer and the exact verdict is unchanged), so a witness never drifts to
// another failure or another truth.
#pragma once

#include "tritri/geometry.hpp"

#include <cstddef>
#include <functional>
#include <vector>

namespace tritri::hunt {

// The bits needed to write x = m·2^e (m odd): m's bit length plus |e|; 0 for 0. An integer
// costs its bit length, a dyadic fraction its numerator's and denominator's.
int coordinate_cost(double x);
// The significant bits of x (m's bit length); 0 for 0.
int significant_bits(double x);
// What the shrinker minimises: the pair's coordinates as integers once the whole pair is scaled
// by the power of two that makes its smallest bit 1 (so 2^k scalings cost nothing but a
// tie-breaker), their bit lengths summed, plus two per distinct value.
std::size_t pair_cost(const TrianglePair& pair);

// The pairs one step simpler than `pair` (not all cheaper: the shrinker keeps the cheapest that
// passes): a vertex moved to the origin, the pair scaled by 2^k or snapped to a grid or to a few
// significant bits, one coordinate zeroed, rounded, shortened or set to another's value.
std::vector<TrianglePair> simpler_pairs(const TrianglePair& pair);

// For each pair, whether it still shows the failure.
using StillFails = std::function<std::vector<bool>(const std::vector<TrianglePair>&)>;

struct Shrunk {
  TrianglePair pair;
  int steps = 0;  // steps taken (each a strictly cheaper pair that still fails)
  bool cut = false;  // stopped by out_of_time, not because no simpler pair still fails
  std::vector<TrianglePair> trail;  // the pair after each step
};

// Greedy: each round tries every simpler pair in one call of `still_fails` and moves to the
// cheapest that still fails, until none is cheaper, `max_rounds` rounds have run or, asked before
// each round, `out_of_time` says the caller's budget is spent (`cut` is then set).
Shrunk shrink(const TrianglePair& start, const StillFails& still_fails, int max_rounds = 64,
              const std::function<bool()>& out_of_time = {});

// How small a witness is, for the JSON and the done-when rule: every coordinate an integer of at
// most 4 digits, or at most 8 significant bits.
struct WitnessSize {
  int max_significant_bits = 0;
  double max_abs = 0;
  bool integers = true;
  std::size_t distinct = 0;  // distinct coordinate values
  std::size_t cost = 0;      // pair_cost
  bool small() const { return (integers && max_abs < 10000) || max_significant_bits <= 8; }
};
WitnessSize witness_size(const TrianglePair& pair);

// The 18 coordinates in order (T1's vertices, then T2's), by index.
double& coordinate(TrianglePair& pair, int index);
double coordinate(const TrianglePair& pair, int index);

}  // namespace tritri::hunt
