// The brute-force test: each closed edge of each triangle against the other triangle, plus a
// coplanar branch. It is the baseline of
//   Tomas Möller. A Fast Triangle-Triangle Intersection Test. journal of graphics tools
//   2(2):25–30, 1997, §3 and footnote 1
// ("each closed edge of each triangle is tested for intersection with the other triangle and if,
// at any time, an intersection occurs, then the triangles intersect. However, this method does
// not (easily) handle cases where one or three edges are parallel to the plane of the other
// triangle"), which took 1.3–1.6 times as long as Möller's interval test in RAPID.
//
// The paper gives no code. Choices, and what this port does:
// - The segment-vs-triangle test is Möller & Trumbore's ray–triangle test (journal of graphics
//   tools 2(1):21–28, 1997, same author, same year), non-culling, with divisions, on the edge
//   p → q as a ray with direction q − p and the ray parameter limited to [0, 1]. Closed: every
//   bound is inclusive.
// - An edge parallel to the other plane (MT's determinant exactly 0, including an edge lying in
//   that plane) is skipped, as the footnote says the method does: such contacts are found only
//   through the neighbouring edges, which meet the plane at the shared endpoints. The published
//   MT code skips |det| < 1e-6; this port uses exact zero, so its only tolerance-free failures
//   come from rounding the barycentrics u, v and t.
// - Coplanar branch: only when all six edges were parallel to the other plane (the planes are
//   parallel); then one distance decides parallel vs coplanar, and coplanar pairs go to Möller's
//   coplanar test (from ../moller97, the routine of the same author and period).
// - Order: T1's three edges against T2, then T2's against T1; the first hit answers.
// - Degenerate (zero-area) triangles: not handled.
#pragma once

#include "algorithms/moller97/moller97.hpp"  // Möller's coplanar test

#include "tritri/answers.hpp"

namespace tritri::brute {

struct EdgeResult {
  bool hit = false;
  bool parallel = false;  // det == 0: the edge is parallel to (or in) the triangle's plane
};

// Möller–Trumbore on the closed segment [p, q] against the closed triangle.
template <class T>
EdgeResult segment_hits_triangle(const Vec3<T>& p, const Vec3<T>& q, const TriangleT<T>& t) {
  EdgeResult r;
  const Vec3<T> e1 = t[1] - t[0], e2 = t[2] - t[0];
  const Vec3<T> dir = q - p;
  const Vec3<T> pvec = dir.cross(e2);
  const T det = e1.dot(pvec);
  if (det == T(0)) {
    r.parallel = true;
    return r;
  }
  const T inv = T(1) / det;
  const Vec3<T> tvec = p - t[0];
  const T u = tvec.dot(pvec) * inv;
  if (u < T(0) || u > T(1)) return r;
  const Vec3<T> qvec = tvec.cross(e1);
  const T v = dir.dot(qvec) * inv;
  if (v < T(0) || u + v > T(1)) return r;
  const T s = e2.dot(qvec) * inv;  // the ray parameter: where along the edge
  r.hit = s >= T(0) && s <= T(1);
  return r;
}

template <class T>
bool overlap(const PairT<T>& pair) {
  bool all_parallel = true;
  for (int pass = 0; pass < 2; ++pass) {
    const TriangleT<T>& from = pass == 0 ? pair.t1 : pair.t2;
    const TriangleT<T>& against = pass == 0 ? pair.t2 : pair.t1;
    for (int k = 0; k < 3; ++k) {
      const EdgeResult e = segment_hits_triangle(from[k], from[(k + 1) % 3], against);
      if (e.hit) return true;
      all_parallel = all_parallel && e.parallel;
    }
  }
  if (!all_parallel) return false;
  // every edge parallel to the other plane: parallel or coplanar planes
  const Vec3<T> n1 = (pair.t1[1] - pair.t1[0]).cross(pair.t1[2] - pair.t1[0]);
  if (n1.dot(pair.t2[0] - pair.t1[0]) != T(0)) return false;
  return moller97::coplanar_overlap(n1, pair.t1, pair.t2);
}

}  // namespace tritri::brute
