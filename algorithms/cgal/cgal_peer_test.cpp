// CGAL's filtered do_intersect is exact: it agrees with the oracle on contact as well as on
// general position.
#include "algorithms/cgal/cgal_peer.hpp"

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"

#include <gtest/gtest.h>

#include <random>

namespace tritri::cgal_peer {
namespace {

Triangle tri(Vec3<double> a, Vec3<double> b, Vec3<double> c) { return {{a, b, c}}; }

TEST(Cgal, AgreesWithTheOracleOnEveryBuiltinCase) {
  for (const Case& c : read_case_file(std::string(TRITRI_SOURCE_DIR) + "/cases/builtin.cases")) {
    if (has_degenerate_triangle(c.pair)) continue;
    EXPECT_EQ(overlap(c.pair), oracle_label(c.pair).overlap) << c.name;
    EXPECT_EQ(overlap(swapped(c.pair)), oracle_label(c.pair).overlap) << c.name << " (swapped)";
  }
}

TEST(Cgal, AgreesWithTheOracleOnRandomPairs) {
  std::mt19937_64 rng(55);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto random_triangle = [&] {
    return tri({unit(rng), unit(rng), unit(rng)}, {unit(rng), unit(rng), unit(rng)},
               {unit(rng), unit(rng), unit(rng)});
  };
  for (int i = 0; i < 2000; ++i) {
    const TrianglePair pair{random_triangle(), random_triangle()};
    ASSERT_EQ(overlap(pair), oracle_label(pair).overlap) << i;
  }
}

}  // namespace
}  // namespace tritri::cgal_peer
