// Pair generators shared by the differential test, the unit tests and the fuzzer.
#pragma once

#include "cases/util/random.hpp"
#include "tritri/geometry.hpp"

#include <cmath>
#include <cstdint>

namespace exact_pairs {

using tritri::Triangle;
using tritri::TrianglePair;
using V = tritri::Vec3<double>;

// tritri's one generator, under the short names the generators below use.
struct GenRng : tritri::Rng {
  using tritri::Rng::Rng;
  using tritri::Rng::uniform;
  std::uint64_t bits() { return next(); }
  double uniform() { return unit(); }
  bool coin() { return next() >> 63; }
};

inline V cube(GenRng& r, double h) { return {r.uniform(-h, h), r.uniform(-h, h), r.uniform(-h, h)}; }

inline Triangle around(GenRng& r, const V& c, double s) { return {{c + s * cube(r, 1), c + s * cube(r, 1), c + s * cube(r, 1)}}; }

inline double mixed_size(GenRng& r) { return std::exp2(r.uniform(-6.0, 0.0)); }

// Random triangles of mixed sizes: half scattered in the unit cube, half centred on a point of
// the first triangle (as the bench's ratio pools do).
inline TrianglePair random_pair(GenRng& r) {
  if (r.coin()) {
    const V c1(r.uniform(), r.uniform(), r.uniform()), c2(r.uniform(), r.uniform(), r.uniform());
    return {around(r, c1, mixed_size(r)), around(r, c2, mixed_size(r))};
  }
  const V c(r.uniform(), r.uniform(), r.uniform());
  const Triangle t1 = around(r, c, mixed_size(r));
  double a = r.uniform(), b = r.uniform();
  if (a + b > 1) a = 1 - a, b = 1 - b;
  const V at = t1[0] + a * (t1[1] - t1[0]) + b * (t1[2] - t1[0]);
  return {t1, around(r, at, mixed_size(r))};
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

}  // namespace exact_pairs
