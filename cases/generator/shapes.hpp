// Random triangle pairs of the shapes the bench's ratio and type workloads, the exact test's
// generators (exact_pairs.hpp) and the hunt draw from. Everything is drawn from tritri::Rng, so a
// seed names the same pairs on every toolchain.
#pragma once

#include "cases/util/random.hpp"
#include "tritri/geometry.hpp"

#include <cstdint>

namespace tritri::shapes {

using V = Vec3<double>;

V integer_vector(Rng& r, std::int64_t m);  // each coordinate an integer in [-m, m]

V random_in_cube(Rng& r, double half);    // each coordinate uniform in [-half, half]
// Sizes spread over two orders of magnitude (2^-6 to 1), so small triangles are rejected by the
// first plane test, long thin ones reach the interval stage, and both kinds meet.
double mixed_size(Rng& r);
// Three vertices each uniform in the cube of half-width `size` around `center`.
Triangle triangle_around(Rng& r, const V& center, double size);

// Two triangles anywhere in the unit cube, of sizes 2^-6 to 1: mostly rejected by a plane test.
TrianglePair scatter_pair(Rng& r);
// T2 centred on a point of T1: they meet about half the time, and the disjoint ones mostly
// reach the interval stage.
TrianglePair near_pair(Rng& r);
// Exactly coplanar, in dyadic coordinates.
TrianglePair coplanar_pair(Rng& r);

// Integer points o + a·e1 + b·e2 of one plane: scaled by a power of two (scaled() below) every
// coordinate stays exact.
struct IntegerPlane {
  V origin, e1, e2;
  V at(std::int64_t a, std::int64_t b) const {
    return origin + static_cast<double>(a) * e1 + static_cast<double>(b) * e2;
  }
};
IntegerPlane integer_plane(Rng& r);
// A triangle of the plane's integer points around (ca, cb).
Triangle plane_triangle(Rng& r, const IntegerPlane& plane, std::int64_t ca, std::int64_t cb);

double power_of_two_scale(Rng& r);  // 2^-7 to 2^-3
TrianglePair scaled(TrianglePair p, double scale);

}  // namespace tritri::shapes
