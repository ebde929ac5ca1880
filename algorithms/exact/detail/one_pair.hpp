// One pair per call (exact.hpp's `overlap` / `relation`): the batch kernel's first pass for one
// pair, in Guigue–Devillers' order with their early exits, then the shared-vertex and shared-edge
// shortcuts, then the exact scalar classification (scalar.hpp) for whatever is left.
//
//   boxes     overlap level: the vertices' boxes apart along an axis (and finite input) ->
//             disjoint, exactly, before any arithmetic;
//   flat      six points whose box has a zero z extent leave before the values (which would be
//             zeros): in the plane z = h, decided in 2-D on (x, y) (`flat_first`);
//   filter    one semi-static bound B for the pair (the extents of its six points, as the
//             kernel's pair_bound; algorithms/exact/README.md, "Shared bounds"), then
//             step 1: T1's signs against π2; all certain and equal -> disjoint (overlap level);
//             step 2: T2's against π1, likewise; the relation level answers one-sided pairs
//             only with both triangles certainly proper and the planes certainly not parallel;
//             step 3: six certain signs -> the canonical order by table look-ups, G1 and G2;
//             G1 > B or G2 > B -> disjoint, both < -B -> they meet (`cross`).
//   shared    exact coordinate equality of vertices (finite input only): at the overlap level a
//             shared vertex is a common point; at the relation level the filter's signs decide a
//             shared vertex (`touch_point`) or a shared edge (`touch_segment`) when certain.
//   exact     the six plane signs made exact (the grid test once, axis by axis; off it, against
//             a triangle in an axis-parallel plane by comparisons and one o2, else the pair's
//             integer conversion or the per-call filters and the integer engine); crossing and
//             one-sided pairs decided from them with the pair's bound for G1, G2; coplanar proper
//             pairs in 2-D (coplanar.hpp); degenerate pairs by the classification.
// Each exit and shortcut is proved in algorithms/exact/README.md, "One pair per call" and
// "Exact signs after the filter".
#pragma once

#include "algorithms/exact/detail/coplanar.hpp"
#include "algorithms/exact/detail/crossing.hpp"
#include "algorithms/exact/detail/finish_front.hpp"
#include "algorithms/exact/detail/grid_axes.hpp"
#include "algorithms/exact/detail/pair_box.hpp"
#include "algorithms/exact/detail/plane_bound.hpp"
#include "algorithms/exact/detail/scalar.hpp"

#include <array>
#include <cstdint>
#include <cstring>

