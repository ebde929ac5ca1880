// The pairs the conformance suites draw, from tritri's one random source.
#include "harness/testing/tritri/testing.hpp"

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"
#include "cases/util/random.hpp"

namespace tritri::testing {
namespace {

// Draws every coordinate of a pair from `coordinate`, one at a time (random.hpp says why),
// until `count` pairs of proper triangles are found.
template <class Coordinate>
std::vector<TrianglePair> proper_pairs(std::size_t count, Coordinate coordinate) {
  std::vector<TrianglePair> pairs;
  pairs.reserve(count);
  while (pairs.size() < count) {
    TrianglePair p;
    for (Triangle* t : {&p.t1, &p.t2})
      for (int v = 0; v < 3; ++v)
        for (int axis = 0; axis < 3; ++axis) (*t)[v][axis] = coordinate();
    if (!has_degenerate_triangle(p)) pairs.push_back(p);
  }
  return pairs;
}

}  // namespace

std::vector<TrianglePair> random_pairs(std::uint64_t seed, std::size_t count) {
  Rng rng(seed);
  return proper_pairs(count, [&] { return rng.uniform(-1.0, 1.0); });
}

std::vector<TrianglePair> random_grid_pairs(std::uint64_t seed, std::size_t count, int range) {
  Rng rng(seed);
  return proper_pairs(count, [&] { return static_cast<double>(rng.between(-range, range)); });
}

std::vector<TrianglePair> counting_pairs() {
  std::vector<TrianglePair> pairs = random_pairs(stream_seed(1, "counting-random"), 2000);
  for (int range : {2, 3}) {
    const auto grid = random_grid_pairs(stream_seed(1, "counting-grid", range), 1000, range);
    pairs.insert(pairs.end(), grid.begin(), grid.end());
  }
  for (const Case& c : builtin_cases())
    if (!has_degenerate_triangle(c.pair)) pairs.push_back(c.pair);
  return pairs;
}

}  // namespace tritri::testing
