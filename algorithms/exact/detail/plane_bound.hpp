// A plane's own bound (one_pair.hpp `finish`): the values of one triangle's vertices x against the
// other triangle's plane abc, (x - a)·((b - a)×(c - a)) in det3_eval's shape, have two of their
// three difference rows inside abc's own box, so their rounding error is bounded by the pair's
// extents times abc's extents squared, where the pair's bound B takes the pair's extents cubed. A
// plane triangle much smaller than the pair (all three values against it within B, and not all
// three against the other plane) gets its values' signs from it without the pair's integers.
// Proof: algorithms/exact/README.md, "A plane's own bound: a small plane triangle".
#pragma once

#include "algorithms/exact/detail/pair_box.hpp"

namespace tritri::exact::detail {

// 17u: at least 2γ8 after the nine roundings of the bound's own evaluation (the README heading above).
inline constexpr double kRelPlane = 17.0 * bound::kU;

// kRelPlane·(E_x e_y e_z + E_y e_z e_x + E_z e_x e_y) + kAbs3 for the plane of the triangle at `t`
// (its nine coordinates): E the extents of `pair` (the six points' box, whose extents are at most
// kMax3: the caller's B is finite), e the triangle's own, each raised to kMin3 as bound_of_box
// raises them. Finite coordinates.
inline double own_plane_bound(const double* t, const Box& pair) {
  const Box own = box_of(t);
  const Double2 least = {bound::kMin3, bound::kMin3};
  const Double2 e = max2(own.hi - own.lo, least), big = max2(pair.hi - pair.lo, least);
  const double ez = dmax(own.hi_z - own.lo_z, bound::kMin3), bz = dmax(pair.hi_z - pair.lo_z, bound::kMin3);
  // lane 0: E_x·(e_y·e_z), lane 1: E_y·(e_x·e_z); then E_z·(e_x·e_y)
  const Double2 xy = big * (swapped(e) * Double2{ez, ez});
  return kRelPlane * ((xy[0] + xy[1]) + bz * (e[0] * e[1])) + bound::kAbs3;
}

// The bound for the three values against the plane of the triangle at `t`: its own when `open`
// (PairSigns::open) has the three bits `three` (007: T1's values against π2, t = T2; 070: T2's
// against π1, t = T1) and not all three of the other plane's, else the pair's B. Then a value
// against the other plane is beyond B, so B is finite, and the plane triangle is small, or thin,
// beside the pair (coplanar and nearly coplanar pairs of like-sized triangles have all six within
// B, touching pairs one or two against a plane).
[[gnu::always_inline]] inline double plane_bound(const double* t, const Box& pair, double b, unsigned open,
                                                 unsigned three) {
  const unsigned certain = ~open & 077u;  // some, and none of `three`
  return ((certain != 0u) & ((certain & three) == 0u)) ? own_plane_bound(t, pair) : b;
}

}  // namespace tritri::exact::detail