namespace tritri::exact::detail {

// The signed distances the filter computed and the bound they share.
struct PairSigns {
  Box box;  // of the six points
  double bound;
  double s1[3];   // T1's vertices against π2: (x - a2)·((b2 - a2)×(c2 - a2))
  double s2[3];   // T2's vertices against π1
  unsigned open;  // bit k: s1[k] within the bound, bit 3 + k: s2[k] (neither > B nor < -B)
};

// An interleaved six-bit mask (bit 2k: T1's vertex k, 2k + 1: T2's, as plane_values' lanes)
// as PairSigns::open orders its bits: T1's three, then T2's.
inline constexpr auto kSplit = [] {
  std::array<unsigned char, 64> t{};
  for (unsigned m = 0; m < 64; ++m)
    for (unsigned k = 0; k < 3; ++k) t[m] |= ((m >> (2 * k)) & 1u) << k | ((m >> (2 * k + 1)) & 1u) << (3 + k);
  return t;
}();

// The planes are certainly not parallel: two distances to one plane differ by more than 3B.
inline bool certainly_slanted(const double s[3], double b) {
  return (std::fabs(s[1] - s[0]) > 3.0 * b) | (std::fabs(s[2] - s[0]) > 3.0 * b);
}

// 1: they meet (relation: `cross`); 0: disjoint; -1: undecided (then `ps` holds both triangles'
// values and the bound); with kFlat, -2: the six points' box has a zero z extent (then ps.box is
// that box, and no value is computed: `flat_first` takes the pair).
template <bool kRelation, bool kFlat = true>
[[gnu::always_inline]] inline int filter_pair(const double* c, PairSigns& ps) {
  Box b1, b2;
  boxes_of(c, b1, b2);
  // step 0 (overlap level): the vertices' boxes apart -> disjoint. At the relation level the
  // answer could be `parallel` or `degenerate`, so there the bound comes first.
  if constexpr (!kRelation)
    if (boxes_apart(b1, b2) && finite18(c)) return 0;
  const Box u = union_of(b1, b2);
  // a zero z extent leaves before the values, through the bound's own branch
  double b;
  if (!bound_unless_flat(u, b)) [[unlikely]] {
    if (kFlat && u.lo_z == u.hi_z) {
      ps.box = u;
      return -2;
    }
    b = bound_of_box(u);
  }
  // steps 1 and 2 together (lane 0: T1 against π2, lane 1: T2 against π1)
  Double2 s[3];
  plane_values(c, s);
  const Double2 hi = {b, b}, lo = -hi;
  // overlap level: either triangle one-sided -> disjoint, one branch for both
  if constexpr (!kRelation)
    if (either_one_sided(hi, lo, s)) return 0;
  const unsigned p[3] = {lt2(hi, s[0]), lt2(hi, s[1]), lt2(hi, s[2])};
  const unsigned n[3] = {lt2(s[0], lo), lt2(s[1], lo), lt2(s[2], lo)};
  // bits 2k, 2k + 1: s1[k], s2[k] certain and positive (pos) or negative (neg)
  const unsigned pos = p[0] | p[1] << 2 | p[2] << 4, neg = n[0] | n[1] << 2 | n[2] << 4;
  const double s1[3] = {s[0][0], s[1][0], s[2][0]}, s2[3] = {s[0][1], s[1][1], s[2][1]};
  // the values are written to `ps` only when the pair is left undecided
  const auto undecided = [&](Box box) {
    ps.bound = b, ps.open = ~kSplit[pos | neg] & 63u, ps.box = box;
    for (int k = 0; k < 3; ++k) ps.s1[k] = s1[k], ps.s2[k] = s2[k];
    return -1;
  };
  if constexpr (kRelation) {
    const unsigned sp = kSplit[pos], sn = kSplit[neg];  // T1's three bits, then T2's
    if (((sp & 7u) == 7u) | ((sn & 7u) == 7u) | (sp >= 070u) | (sn >= 070u)) {
      // one-sided: `disjoint` once both are certainly proper (a certain sign against a plane
      // proves its triangle proper) and the planes certainly not parallel; else undecided
      const bool proper = ((sp | sn) & 7u) != 0u && ((sp | sn) & 070u) != 0u;
      if (proper & (certainly_slanted(s1, b) | certainly_slanted(s2, b))) return 0;
      return undecided(u);
    }
  }
  if ((pos | neg) != 63u) return undecided(u);  // a sign within the bound
  const Double2 gg = gd_values(c, kSplit[pos]);  // step 3: G1, G2
  // on the larger of G1, G2 (finite here): one branch per exit, where the two comparisons of
  // each were compiled as two branches on random signs
  const double g = dmax(gg[0], gg[1]);
  if (g > b) return 0;
  if (g < -b) return 1;
  // G1 or G2 within the bound: the box again rather than kept through step 3, where most pairs
  // are decided
  return undecided(union_of(box_of(c), box_of(c + 9)));
}

// All 18 coordinates finite. A finite bound and six values of which none is NaN prove it (a NaN
// coordinate makes three values NaN, an infinite one the bound +inf: algorithms/exact/README.md,
// "The fixed cost of `finish`"); else the coordinates themselves decide.
inline bool finite_after_filter(const double* c, const PairSigns& ps) {
  const double sum = ((ps.s1[0] + ps.s1[1]) + (ps.s1[2] + ps.s2[0])) + (ps.s2[1] + ps.s2[2]);
  return ((ps.bound < __builtin_inf()) & (sum == sum)) || finite18(c);
}

// The sign of a filter value when certain, else 0.
inline int certain_sign(double s, double b) { return (s > b) - (s < -b); }

// The relation of finite triangles with shared vertices (`bits` non-zero, from shared_vertices)
// when the filter's certain signs decide it; Relation::unsupported otherwise (undecided).
inline Relation shared_relation(unsigned bits, const PairSigns& ps) {
  int s1[3], s2[3];
  for (int k = 0; k < 3; ++k) s1[k] = certain_sign(ps.s1[k], ps.bound), s2[k] = certain_sign(ps.s2[k], ps.bound);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (!((bits >> (3 * i + j)) & 1u)) continue;
      const int a = (i + 1) % 3, b = (i + 2) % 3, c = (j + 1) % 3, d = (j + 2) % 3;
      // shared vertex: the other two of one triangle strictly on one side of the other's plane,
      // and a certain non-zero sign against each plane (both triangles proper)
      if ((s1[a] * s1[b] > 0 && (s2[c] | s2[d]) != 0) || (s2[c] * s2[d] > 0 && (s1[a] | s1[b]) != 0))
        return Relation::touch_point;
      // shared edge: T1's vertex a (or b) also equals one of T2's other two, and T1's third
      // vertex is certainly off π2
      const unsigned other = (bits >> (3 * a)) & ((1u << c) | (1u << d));
      if (other && s1[b] != 0) return Relation::touch_segment;
      const unsigned other_b = (bits >> (3 * b)) & ((1u << c) | (1u << d));
      if (other_b && s1[a] != 0) return Relation::touch_segment;
    }
  return Relation::unsupported;
}

