// The floor's only promises: it reads every coordinate (each one can flip the answer), and it
// is deterministic.
#include "algorithms/null/null.hpp"

#include <gtest/gtest.h>

namespace tritri::null_floor {
namespace {

TEST(Null, EveryCoordinateCanChangeTheAnswer) {
  const Triangle zero{{Vec3<double>::Zero(), Vec3<double>::Zero(), Vec3<double>::Zero()}};
  const TrianglePair pair{zero, zero};
  for (int t = 0; t < 2; ++t)
    for (int v = 0; v < 3; ++v)
      for (int c = 0; c < 3; ++c) {
        TrianglePair p = pair;  // all zero: every bit folds to 0
        EXPECT_FALSE(overlap(p));
        (t == 0 ? p.t1 : p.t2)[v][c] = 1.5;  // 1.5: the top stored mantissa bit is set
        EXPECT_TRUE(overlap(p)) << t << ' ' << v << ' ' << c;
        (t == 0 ? p.t2 : p.t1)[v][c] = -3.0;  // 3 = 1.5 x 2: the same bit, folded away again
        EXPECT_FALSE(overlap(p)) << t << ' ' << v << ' ' << c;
      }
}

TEST(Null, FloatAndDoubleAgreeOnSmallIntegers) {
  const Triangle t1{{Vec3<double>(1, 2, 3), Vec3<double>(4, 5, 6), Vec3<double>(7, 8, -50)}};
  const Triangle t2{{Vec3<double>(1, 1, 1), Vec3<double>(0, 0, 0), Vec3<double>(2, 2, 2)}};
  const TrianglePair p{t1, t2};
  EXPECT_EQ(overlap(p), overlap(cast<float>(p)));
  // top mantissa bits set: 3, 6, 7 (1.5, 1.5 and 1.75 times a power of 2), -50 (1.5625 x 32)
  // and 1, 1, 1, 2, 2, 2 have none: four set bits fold to 0
  EXPECT_FALSE(overlap(p));
}

}  // namespace
}  // namespace tritri::null_floor
