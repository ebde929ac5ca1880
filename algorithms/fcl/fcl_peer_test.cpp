// FCL's test on the relations in general position, and its documented behaviour on contact.
#include "algorithms/fcl/fcl_peer.hpp"

#include "cases/oracle/oracle.hpp"

#include <gtest/gtest.h>

#include <random>

namespace tritri::fcl_peer {
namespace {

Triangle tri(Vec3<double> a, Vec3<double> b, Vec3<double> c) { return {{a, b, c}}; }
const Triangle kFloor = tri({0, 0, 0}, {4, 0, 0}, {0, 4, 0});

TEST(Fcl, AnswersTheBasicRelations) {
  EXPECT_TRUE(overlap({kFloor, tri({1, 1, -2}, {1, 1, 2}, {1, -3, 1})}));     // cross
  EXPECT_FALSE(overlap({kFloor, tri({0, 0, 2}, {4, 0, 3}, {0, 4, 5})}));      // above
  EXPECT_FALSE(overlap({kFloor, tri({0, 0, 1}, {4, 0, 1}, {0, 4, 1})}));      // parallel
  EXPECT_TRUE(overlap({kFloor, tri({1, 1, 0}, {5, 1, 0}, {1, 5, 0})}));       // coplanar overlap
  EXPECT_FALSE(overlap({kFloor, tri({5, 5, 0}, {8, 5, 0}, {5, 8, 0})}));      // coplanar apart
}

TEST(Fcl, TouchingCountsAsMeeting) {
  EXPECT_TRUE(overlap({kFloor, tri({0, 0, 0}, {-1, -2, 3}, {-2, -1, 3})}));  // shared vertex
  EXPECT_TRUE(overlap({kFloor, tri({0, 0, 0}, {4, 0, 0}, {1, -1, 2})}));     // hinge
}

TEST(Fcl, AgreesWithTheOracleOnRandomPairs) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto random_triangle = [&] {
    return tri({unit(rng), unit(rng), unit(rng)}, {unit(rng), unit(rng), unit(rng)},
               {unit(rng), unit(rng), unit(rng)});
  };
  for (int i = 0; i < 3000; ++i) {
    const TrianglePair pair{random_triangle(), random_triangle()};
    ASSERT_EQ(overlap(pair), oracle_label(pair).overlap) << i;
  }
}

}  // namespace
}  // namespace tritri::fcl_peer