// The pair's grid test and its shared integer conversion, each evaluated at most once per pair
// and only when a value within the bound needs it (`state`, `ints`: -1 not yet known, 0 no, 1 yes,
// 2 yes in 40 bits). The largest |coordinate| per axis comes from the filter's box (finite: exact).
struct LazyGrid {
  // `grid` 1: known on the grid; else unknown (so `points` is on_grid's whenever state is 0)
  LazyGrid(const double* pair, const Box& box, int grid) : c(pair), state(grid > 0 ? 1 : -1) { box_magnitudes(box, mag); }
  const double* c;
  int state;
  int ints = -1;
  unsigned points = 0u;  // off the grid: grid_points' mask from on_grid, when `want_points`
  bool want_points = true;
  double mag[3];
  intexact::PairInt61 x;
  bool on() {
    if (state < 0) state = on_grid(c, mag, points, want_points) ? 1 : 0;
    return state != 0;
  }
  bool converted() {  // x unset until needed; 2: every |X| < 2^40 (pair_to_int40), 1: below 2^61
    if (ints < 0) ints = intexact::pair_to_int40(c, mag, x) ? 2 : intexact::pair_to_int61(c, mag, x) ? 1 : 0;
    return ints != 0;
  }
};

// sign_o3_within's last steps, off the grid: the pair's shared integer conversion when every axis
// fits, 40 bits in __int128 first (algorithms/exact/README.md, "Zeros off the grid, 40 bits per
// axis"), else 61 ("Zeros off the grid"); else the per-call filters and the integer engine. Apart
// so that the steps before keep no registers to save.
[[gnu::noinline]] inline int sign_o3_converted(LazyGrid& g, int a, int b, int cc, int d) {
  if (const int i[6] = {a, b, a, cc, a, d}; g.converted())
    return g.ints == 2 ? intexact::det3_pair40_sign(g.x, i) : intexact::det3_pair_sign(g.x, i);
  return Filtered::o3(g.c + 3 * a, g.c + 3 * b, g.c + 3 * cc, g.c + 3 * d);
}

