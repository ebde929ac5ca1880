// One pair per call (exact.hpp's `overlap` / `relation`): the batch kernel's first pass for one
// pair, in Guigue–Devillers' order with their early exits, then the shared-vertex and shared-edge
// shortcuts, then the exact scalar classification (scalar.hpp) for whatever is left.
//
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
// Each exit and shortcut is proved in algorithms/exact/README.md, "One pair per call".
#pragma once

#include "algorithms/exact/detail/scalar.hpp"

#include <cstdint>
#include <cstring>

namespace tritri::exact::detail {

// The signed distances the filter computed and the bound they share.
struct PairSigns {
  double bound;
  double s1[3];  // T1's vertices against π2: (x - a2)·((b2 - a2)×(c2 - a2))
  double s2[3];  // T2's vertices against π1
};

// (x_k - a)·((b - a)×(c - a)) for the three vertices x_k at `pts` and the plane of a b c at `pl`,
// evaluated as det3_eval evaluates o3 (the kernel's plane_distances, one pair).
inline void plane_values(const double* pl, const double* pts, double s[3]) {
  const double ux = pl[3] - pl[0], uy = pl[4] - pl[1], uz = pl[5] - pl[2];
  const double vx = pl[6] - pl[0], vy = pl[7] - pl[1], vz = pl[8] - pl[2];
  const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  for (int k = 0; k < 3; ++k) {
    const double* x = pts + 3 * k;
    s[k] = ((x[0] - pl[0]) * nx + (x[1] - pl[1]) * ny) + (x[2] - pl[2]) * nz;
  }
}

// Two doubles in one SSE2 / NEON register (GCC vector extension): x and y of a point.
using Double2 = double __attribute__((vector_size(16)));

// The kernel's B for one pair (pair_bound3's value), +inf unless every extent is at most kMax3.
// Minima and maxima by `<` / `>` (an unordered comparison keeps the running value): an infinite
// coordinate leaves its axis' minimum at -inf or maximum at +inf, or both NaN (a NaN first
// coordinate), so the extent is +inf or NaN and B = +inf; a NaN coordinate met later is skipped,
// but makes every value it enters NaN. Either way no comparison with B below is true.
inline double one_pair_bound(const double* c) {
  Double2 lo, hi;
  std::memcpy(&lo, c, sizeof lo);
  hi = lo;
  double lo_z = c[2], hi_z = c[2];
  for (int v = 1; v < 6; ++v) {
    Double2 p;
    std::memcpy(&p, c + 3 * v, sizeof p);
    lo = p < lo ? p : lo;
    hi = p > hi ? p : hi;
    lo_z = c[3 * v + 2] < lo_z ? c[3 * v + 2] : lo_z;
    hi_z = c[3 * v + 2] > hi_z ? c[3 * v + 2] : hi_z;
  }
  const Double2 e = hi - lo;
  const double ex = e[0], ey = e[1], ez = hi_z - lo_z;
  if (!(ex <= bound::kMax3 && ey <= bound::kMax3 && ez <= bound::kMax3)) return __builtin_inf();
  return bound::kRel3 * dmax(ex, bound::kMin3) * dmax(ey, bound::kMin3) * dmax(ez, bound::kMin3) + bound::kAbs3;
}

// Bits of the certainly positive (pos) and certainly negative (neg) values among three.
inline unsigned above(const double s[3], double b) { return (s[0] > b) | (s[1] > b) << 1 | (s[2] > b) << 2; }
inline unsigned below(const double s[3], double b) { return (s[0] < -b) | (s[1] < -b) << 1 | (s[2] < -b) << 2; }

// The planes are certainly not parallel: two distances to one plane differ by more than 3B.
inline bool certainly_slanted(const double s[3], double b) {
  return (std::fabs(s[1] - s[0]) > 3.0 * b) | (std::fabs(s[2] - s[0]) > 3.0 * b);
}

// Guigue–Devillers' G1 = [p1,q1,p2,q2] and G2 = [p1,r1,r2,p2] on six certain non-zero signs,
// `pos1` / `pos2` the bits of the positive ones (each in 1..6): the lone vertex is the one whose
// sign differs from the other two, and a triangle's flip (its lone vertex negative) swaps q and r
// of the other, as in classify.hpp's `crossing`. Evaluated as the kernel's gd_determinants.
[[gnu::always_inline]] inline void gd_values(const double* c, unsigned pos1, unsigned pos2, double& g1, double& g2) {
  // vertex offsets (p, q, r) with the lone vertex first, per sign pattern; and the flip
  static constexpr unsigned char kOrder[8][3] = {{0, 3, 6}, {0, 3, 6}, {3, 6, 0}, {6, 0, 3},
                                                 {6, 0, 3}, {3, 6, 0}, {0, 3, 6}, {0, 3, 6}};
  static constexpr bool kFlip[8] = {false, false, false, true, false, true, true, true};
  const unsigned char* o1 = kOrder[pos1];
  const unsigned char* o2 = kOrder[pos2];
  const double* p1 = c + o1[0];
  const double* p2 = c + 9 + o2[0];
  const double* q1 = c + o1[kFlip[pos2] ? 2 : 1];
  const double* r1 = c + o1[kFlip[pos2] ? 1 : 2];
  const double* q2 = c + 9 + o2[kFlip[pos1] ? 2 : 1];
  const double* r2 = c + 9 + o2[kFlip[pos1] ? 1 : 2];
  const double dx = p2[0] - p1[0], dy = p2[1] - p1[1], dz = p2[2] - p1[2];
  const double ex = q1[0] - p1[0], ey = q1[1] - p1[1], ez = q1[2] - p1[2];
  g1 = ((q2[0] - p1[0]) * (ey * dz - ez * dy) + (q2[1] - p1[1]) * (ez * dx - ex * dz)) +
       (q2[2] - p1[2]) * (ex * dy - ey * dx);
  const double gx = r1[0] - p1[0], gy = r1[1] - p1[1], gz = r1[2] - p1[2];
  const double hx = r2[0] - p1[0], hy = r2[1] - p1[1], hz = r2[2] - p1[2];
  g2 = (dx * (gy * hz - gz * hy) + dy * (gz * hx - gx * hz)) + dz * (gx * hy - gy * hx);
}

// 1: they meet (relation: `cross`); 0: disjoint; -1: undecided (then `ps` holds both triangles'
// values and the bound).
template <bool kRelation>
[[gnu::always_inline]] inline int filter_pair(const double* c, PairSigns& ps) {
  const double b = one_pair_bound(c);
  ps.bound = b;
  plane_values(c + 9, c, ps.s1);  // step 1: T1 against π2
  const unsigned pos1 = above(ps.s1, b), neg1 = below(ps.s1, b);
  if constexpr (!kRelation)
    if ((pos1 == 7u) | (neg1 == 7u)) return 0;
  plane_values(c, c + 9, ps.s2);  // step 2: T2 against π1
  const unsigned pos2 = above(ps.s2, b), neg2 = below(ps.s2, b);
  if constexpr (!kRelation) {
    if ((pos2 == 7u) | (neg2 == 7u)) return 0;
  } else if ((pos1 == 7u) | (neg1 == 7u) | (pos2 == 7u) | (neg2 == 7u)) {
    // one-sided: `disjoint` once both are certainly proper (a certain sign against a plane
    // proves its triangle proper) and the planes certainly not parallel; else undecided
    const bool proper = ((pos1 | neg1) != 0u) & ((pos2 | neg2) != 0u);
    return proper & (certainly_slanted(ps.s1, b) | certainly_slanted(ps.s2, b)) ? 0 : -1;
  }
  if (((pos1 | neg1) != 7u) | ((pos2 | neg2) != 7u)) return -1;  // a sign within the bound
  double g1, g2;
  gd_values(c, pos1, pos2, g1, g2);  // step 3
  if ((g1 > b) | (g2 > b)) return 0;
  return (g1 < -b) & (g2 < -b) ? 1 : -1;
}

// All 18 coordinates finite: x - x is 0 for finite x and NaN otherwise.
inline bool finite18(const double* c) {
  double z = 0.0;
  for (int i = 0; i < 18; ++i) z += c[i] - c[i];
  return z == 0.0;
}

// Bit 3i + j: T1's vertex i equals T2's vertex j (exact comparison of the coordinates).
inline unsigned shared_vertices(const double* c) {
  unsigned bits = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double* a = c + 3 * i;
      const double* d = c + 9 + 3 * j;
      bits |= static_cast<unsigned>((a[0] == d[0]) & (a[1] == d[1]) & (a[2] == d[2])) << (3 * i + j);
    }
  return bits;
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

// The kernel's grid test (grid_lanes) for one pair: max|coordinate| m in [2^-344, 2^300) and every
// coordinate x a multiple of 2^q, q = e - 14 for 2^e <= m < 2^(e+1): fl(fl(x + C) - C) = x with
// C = 1.5·2^(q+52) built from m's exponent bits (algorithms/exact/README.md, "The grid case (pass 2
// and `Plain`)"). Then every value the filter computed is exact.
inline bool on_grid(const double* c) {
  double m = 0.0;
  for (int i = 0; i < 18; ++i) m = dmax(m, std::fabs(c[i]));
  if (!(m >= 0x1p-344 && m < 0x1p300)) return false;
  std::uint64_t bits;
  std::memcpy(&bits, &m, sizeof bits);
  bits = ((bits & 0x7ff0000000000000ull) + (38ull << 52)) | (1ull << 51);
  double big;
  std::memcpy(&big, &bits, sizeof big);
  bool grid = true;
  for (int i = 0; i < 18; ++i) grid &= (c[i] + big) - big == c[i];
  return grid;
}

// After an undecided filter: the shortcuts, then the classification (`grid`: the pair is known to
// pass grid_exact, so plain double is exact for it). At the overlap level only the emptiness of
// the answer counts (classify.hpp).
template <bool kRelation>
RelationAnswer finish(const TrianglePair& pair, const PairSigns& ps, bool grid, Route* route) {
  const double* c = pair.t1[0].data();
  if (const unsigned bits = shared_vertices(c); bits != 0u && finite18(c)) {
    const Relation rel = kRelation ? shared_relation(bits, ps) : Relation::touch_point;  // a common point
    if (rel != Relation::unsupported) {
      if (route) *route = Route::shared;
      return answer_with(rel);
    }
  }
  if (!grid && !on_grid(c)) return solve<kRelation>(pair, route);
  if (route) *route = Route::grid;
  Tri t1, t2;
  double unused[18];
  gather(pair, t1, t2, unused);
  // on the grid the filter's values are exact: their signs are the plane signs
  const int known[6] = {sgn(ps.s1[0]), sgn(ps.s1[1]), sgn(ps.s1[2]), sgn(ps.s2[0]), sgn(ps.s2[1]), sgn(ps.s2[2])};
  return classify<Plain, kRelation>(t1, t2, known);
}

// One pair: the filter, then `finish`.
template <bool kRelation>
RelationAnswer decide(const TrianglePair& pair, bool grid, Route* route) {
  PairSigns ps;
  const int r = filter_pair<kRelation>(pair.t1[0].data(), ps);
  if (r < 0) return finish<kRelation>(pair, ps, grid, route);
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
  return to_overlap(finish<false>(pair, ps, false, nullptr));
}

inline RelationAnswer relation_one_pair(const TrianglePair& pair) { return decide<true>(pair, false, nullptr); }

}  // namespace tritri::exact::detail
