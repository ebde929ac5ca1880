// Building blocks of the canonical frame: T1 in the plane z = 0 with edge AB on the x-axis and
// C on the side y > 0. T1's coordinates are multiples of 8, so every point with barycentric
// weights in eighths is an integer point: vertices, edge points and interior points are all
// exact, and the singularities built from them are exact too.
#pragma once

#include "cases/generator/construction.hpp"

namespace tritri::corpus {

inline TrianglePair pair_of(const Triangle& t1, const V3& p, const V3& q, const V3& r) {
  return {t1, Triangle{{p, q, r}}};
}

inline Triangle canonical_t1(Rng& rng, double unit = 8) {
  const int a = rng.between(1, 3), c = rng.between(1, 3), b = rng.between(-1, a + 1);
  return Triangle{{v3(0, 0, 0), v3(unit * a, 0, 0), v3(unit * b, unit * c, 0)}};
}

// (wa·A + wb·B + wc·C) / 8, with wa + wb + wc = 8.
inline V3 bary(const Triangle& t, int wa, int wb, int wc) {
  return (double(wa) * t[0] + double(wb) * t[1] + double(wc) * t[2]) / 8.0;
}

// Strictly inside: every weight at least 1/8.
inline V3 interior_point(Rng& rng, const Triangle& t) {
  const int wa = rng.between(1, 6), wb = rng.between(1, 7 - wa);
  return bary(t, wa, wb, 8 - wa - wb);
}

// Strictly inside edge e, the edge from vertex e to vertex e+1.
inline V3 edge_point(Rng& rng, const Triangle& t, int e) {
  const int w = rng.between(1, 7);
  return (double(w) * t[e] + double(8 - w) * t[(e + 1) % 3]) / 8.0;
}

// A random integer vector strictly above the plane z = 0.
inline V3 upward(Rng& rng, int reach = 6) {
  const double x = rng.between(-reach, reach), y = rng.between(-reach, reach), z = rng.between(1, reach);
  return v3(x, y, z);
}

// A random integer vector off the plane z = 0, above or below it.
inline V3 off_plane(Rng& rng) {
  V3 r = upward(rng, 10);
  if (rng.sign() < 0) r.z() = -r.z();
  return r;
}

// A random non-zero integer vector in the plane z = 0.
inline V3 in_plane(Rng& rng, int reach = 6) {
  for (;;) {
    const double x = rng.between(-reach, reach), y = rng.between(-reach, reach);
    if (x != 0 || y != 0) return v3(x, y, 0);
  }
}

// A point of the plane z = 0 reached from a boundary point of T1 by going directly away from an
// interior point: from an edge point it lands strictly across that edge's line, from a vertex
// strictly inside the vertex's opposite cone. Either way the segment from `from` to it meets
// T1 only at `from`.
inline V3 away_from(Rng& rng, const Triangle& t, const V3& from) {
  const double k = rng.between(1, 2);
  return from - k * (interior_point(rng, t) - from);
}

}  // namespace tritri::corpus