// The exact sign of o3(a, b, cc, d) for the pair's points with indices a, b, cc, d (0..5), given
// a value `v` of it evaluated in det3_eval's shape and the pair's bound, valid for every such
// value (algorithms/exact/README.md, "Shared bounds"): certain beyond the bound; within it, on
// the grid the value is exact ("The grid case"), and off it when its own four points are on it ("A
// value's own points on the grid"); else sign_o3_converted. (The certain case and a grid already
// known inline, the rest out of line: most calls are one of those.)
[[gnu::noinline]] inline int sign_o3_within(double v, LazyGrid& g, int a, int b, int cc, int d) {
  if (g.on()) return sgn(v);  // the first value within the bound tests the grid
  // off it, the value's own four points on it: exact ("A value's own points on the grid")
  if (const unsigned own = point_bits(a, b, cc, d); g.points != 0u && (g.points & own) == own) return sgn(v);
  return sign_o3_converted(g, a, b, cc, d);
}
[[gnu::always_inline]] inline int sign_o3(double v, double bound, LazyGrid& g, int a, int b, int cc, int d) {
  if (v > bound) return 1;
  if (v < -bound) return -1;
  if (g.state == 1) return sgn(v);  // on the grid, known: no call
  return sign_o3_within(v, g, a, b, cc, d);
}

// Crossing planes (classify.hpp's `crossing`) from the six exact plane signs, both triangles
// proper, neither sign triple one-sided nor all zero: the canonical order by one kCanon row, G1
// and G2 in two lanes against the pair's bound (one branch per exit, as the filter's step 3; the
// values are finite when B is, and no comparison with B = +inf holds), then their exact signs
// (algorithms/exact/README.md, "Crossing planes from exact signs: one table row, G1 and G2 in two
// lanes").
template <bool kRelation>
[[gnu::always_inline]] inline Relation crossing_known(const double* c, const int s1[3], const int s2[3], double bound,
                                                     LazyGrid& g) {
  const unsigned char* o = kCanon[27 * sign_index(s1) + sign_index(s2)].data();
  const Double2 gg = gd_lanes(c, o);
  const double hi = dmax(gg[0], gg[1]);
  if (hi > bound) return Relation::disjoint;
  int g1 = -1, g2 = -1;  // both certainly negative unless a value is within the bound
  if (!(hi < -bound)) {
    g1 = sign_o3(gg[0], bound, g, o[0] / 3, o[1] / 3, o[3] / 3, o[4] / 3);
    if (g1 > 0) return Relation::disjoint;
    g2 = sign_o3(gg[1], bound, g, o[0] / 3, o[2] / 3, o[5] / 3, o[3] / 3);
    if (g2 > 0) return Relation::disjoint;
  }
  if (!kRelation) return Relation::cross;  // meets
  if (g1 == 0 || g2 == 0 || s1[o[0] / 3] == 0 || s2[o[3] / 3 - 3] == 0) return Relation::touch_point;
  return (zero_count(s1) == 2 || zero_count(s2) == 2) ? Relation::touch_segment : Relation::cross;
}

