// A plane value's bound from its own triangle's extents (one_pair.hpp `sign_o3_within`): the value
// of a vertex x against the plane of the other triangle abc, (x - a)·((b - a)×(c - a)) as
// det3_eval evaluates it, has two of its three difference rows inside abc's own box, so its
// rounding error is bounded by the pair's extents times abc's extents squared, where the pair's
// bound B takes the pair's extents cubed. Proof, constants and measurements: algorithms/exact/MEASUREMENTS.md,
// "Values within the bound off the grid: where `sign_o3_within`'s instructions go".
#pragma once

#include "algorithms/exact/detail/pair_box.hpp"

#include <cstring>

namespace tritri::exact::detail {

// 17u ≥ 2γ8 with the nine roundings of the bound's own evaluation (the proof in MEASUREMENTS.md, cited above).
inline constexpr double kRelPlane = 17.0 * bound::kU;

// The bound for the values against the plane of the triangle at `t` (its nine coordinates):
// kRelPlane·(E_x e_y e_z + E_y e_z e_x + E_z e_x e_y) + kAbs3 with E_k = 2·mag_k (mag: the pair's
// largest |coordinate| per axis, box_magnitudes) and e the triangle's own extents, each raised to
// kMin3 as det3_bound raises them; +inf unless every 2·mag_k is at most kMax3. Finite coordinates.
inline double plane_bound(const double* t, const double (&mag)[3]) {
  const Double2 most = {bound::kMax3, bound::kMax3}, least = {bound::kMin3, bound::kMin3};
  const Double2 mxy = {2.0 * mag[0], 2.0 * mag[1]}, mz = {2.0 * mag[2], 2.0 * mag[2]};
  if ((le2(mxy, most) & le2(mz, most)) != 3u) return __builtin_inf();
  Double2 lo, hi, p;
  std::memcpy(&lo, t, sizeof lo);
  hi = lo;
  double lo_z = t[2], hi_z = t[2];
  for (int v = 1; v < 3; ++v) {
    std::memcpy(&p, t + 3 * v, sizeof p);
    lo = p < lo ? p : lo, hi = p > hi ? p : hi;
    lo_z = t[3 * v + 2] < lo_z ? t[3 * v + 2] : lo_z, hi_z = t[3 * v + 2] > hi_z ? t[3 * v + 2] : hi_z;
  }
  const Double2 exy = max2(hi - lo, least), big = max2(mxy, least);
  const double ez = dmax(hi_z - lo_z, bound::kMin3), bz = dmax(mz[0], bound::kMin3);
  // lane 0: E_x·(e_y·e_z), lane 1: E_y·(e_x·e_z); then + E_z·(e_x·e_y)
  const Double2 two = big * (swapped(exy) * Double2{ez, ez});
  const double s = (two[0] + two[1]) + bz * (exy[0] * exy[1]);
  return kRelPlane * s + bound::kAbs3;
}

// The bounds of one pair's two planes, each computed on the first plane value that asks.
struct PlaneBounds {
  unsigned known = 0;  // bit 0: T1's plane, bit 1: T2's
  double t[2];
  // the bound for values against the plane of the triangle with first vertex `a` (0: T1, 3: T2)
  double of(const double* c, const double (&mag)[3], int a) {
    const int i = a != 0;
    if (!(known >> i & 1u)) t[i] = plane_bound(c + 3 * a, mag), known |= 1u << i;
    return t[i];
  }
};

// The exact sign of o3 of the pair's points a, b, cc, d (0..5) off the grid: the pair's shared
// integer conversion when every axis fits, 40 bits in __int128 first ("Zeros off the grid, 40 bits
// per axis"), else 61 ("Zeros off the grid"); else the per-call filters and the integer engine.
// `Grid`: one_pair.hpp's LazyGrid. Out of line, so that the registers its integers need are saved
// here and not on sign_o3_within's other returns (inlined there, they were saved on its entry).
template <class Grid>
[[gnu::noinline]] int sign_o3_converted(Grid& g, int a, int b, int cc, int d) {
  if (const int i[6] = {a, b, a, cc, a, d}; g.converted())
    return g.ints == 2 ? intexact::det3_pair40_sign(g.x, i) : intexact::det3_pair_sign(g.x, i);
  return Filtered::o3(g.c + 3 * a, g.c + 3 * b, g.c + 3 * cc, g.c + 3 * d);
}

}  // namespace tritri::exact::detail
