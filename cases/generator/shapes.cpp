#include "cases/generator/shapes.hpp"

#include <cmath>

namespace tritri::shapes {
V random_in_cube(Rng& r, double half) {
  return {r.uniform(-half, half), r.uniform(-half, half), r.uniform(-half, half)};
}

double mixed_size(Rng& r) { return std::exp2(r.uniform(-6.0, 0.0)); }

Triangle triangle_around(Rng& r, const V& center, double size) {
  return {{center + size * random_in_cube(r, 1), center + size * random_in_cube(r, 1),
           center + size * random_in_cube(r, 1)}};
}

V integer_vector(Rng& r, std::int64_t m) {
  return V(static_cast<double>(r.integer(-m, m)), static_cast<double>(r.integer(-m, m)),
           static_cast<double>(r.integer(-m, m)));
}

TrianglePair scatter_pair(Rng& r) {
  const V c1(r.unit(), r.unit(), r.unit()), c2(r.unit(), r.unit(), r.unit());
  return {triangle_around(r, c1, mixed_size(r)), triangle_around(r, c2, mixed_size(r))};
}

TrianglePair near_pair(Rng& r) {
  const V c(r.unit(), r.unit(), r.unit());
  const Triangle t1 = triangle_around(r, c, mixed_size(r));
  double a = r.unit(), b = r.unit();
  if (a + b > 1) a = 1 - a, b = 1 - b;
  const V at = t1[0] + a * (t1[1] - t1[0]) + b * (t1[2] - t1[0]);
  const double s = mixed_size(r);
  V d[3] = {random_in_cube(r, s), random_in_cube(r, s), random_in_cube(r, s)};
  const V mean = (d[0] + d[1] + d[2]) / 3.0;
  return {t1, {{at + d[0] - mean, at + d[1] - mean, at + d[2] - mean}}};
}

IntegerPlane integer_plane(Rng& r) {
  IntegerPlane p;
  do {
    p.e1 = integer_vector(r, 4);
    p.e2 = integer_vector(r, 4);
  } while (p.e1.cross(p.e2).isZero());
  p.origin = integer_vector(r, 64);
  return p;
}

double power_of_two_scale(Rng& r) { return std::ldexp(1.0, static_cast<int>(r.integer(-7, -3))); }

TrianglePair scaled(TrianglePair p, double scale) {
  for (Triangle* t : {&p.t1, &p.t2})
    for (auto& v : t->v) v *= scale;
  return p;
}

Triangle plane_triangle(Rng& r, const IntegerPlane& plane, std::int64_t ca, std::int64_t cb) {
  const std::int64_t w = r.integer(1, 12);
  Triangle t;
  for (auto& v : t.v) v = plane.at(ca + r.integer(-w, w), cb + r.integer(-w, w));
  return t;
}

// Two triangles of one integer plane, near each other, scaled by a power of two: every
// coordinate is exact, so they are exactly coplanar.
TrianglePair coplanar_pair(Rng& r) {
  const IntegerPlane plane = integer_plane(r);
  const auto da = r.integer(-10, 10), db = r.integer(-10, 10);
  return scaled({plane_triangle(r, plane, 0, 0), plane_triangle(r, plane, da, db)},
                power_of_two_scale(r));
}

}  // namespace tritri::shapes