// After an undecided filter (`grid`: the pair is known to pass the grid test, so plain double is
// exact for it): non-finite input declined; the shared-vertex shortcuts; the six plane signs made
// exact (certain ones kept, the others resolved one by one); one-sided, crossing and coplanar pairs
// decided from them; the rest (degenerate, parallel candidates) by the classification. Proved in
// algorithms/exact/README.md, "Exact signs after the filter"; at the overlap level only the
// emptiness of the answer counts (classify.hpp).
template <bool kRelation>
RelationAnswer finish(const TrianglePair& pair, const PairSigns& ps, bool grid, Route* route) {
  const double* c = pair.t1[0].data();
  // the comparisons need no finiteness, their answer does (algorithms/exact/README.md, "The grid
  // test first: finiteness, flat pairs and the signs from it")
  if (const unsigned bits = shared_vertices<!kRelation>(c, shared_candidates(ps.open)); bits != 0u) {
    if (!finite_after_filter(c, ps)) return solve<kRelation>(pair, route);  // declines
    const Relation rel = kRelation ? shared_relation(bits, ps) : Relation::touch_point;  // a common point
    if (rel != Relation::unsupported) {
      if (route) *route = Route::shared;
      return answer_with(rel);
    }
  }
  LazyGrid g{c, ps.box, grid ? 1 : -1};
  // T1's three values computed as zeros: off the grid the flat and coplanar steps decide most such
  // pairs, not sign_o3_within, so the own-points mask is not made for them (0: no shortcut)
  const bool zero1 = all_zero3(ps.s1);
  g.want_points = !zero1;
  // a value within the bound needs the grid test: made here, a pass proves the coordinates finite
  if (!(!grid && ps.open != 0u && g.on()) && !finite_after_filter(c, ps)) return solve<kRelation>(pair, route);
  // T1's three values computed as zeros on the grid: its exact signs, and the coplanar step decides
  // (algorithms/exact/README.md, "Coplanar pairs on the grid straight from the filter's zeros")
  if (zero1 && g.state == 1) {
    if (route) *route = Route::grid;
    if (Relation rel; coplanar_grid<kRelation>(c, rel)) return answer_with(rel);
    return solve<kRelation>(pair, route);  // a degenerate triangle
  }
  const double b = ps.bound;
  // every value certain or exact (on the grid): the six signs are the values' own
  const bool exact = (ps.open == 0u) | (g.state == 1);
  int known[6];
  if (exact) {
    value_signs(ps.s1, ps.s2, known);
  } else {
    // off the grid: six points on one axis-parallel plane prove T1's zeros without arithmetic
    // (their values are computed zeros); a value within the bound against a triangle in an
    // axis-parallel plane by comparisons and one o2; else its exact sign one by one
    if (zero1 && flat_pair(c))
      known[0] = known[1] = known[2] = 0;
    else if (!((ps.open & 7u) != 0u && axis_plane_signs(c + 9, c, known)))
      // t: π2's own bound for a small T2 (algorithms/exact/README.md, "A plane's own bound")
      for (const double t = plane_bound(c + 9, ps.box, b, ps.open, 007u); const int k : {0, 1, 2})
        known[k] = sign_o3(ps.s1[k], t, g, 3, 4, 5, k);
  }
  // T1 in π2 (all three exact signs zero): coplanar when both are proper, decided in 2-D
  // (coplanar.hpp); degenerate input goes on to the classification (exact: zero1 failed, a sign not)
  const bool any1 = exact || (known[0] | known[1] | known[2]) != 0;
  if (Relation rel; !any1 && coplanar_known<kRelation>(c, g, rel)) {
    if (route) *route = g.state == 1 ? Route::grid : Route::filtered;
    return answer_with(rel);
  }
  // T1 in π2 (all zero): T2 degenerate, or T1 ⊂ π2 and then, both proper, π1 = π2 and T2 ⊂ π1;
  // the classification reads s2 only when both are proper, so zeros are its exact signs
  if (!any1)
    known[3] = known[4] = known[5] = 0;
  else if (!exact && !((ps.open & 070u) != 0u && axis_plane_signs(c, c + 9, known + 3)))
    for (const double t = plane_bound(c, ps.box, b, ps.open, 070u); const int k : {0, 1, 2})
      known[3 + k] = sign_o3(ps.s2[k], t, g, 0, 1, 2, 3 + k);
  const bool any2 = (known[3] | known[4] | known[5]) != 0;
  if (any1 & any2) {  // both triangles proper, the planes distinct
    const bool one1 = one_sided(known), one2 = one_sided(known + 3);
    if (!(one1 | one2) || !kRelation || !(one1 & one2)) {
      if (route) *route = g.state == 1 ? Route::grid : Route::filtered;
      if (one1 | one2) return answer_with(Relation::disjoint);  // parallel planes: both one-sided
      return answer_with(crossing_known<kRelation>(c, known, known + 3, b, g));
    }
  }
  Tri t1, t2;
  double unused[18];
  gather(pair, t1, t2, unused);
  if (g.on()) {
    if (route) *route = Route::grid;
    return classify<Plain, kRelation>(t1, t2, known);
  }
  if (route) *route = Route::filtered;
  return classify<Filtered, kRelation>(t1, t2, known);
}

