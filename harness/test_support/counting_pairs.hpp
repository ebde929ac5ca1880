// Pairs on which a port's counting instantiation must answer exactly as its double one: random
// pairs in general position, pairs on a small integer grid (exact contacts, where the last bit
// decides an answer), and the built-in cases. No zero-area triangle.
#pragma once

#include "casefile.hpp"
#include "oracle/oracle.hpp"

#include <random>
#include <vector>

namespace tritri::test_support {

struct CountingPairs {
  std::vector<TrianglePair> general;   // coordinates uniform in [-1, 1]
  std::vector<TrianglePair> singular;  // integer grid [-2, 2]^3, and the built-in cases
};

inline CountingPairs counting_pairs(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> real(-1, 1);
  std::uniform_int_distribution<int> grid(-2, 2);
  CountingPairs out;
  while (out.general.size() < 300 || out.singular.size() < 300) {
    const bool on_grid = out.singular.size() < out.general.size();
    TrianglePair p;
    for (auto* t : {&p.t1, &p.t2})
      for (int i = 0; i < 3; ++i)
        (*t)[i] = on_grid ? Vec3<double>(grid(rng), grid(rng), grid(rng)) : Vec3<double>(real(rng), real(rng), real(rng));
    if (!has_degenerate_triangle(p)) (on_grid ? out.singular : out.general).push_back(p);
  }
  for (const Case& c : builtin_cases())
    if (!has_degenerate_triangle(c.pair)) out.singular.push_back(c.pair);
  return out;
}

}  // namespace tritri::test_support
