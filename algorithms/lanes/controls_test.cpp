// Every lane control (a registered algorithm NAME-lanes) answers every pair as its scalar port NAME
// does, on the instruction set TRITRI_ISA names: ctest runs this once per set of this
// architecture (CMakeLists.txt), skipped where the CPU lacks it. The pools: the quick corpus,
// random pairs, small-integer pairs (zero signs, coplanar pairs), pairs a hair from each other's
// plane around moller97's EPSILON, and pairs with NaN, infinite and signed-zero coordinates;
// each answered whole, without its first pair and without its last three (other tails).
#include "algorithms/lanes/isa.hpp"
#include "cases/generator/corpus.hpp"
#include "cases/util/random.hpp"
#include "harness/testing/tritri/testing.hpp"
#include "tritri/algorithm.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace tritri::lanes {
namespace {

std::vector<TrianglePair> corpus_pairs() {
  std::vector<TrianglePair> pairs;
  for (const Case& c : corpus::generate_corpus(corpus::quick_options())) pairs.push_back(c.pair);
  return pairs;
}

// T2 against the floor (z = 0, |N| = 16 for guigue03's and moller97's normals) with each vertex
// at a height around EPSILON / |N| = 6.25e-8, where moller97 snaps the distance to zero or not.
std::vector<TrianglePair> near_snap_pairs() {
  const double heights[] = {0.0, -0.0, 6.2e-8, -6.2e-8, 6.25e-8, -6.25e-8, 6.3e-8, -6.3e-8, 1e-7, -1e-7, 1.0, -1.0};
  const Triangle floor = {{Vec3<double>(0, 0, 0), Vec3<double>(4, 0, 0), Vec3<double>(0, 4, 0)}};
  Rng rng(11);
  std::vector<TrianglePair> pairs;
  for (int n = 0; n < 20000; ++n) {
    TrianglePair p{floor, floor};
    for (int i = 0; i < 3; ++i) {
      const int h = rng.between(0, 11);
      const double x = rng.uniform(-1, 5);
      const double y = rng.uniform(-1, 5);
      p.t2[i] = Vec3<double>(x, y, heights[h]);
    }
    pairs.push_back(n % 2 ? swapped(p) : p);
  }
  return pairs;
}

// Random pairs with some coordinates replaced by NaN, ±infinity or ±0 (the ports define no
// answer there, but the lanes must give theirs).
std::vector<TrianglePair> non_finite_pairs() {
  const double special[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity(), -0.0};
  std::vector<TrianglePair> pairs = testing::random_grid_pairs(13, 4000, 2);
  Rng rng(17);
  for (TrianglePair& p : pairs) {
    const int s = rng.between(0, 17);
    const int pick = rng.between(0, 3);
    p.t1[0].data()[s] = special[pick];  // 18 packed doubles (isa.hpp)
  }
  return pairs;
}

std::string hex(const TrianglePair& p) {
  std::string s;
  char buf[32];
  for (int k = 0; k < 18; ++k) s += (std::snprintf(buf, sizeof buf, " %a", p.t1[0].data()[k]), buf);
  return s;
}

// The answers of `a` on pairs [from, from + n).
std::vector<Overlap> answers(const Algorithm& a, const std::vector<TrianglePair>& pairs, std::size_t from, std::size_t n) {
  std::vector<Overlap> out(n, Overlap::unsupported);
  a.batch<Level::overlap>()(pairs.data() + from, n, out.data());
  return out;
}

TEST(LaneControls, AnswerEveryPairAsTheirPortsOnTheChosenInstructionSet) {
  const std::string setting = std::getenv(kIsaVariable) ? std::getenv(kIsaVariable) : "";
  for (Isa named : kIsas)
    if (to_string(named) == setting && !supported(named)) GTEST_SKIP() << setting << " is not on this CPU";
  const Isa isa = active();
  const std::vector<std::vector<TrianglePair>> pools = {
      corpus_pairs(), testing::random_pairs(19, 20000), testing::random_grid_pairs(23, 20000, 1),
      testing::random_grid_pairs(29, 20000, 4), near_snap_pairs(), non_finite_pairs()};
  int controls = 0;
  for (const Algorithm& lanes : registry().all()) {
    const std::string suffix = "-lanes";
    if (!lanes.build.empty() || lanes.name.size() <= suffix.size() || !lanes.name.ends_with(suffix)) continue;
    const Algorithm* port = registry().find(lanes.name.substr(0, lanes.name.size() - suffix.size()));
    ASSERT_NE(port, nullptr) << lanes.name << " has no port";
    ++controls;
    lanes.counters.reset();
    for (const std::vector<TrianglePair>& pool : pools) {
      for (const auto& [from, n] : {std::pair{std::size_t{0}, pool.size()}, std::pair{std::size_t{1}, pool.size() - 1},
                                    std::pair{std::size_t{0}, pool.size() - 3}}) {
        const std::vector<Overlap> got = answers(lanes, pool, from, n), want = answers(*port, pool, from, n);
        for (std::size_t i = 0; i < n; ++i)
          ASSERT_EQ(got[i], want[i]) << lanes.name << " on " << to_string(isa) << ", pair" << hex(pool[from + i]);
      }
    }
    const CounterList counts = lanes.counters.read();
    EXPECT_NE(std::find(counts.begin(), counts.end(), std::pair{"isa:" + std::string(to_string(isa)), std::uint64_t{1}}),
              counts.end())
        << lanes.name << " does not name " << to_string(isa) << " in its counters";
  }
  EXPECT_GE(controls, 2) << "guigue03-lanes and moller97-lanes are registered";
}

}  // namespace
}  // namespace tritri::lanes