// `finish`, after the route for six points in one plane z = h: the box's z extent zero, and T1's
// values computed zeros, which proves every coordinate finite; then (x, y) on the 2-D grid
// decides, before the shared-vertex scan and the 3-D grid test (algorithms/exact/README.md, "Six
// points in one plane z = h: (x, y) before the 3-D grid test"). Here rather than in `finish`: there
// its test had cost the other pairs 1.5 % more instructions (registers), here 0.6 %.
template <bool kRelation>
[[gnu::always_inline]] inline RelationAnswer finish_pair(const TrianglePair& pair, const PairSigns& ps, bool grid,
                                                        Route* route) {
  if (ps.box.lo_z == ps.box.hi_z) [[unlikely]] {
    if (Relation rel; all_zero3(ps.s1) && coplanar_flat_z<kRelation>(pair.t1[0].data(), ps.box, rel)) {
      if (route) *route = Route::grid;
      return answer_with(rel);
    }
  }
  return finish<kRelation>(pair, ps, grid, route);
}

// The filter without the test for a zero z extent, then `finish`: flat_first's way on when its
// route does not decide. Out of line, so that flat_first keeps no registers for it.
template <bool kRelation>
[[gnu::noinline]] RelationAnswer filter_and_finish(const TrianglePair& pair, bool grid, Route* route) {
  PairSigns ps;
  const int r = filter_pair<kRelation, false>(pair.t1[0].data(), ps);
  if (r < 0) return finish<kRelation>(pair, ps, grid, route);
  if (route) *route = Route::filter;
  return answer_with(r ? Relation::cross : Relation::disjoint);
}

// A pair whose six points' box `u` has a zero z extent, before the filter's values (which would
// all be zeros there): the six z equal and finite, then coplanar_flat_z, whose 2-D grid test
// refuses a non-finite x or y (algorithms/exact/README.md, "Six points in one plane z = h,
// before the filter's values"); else filter_and_finish. Out of line, so that the filter keeps
// nothing across a call.
template <bool kRelation>
[[gnu::noinline]] RelationAnswer flat_first(const TrianglePair& pair, const Box& u, bool grid, Route* route) {
  const double* c = pair.t1[0].data();
  // the box skips a NaN z but no infinite one: with lo_z = hi_z finite, the six z are equal
  // unless one is NaN, and then so is their sum
  const double sum = ((c[2] + c[5]) + (c[8] + c[11])) + (c[14] + c[17]);
  if (Relation rel; (std::fabs(u.lo_z) <= 0x1.fffffffffffffp1023) & (sum == sum) && coplanar_flat_z<kRelation>(c, u, rel)) {
    if (route) *route = Route::grid;
    return answer_with(rel);
  }
  return filter_and_finish<kRelation>(pair, grid, route);
}

// One pair: the filter, then `finish` (or `flat_first`).
template <bool kRelation>
RelationAnswer decide(const TrianglePair& pair, bool grid, Route* route) {
  PairSigns ps;
  const int r = filter_pair<kRelation>(pair.t1[0].data(), ps);
  if (r == -1) return finish<kRelation>(pair, ps, grid, route);
  if (r == -2) return flat_first<kRelation>(pair, ps.box, grid, route);
  if (route) *route = Route::filter;
  return answer_with(r ? Relation::cross : Relation::disjoint);
}

inline Overlap to_overlap(const RelationAnswer& a) {
  if (a.relation == Relation::unsupported) return Overlap::unsupported;
  return meets(a) ? Overlap::yes : Overlap::no;
}

inline Overlap overlap_one_pair(const TrianglePair& pair) {
  PairSigns ps;
  const int r = filter_pair<false>(pair.t1[0].data(), ps);
  if (r >= 0) return static_cast<Overlap>(r);
  if (r == -2) return to_overlap(flat_first<false>(pair, ps.box, false, nullptr));
  return to_overlap(finish<false>(pair, ps, false, nullptr));
}

inline RelationAnswer relation_one_pair(const TrianglePair& pair) { return decide<true>(pair, false, nullptr); }

}  // namespace tritri::exact::detail
