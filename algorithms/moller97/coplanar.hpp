// Möller's coplanar_tri_tri (jgt-code 1c80455, Volume_02/Number_2/Moller1997b/tritri_isectline.c),
// in its own header because three other ports call it as their published code does: tropp06 and
// shen03 (the authors' files carry a copy of it) and brute (its coplanar branch). The arithmetic,
// the projection's tie rules and the order of the tests are the published ones (see
// algorithms/moller97/moller97.hpp, "the published arithmetic").
#pragma once

#include <cmath>

namespace tritri::moller97::detail {

// ---- the coplanar test (Möller's coplanar_tri_tri; also used by tropp06, shen03, brute) ----

// Antonio's segment test (Graphics Gems III) between edge (v0, v0 + (ax, ay)) and edge (u0, u1)
// in the projection (i0, i1). Endpoints count; a zero f (parallel edges) never reports.
template <class T>
inline bool edges_cross(int i0, int i1, const T& ax, const T& ay, const T* v0, const T* u0,
                        const T* u1) {
  const T bx = u0[i0] - u1[i0], by = u0[i1] - u1[i1];
  const T cx = v0[i0] - u0[i0], cy = v0[i1] - u0[i1];
  const T f = ay * bx - ax * by;
  const T d = by * cx - bx * cy;
  if ((f > T(0) && d >= T(0) && d <= f) || (f < T(0) && d <= T(0) && d >= f)) {
    const T e = ax * cy - ay * cx;
    if (f > T(0)) {
      if (e >= T(0) && e <= f) return true;
    } else {
      if (e <= T(0) && e >= f) return true;
    }
  }
  return false;
}

template <class T>
inline bool edge_crosses_triangle(int i0, int i1, const T* v0, const T* v1, const T* u0,
                                  const T* u1, const T* u2) {
  const T ax = v1[i0] - v0[i0], ay = v1[i1] - v0[i1];
  return edges_cross(i0, i1, ax, ay, v0, u0, u1) || edges_cross(i0, i1, ax, ay, v0, u1, u2) ||
         edges_cross(i0, i1, ax, ay, v0, u2, u0);
}

// The value of p against the line through a and b, as the published code writes it: the line
// a·x + b·y + c = 0 with a = Δy, b = −Δx, c = −a·x0 − b·y0.
template <class T>
inline T line_value(int i0, int i1, const T* p, const T* from, const T* to) {
  const T a = to[i1] - from[i1];
  const T b = -(to[i0] - from[i0]);
  const T c = -a * from[i0] - b * from[i1];
  return a * p[i0] + b * p[i1] + c;
}

// Strictly inside: the three values have one sign (as products) and none is zero.
template <class T>
inline bool strictly_inside(int i0, int i1, const T* p, const T* u0, const T* u1, const T* u2) {
  const T d0 = line_value(i0, i1, p, u0, u1);
  const T d1 = line_value(i0, i1, p, u1, u2);
  const T d2 = line_value(i0, i1, p, u2, u0);
  return d0 * d1 > T(0) && d0 * d2 > T(0);
}

template <class T>
inline bool coplanar_tri_tri(const T* n, const T* v0, const T* v1, const T* v2, const T* u0,
                             const T* u1, const T* u2) {
  using std::abs;
  // Keep the two axes other than N's largest |component| (ties as published).
  const T a0 = abs(n[0]), a1 = abs(n[1]), a2 = abs(n[2]);
  int i0, i1;
  if (a0 > a1) {
    if (a0 > a2) i0 = 1, i1 = 2;
    else i0 = 0, i1 = 1;
  } else {
    if (a2 > a1) i0 = 0, i1 = 1;
    else i0 = 0, i1 = 2;
  }
  if (edge_crosses_triangle(i0, i1, v0, v1, u0, u1, u2)) return true;
  if (edge_crosses_triangle(i0, i1, v1, v2, u0, u1, u2)) return true;
  if (edge_crosses_triangle(i0, i1, v2, v0, u0, u1, u2)) return true;
  // no edge crossing: one triangle inside the other, or apart
  return strictly_inside(i0, i1, v0, u0, u1, u2) || strictly_inside(i0, i1, u0, v0, v1, v2);
}

// The same, given the normal by value and kept out of line, for a caller whose state must stay
// in registers (moller97's Planes::coplanar, shen03's coplanar exit).
template <class T>
[[gnu::noinline]] bool coplanar_tri_tri_out_of_line(T nx, T ny, T nz, const T* v0, const T* v1, const T* v2,
                                                    const T* u0, const T* u1, const T* u2) {
  const T n[3] = {nx, ny, nz};
  return coplanar_tri_tri(n, v0, v1, v2, u0, u1, u2);
}

}  // namespace tritri::moller97::detail
