// The pairs the conformance suites draw, from tritri's one random source, and the fuzzer's recipe.
#include "cases/generator/pairs.hpp"

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"
#include "cases/util/random.hpp"

#include <cmath>
#include <cstring>

namespace tritri::pairs {
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

TrianglePair recipe_pair(ByteReader& r) {
  double xyz[18];
  for (double& x : xyz) x = static_cast<double>(static_cast<int>(r.byte() % 9) - 4);
  const std::uint8_t twist = r.byte();
  if (twist & 1) {  // nudge one coordinate by a few ulps or by a tiny relative amount
    double& x = xyz[r.byte() % 18];
    const int ulps = static_cast<int>(r.byte() % 7) - 3;
    for (int k = 0; k < std::abs(ulps); ++k) x = std::nextafter(x, ulps > 0 ? 1e300 : -1e300);
  }
  if (twist & 2) {  // scale by 2^k: exact, the answer must not change
    const int k = static_cast<int>(r.byte() % 81) - 40;
    for (double& x : xyz) x = std::ldexp(x, k);
  }
  if (twist & 4) {  // translate by 2^k: exact while the coordinates stay representable
    const double offset = std::ldexp(1.0, static_cast<int>(r.byte() % 61) - 10);
    for (int i = 0; i < 18; i += 3) xyz[i] += offset;
  }
  if (twist & 8) {  // an arbitrary double for one coordinate
    std::uint64_t bits = 0;
    for (int k = 0; k < 8; ++k) bits = bits << 8 | r.byte();
    double any;
    std::memcpy(&any, &bits, sizeof any);
    if (std::isfinite(any) && std::abs(any) < 1e150) xyz[r.byte() % 18] = any;
  }
  TrianglePair p;
  for (int v = 0; v < 3; ++v) {
    p.t1[v] = {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]};
    p.t2[v] = {xyz[9 + 3 * v], xyz[9 + 3 * v + 1], xyz[9 + 3 * v + 2]};
  }
  return p;
}

}  // namespace tritri::pairs
