// Shen, Heng & Tang 2003, "A Fast Triangle-Triangle Overlap Test Using Signed Distances",
// journal of graphics tools 8(1), 2003.
//
// The paper was not at hand; what is known of it is its abstract ("signed
// vertex-plane distances (sufficient if one triangle is wholly to one side of the other) and
// signed line-line distances of selected edges (otherwise)") and that it decides like
// Guigue–Devillers with an absolute tolerance of 1e-7. Steps:
//   1. signed distances of T1's vertices to plane(T2); all beyond the tolerance on one side:
//      reject
//   2. the same for T2 against plane(T1)
//   3. all within the tolerance: coplanar, 2-D test
//   4. order each triangle so its lone vertex comes first (Guigue–Devillers' table, on the
//      tolerant signs)
//   5. the intervals on L overlap iff the signed distances of the line pairs (p1q1, p2q2) and
//      (p1r1, r2p2) are both ≤ the tolerance
//
// Choices (reconstructed, since the paper's text is not at hand):
// - "Signed distance" is taken literally: vertex–plane distances use the unit normal, and the
//   line–line distance of lines ab and cd is [a,b,c,d] / |(b − a)×(d − c)|, the orientation
//   determinant divided by the norm that makes it a length. Both are lengths, so a single
//   absolute tolerance means the same thing for both.
// - Tolerance: kTolerance = 1e-7, absolute, a length in input units. A distance d counts as
//   zero when |d| ≤ 1e-7. Boundary: closed with that slack (near misses count as touching).
// - The lone-vertex table is Guigue–Devillers' (from ../guigue03), applied to the tolerant
//   signs; the coplanar branch is Guigue–Devillers' sign-only 2-D test, exact.
// - Degenerate (zero-area) triangles: not handled (the unit normal divides by zero).
#pragma once

#include "algorithms/guigue03/guigue03.hpp"

#include "tritri/answers.hpp"

#include <cmath>

namespace tritri::shen03 {

inline constexpr double kTolerance = 1e-7;  // absolute, a length

template <class T>
int tolerant_sign(const T& d) {
  return d > T(kTolerance) ? 1 : (d < -T(kTolerance) ? -1 : 0);
}

template <class T>
Vec3<T> unit_normal(const TriangleT<T>& t) {
  using std::sqrt;
  const Vec3<T> n = (t[1] - t[0]).cross(t[2] - t[0]);
  return n / sqrt(n.dot(n));
}

// Signed distance from line ab to line cd, with the sign of the orientation [a,b,c,d].
template <class T>
T line_distance(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Vec3<T>& d) {
  using std::sqrt;
  const Vec3<T> m = (b - a).cross(d - c);
  return (d - a).dot((b - a).cross(c - a)) / sqrt(m.dot(m));
}

template <class T>
void signed_distances(const TriangleT<T>& plane_of, const TriangleT<T>& t, T (&d)[3], int (&s)[3]) {
  const Vec3<T> n = unit_normal(plane_of);
  for (int i = 0; i < 3; ++i) {
    d[i] = n.dot(t[i] - plane_of[0]);
    s[i] = tolerant_sign(d[i]);
  }
}

template <class T>
bool overlap(const PairT<T>& pair) {
  T d1[3], d2[3];
  int s1[3], s2[3];
  signed_distances(pair.t2, pair.t1, d1, s1);  // step 1
  if (guigue03::one_sided(s1)) return false;
  signed_distances(pair.t1, pair.t2, d2, s2);  // step 2
  if (guigue03::one_sided(s2)) return false;
  if (guigue03::all_zero(s1) || guigue03::all_zero(s2))  // step 3
    return guigue03::coplanar_overlap(pair.t1, pair.t2);
  const auto c = guigue03::canonical_from_signs<T>(pair, s1, s2);  // step 4
  const auto& [p1, q1, r1] = c.t1.v;
  const auto& [p2, q2, r2] = c.t2.v;
  return line_distance(p1, q1, p2, q2) <= T(kTolerance) &&  // step 5
         line_distance(p1, r1, r2, p2) <= T(kTolerance);
}

}  // namespace tritri::shen03
