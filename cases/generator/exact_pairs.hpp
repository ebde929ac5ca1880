// The exact algorithm's test generators (algorithms/exact/tests): random pairs of mixed sizes,
// small-integer pairs, and the scalings, translations and perturbations that move them off the
// grid. Drawn from shapes.hpp's pieces, so the bench, these tests and the hunt share them.
#pragma once

#include "cases/generator/shapes.hpp"
#include "cases/util/random.hpp"
#include "tritri/geometry.hpp"

#include <cmath>
#include <cstdint>

namespace tritri::exact_pairs {

using V = Vec3<double>;

// tritri's one generator, with uniform() for a draw in [0, 1) as these generators spell it.
struct GenRng : Rng {
  using Rng::Rng;
  using Rng::uniform;
  double uniform() { return unit(); }
};

inline V cube(GenRng& r, double h) { return shapes::random_in_cube(r, h); }

// Random triangles of mixed sizes: half scattered in the unit cube (shapes::scatter_pair), half
// centred on a point of the first triangle.
inline TrianglePair random_pair(GenRng& r) {
  if (r.coin()) return shapes::scatter_pair(r);
  const V c(r.uniform(), r.uniform(), r.uniform());
  const Triangle t1 = shapes::triangle_around(r, c, shapes::mixed_size(r));
  double a = r.uniform(), b = r.uniform();
  if (a + b > 1) a = 1 - a, b = 1 - b;
  const V at = t1[0] + a * (t1[1] - t1[0]) + b * (t1[2] - t1[0]);
  return {t1, shapes::triangle_around(r, at, shapes::mixed_size(r))};
}

inline V int_vec(GenRng& r, int m) {
  return V(static_cast<double>(r.integer(-m, m)), static_cast<double>(r.integer(-m, m)),
           static_cast<double>(r.integer(-m, m)));
}

// Coordinates in -m..m: shared vertices, coplanar pairs, touching, degenerate triangles.
inline TrianglePair small_int_pair(GenRng& r, int m = 3) {
  TrianglePair p;
  for (auto& v : p.t1.v) v = int_vec(r, m);
  for (auto& v : p.t2.v) v = int_vec(r, m);
  // Make shared vertices and planes more frequent.
  const auto k = r.integer(0, 5);
  if (k == 0) p.t2[0] = p.t1[r.integer(0, 2)];
  if (k == 1) {
    p.t2[0] = p.t1[0];
    p.t2[1] = p.t1[1];
  }
  if (k == 2) {  // force T2 into T1's plane where possible: z = 0 for both
    for (auto& v : p.t1.v) v.z() = 0;
    for (auto& v : p.t2.v) v.z() = 0;
  }
  return p;
}

inline TrianglePair scaled(TrianglePair p, int e) {
  for (Triangle* t : {&p.t1, &p.t2})
    for (auto& v : t->v)
      for (int k = 0; k < 3; ++k) v[k] = std::ldexp(v[k], e);
  return p;
}

inline TrianglePair translated(TrianglePair p, const V& d) {
  for (Triangle* t : {&p.t1, &p.t2})
    for (auto& v : t->v) v += d;
  return p;
}

// A singular pair moved off its singularity: one coordinate of one vertex changed by a few
// ulps, or by δ times the pair's size.
inline TrianglePair perturbed(TrianglePair p, GenRng& r) {
  Triangle& t = r.coin() ? p.t1 : p.t2;
  V& v = t[static_cast<int>(r.integer(0, 2))];
  const int k = static_cast<int>(r.integer(0, 2));
  if (r.coin()) {
    const int steps = static_cast<int>(r.integer(1, 3));
    for (int s = 0; s < steps; ++s) v[k] = std::nextafter(v[k], r.coin() ? INFINITY : -INFINITY);
  } else {
    const double delta = std::ldexp(1.0, -static_cast<int>(r.integer(10, 60)));
    v[k] += (r.coin() ? delta : -delta) * (1.0 + std::fabs(v[k]));
  }
  return p;
}

// A pair whose coordinates mix extreme magnitudes (exercises the GMP engine).
inline TrianglePair wide_pair(GenRng& r) {
  TrianglePair p = small_int_pair(r, 3);
  for (Triangle* t : {&p.t1, &p.t2})
    for (auto& v : t->v)
      for (int k = 0; k < 3; ++k)
        if (r.integer(0, 3) == 0) v[k] = std::ldexp(v[k] + r.uniform(-0.5, 0.5), static_cast<int>(r.integer(-1070, 1000)));
  return p;
}

// A flat pair in the plane where axis k is 3, at 26 bits: o2(u, w, p) = +1 exactly but 0 in
// double (off the 2-D grid); T1's third vertex is on the other side of the line uw and T2 is p
// and two points further out, so the pair is disjoint by one unit of o2.
inline TrianglePair flat_pair_one_unit_apart(int k) {
  const double u[2] = {-61731223, -55978922}, w[2] = {63032092, 64558602}, p[2] = {16672788, 19769509};
  auto put = [k](double x, double y) {
    V v;
    v[k] = 3, v[(k + 1) % 3] = x, v[(k + 2) % 3] = y;
    return v;
  };
  return {Triangle{{put(u[0], u[1]), put(w[0], w[1]), put(0, -33554432)}},
          Triangle{{put(p[0], p[1]), put(p[0], p[1] + 1000), put(p[0] - 1000, p[1])}}};
}

}  // namespace tritri::exact_pairs
