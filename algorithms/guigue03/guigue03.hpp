// Guigue & Devillers 2003, "Fast and Robust Triangle-Triangle Overlap Test Using Orientation
// Predicates", journal of graphics tools 8(1):25–32. doi:10.1080/10867651.2003.10487580
//
// A port of the authors' published code (jgt-code, Volume_08/Number_1/Guigue2003,
// tri_tri_intersect.c, revision of December 2003, USE_EPSILON_TEST false):
//   overlap<T>                tri_tri_overlap_test_3d
//   segment<T>                tri_tri_intersection_test_3d (the segment and the coplanar flag)
//   overlap_with_segment<T>   that function's own 0/1
// The same floating-point operations on the same operands in the same order, and a branch
// exactly where the published code branches; the answers are the published ones bit for bit
// (checked against the published C on millions of random, integer-grid and near-degenerate
// pairs). The published code is a tree of macros; here each level is a function and the
// permutation tables are written once and shared by the two variants (`canonical` below takes
// the last step as a parameter).
//
// Notation: [a,b,c,d] = (d − a)·((b − a)×(c − a)), evaluated as the published macros do: the
// two differences, their cross product, then the dot product summed x, y, z. Its base vertex a
// matters for rounding, so every call below names the base the published code uses.
//
// The published arithmetic:
//   1. N2 = (p2 − r2)×(q2 − r2); dp1, dq1, dr1 = (x − r2)·N2 for x = p1, q1, r1 (base r2).
//      Reject if dp1·dq1 > 0 and dp1·dr1 > 0 (products: an underflowing product does not
//      reject).
//   2. N1 = (q1 − p1)×(r1 − p1); dp2, dq2, dr2 = (x − r1)·N1 (note: the normal from p1, the
//      points from r1). Same rejection.
//   3. A 3×3 table on the signs of dp1, dq1, dr1 rotates T1 (and may swap q2, r2), then a second
//      table on dp2, dq2, dr2 (permuted along) rotates T2 (and may swap q1, r1). All six zero at
//      either level: coplanar, with the vertices as permuted so far and the normal N1 of step 2.
//   4. Overlap iff [q1,p2,p1,q2] ≤ 0 and [p1,p2,r1,r2] ≤ 0 on the permuted vertices (the
//      paper's [p1,q1,p2,q2] ≤ 0 and [p1,r1,r2,p2] ≤ 0 with the bases the code uses).
//   Coplanar: project dropping N1's largest |component| (ties: x needs n_x > n_z and n_x ≥ n_y;
//   y needs n_y > n_z and n_y ≥ n_x; else z) — the x and y projections also swap p and q and
//   list the coordinates (z, y) and (x, z) — then the 2-D test: orient both triangles
//   counter-clockwise by swapping their last two vertices, locate p1 against T2's edges, and
//   finish with the published edge or vertex sub-test. 2-D orientation:
//   (a − c)ₓ(b − c)ᵧ − (a − c)ᵧ(b − c)ₓ.
//   Segment variant: after step 3, up to three more orientations choose which two of the four
//   edge/plane crossings bound the segment; each crossing is x − α·(x − y) with
//   α = ((x − o)·N) / ((x − y)·N) for the original N1 or N2 (see construct_segment).
//
// Undefined behaviour in the published code: none on finite input (`*coplanar` is set only on
// the coplanar branch: the caller initialises it; here the answer kind carries it).
//
// Choices, and the predicates parameter:
// - `Predicates` supplies the orientation values. `FloatPredicates<T>` evaluates them in T as
//   published. An exact or filtered replacement may return any value of the right sign (e.g.
//   −1, 0, 1): every decision is a sign, or a product of two signs in steps 1–2 (where the
//   published code's products can underflow; an exact replacement would not reproduce that).
// - Tolerance: none. Boundary: closed. Degenerate (zero-area) triangles: not handled.
#pragma once

#include "tritri/answers.hpp"

#include <cmath>

namespace tritri::guigue03 {

template <class T>
struct Point2 {
  T x, y;
};

template <class T>
int sign_of(const T& v) {
  return v > T(0) ? 1 : (v < T(0) ? -1 : 0);
}

// The orientation values, evaluated in T exactly as the published macros evaluate them.
template <class T>
struct FloatPredicates {
  // [a,b,c,d] = (d − a)·((b − a)×(c − a)).
  static T orient3d_value(const T* a, const T* b, const T* c, const T* d) {
    const T bx = b[0] - a[0], by = b[1] - a[1], bz = b[2] - a[2];
    const T cx = c[0] - a[0], cy = c[1] - a[1], cz = c[2] - a[2];
    const T nx = by * cz - bz * cy, ny = bz * cx - bx * cz, nz = bx * cy - by * cx;
    return (d[0] - a[0]) * nx + (d[1] - a[1]) * ny + (d[2] - a[2]) * nz;
  }

  // Steps 1–2: one normal n = (b − a)×(c − a) shared by three values (x_i − base)·n. The normal
  // is also returned: the coplanar branch projects with N1 and the segment variant divides by it.
  static void plane_values(const T* a, const T* b, const T* c, const T* base, const T* x0,
                           const T* x1, const T* x2, T (&n)[3], T (&out)[3]) {
    const T bx = b[0] - a[0], by = b[1] - a[1], bz = b[2] - a[2];
    const T cx = c[0] - a[0], cy = c[1] - a[1], cz = c[2] - a[2];
    n[0] = by * cz - bz * cy;
    n[1] = bz * cx - bx * cz;
    n[2] = bx * cy - by * cx;
    out[0] = side(n, base, x0);
    out[1] = side(n, base, x1);
    out[2] = side(n, base, x2);
  }

  // (x − base)·n
  static T side(const T (&n)[3], const T* base, const T* x) {
    return (x[0] - base[0]) * n[0] + (x[1] - base[1]) * n[1] + (x[2] - base[2]) * n[2];
  }

  // 2-D orientation of (a, b, c): (a − c)ₓ(b − c)ᵧ − (a − c)ᵧ(b − c)ₓ.
  static T orient2d_value(const T* a, const T* b, const T* c) {
    return (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0]);
  }

  // Signs, for callers that want only the predicate (tests, other ports).
  static int orient3d(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Vec3<T>& d) {
    return sign_of(orient3d_value(a.data(), b.data(), c.data(), d.data()));
  }
  static int orient2d(const Point2<T>& a, const Point2<T>& b, const Point2<T>& c) {
    const T pa[2] = {a.x, a.y}, pb[2] = {b.x, b.y}, pc[2] = {c.x, c.y};
    return sign_of(orient2d_value(pa, pb, pc));
  }
};

namespace detail {

// ---- the 2-D test (tri_tri_overlap_test_2d) ----

// p1 lies beyond exactly one edge of T2 (the edge p2q2 after the caller's rotation): does T1
// reach T2 through it? The published edge sub-test.
template <class T, class P>
inline bool through_edge(const T* p1, const T* q1, const T* r1, const T* p2, const T* q2,
                         const T* r2) {
  static_cast<void>(q2);
  if (P::orient2d_value(r2, p2, q1) >= T(0)) {
    if (P::orient2d_value(p1, p2, q1) >= T(0)) return P::orient2d_value(p1, q1, r2) >= T(0);
    if (P::orient2d_value(q1, r1, p2) >= T(0)) return P::orient2d_value(r1, p1, p2) >= T(0);
    return false;
  }
  if (P::orient2d_value(r2, p2, r1) >= T(0)) {
    if (P::orient2d_value(p1, p2, r1) >= T(0)) {
      if (P::orient2d_value(p1, r1, r2) >= T(0)) return true;
      return P::orient2d_value(q1, r1, r2) >= T(0);
    }
    return false;
  }
  return false;
}

// p1 lies in the region of T2's vertex p2 (beyond the two edges at p2): the published vertex
// sub-test.
template <class T, class P>
inline bool through_vertex(const T* p1, const T* q1, const T* r1, const T* p2, const T* q2,
                           const T* r2) {
  if (P::orient2d_value(r2, p2, q1) >= T(0)) {
    if (P::orient2d_value(r2, q2, q1) <= T(0)) {
      if (P::orient2d_value(p1, p2, q1) > T(0)) return P::orient2d_value(p1, q2, q1) <= T(0);
      if (P::orient2d_value(p1, p2, r1) >= T(0)) return P::orient2d_value(q1, r1, p2) >= T(0);
      return false;
    }
    if (P::orient2d_value(p1, q2, q1) <= T(0)) {
      if (P::orient2d_value(r2, q2, r1) <= T(0)) return P::orient2d_value(q1, r1, q2) >= T(0);
      return false;
    }
    return false;
  }
  if (P::orient2d_value(r2, p2, r1) >= T(0)) {
    if (P::orient2d_value(q1, r1, r2) >= T(0)) return P::orient2d_value(p1, p2, r1) >= T(0);
    if (P::orient2d_value(q1, r1, q2) >= T(0)) return P::orient2d_value(r2, r1, q2) >= T(0);
    return false;
  }
  return false;
}

// Both triangles counter-clockwise: locate p1 against T2's three edge lines.
template <class T, class P>
inline bool ccw_overlap_2d(const T* p1, const T* q1, const T* r1, const T* p2, const T* q2,
                           const T* r2) {
  if (P::orient2d_value(p2, q2, p1) >= T(0)) {
    if (P::orient2d_value(q2, r2, p1) >= T(0)) {
      if (P::orient2d_value(r2, p2, p1) >= T(0)) return true;  // inside
      return through_edge<T, P>(p1, q1, r1, p2, q2, r2);
    }
    if (P::orient2d_value(r2, p2, p1) >= T(0)) return through_edge<T, P>(p1, q1, r1, r2, p2, q2);
    return through_vertex<T, P>(p1, q1, r1, p2, q2, r2);
  }
  if (P::orient2d_value(q2, r2, p1) >= T(0)) {
    if (P::orient2d_value(r2, p2, p1) >= T(0)) return through_edge<T, P>(p1, q1, r1, q2, r2, p2);
    return through_vertex<T, P>(p1, q1, r1, q2, r2, p2);
  }
  return through_vertex<T, P>(p1, q1, r1, r2, p2, q2);
}

template <class T, class P>
inline bool overlap_2d(const T* p1, const T* q1, const T* r1, const T* p2, const T* q2, const T* r2) {
  // make each triangle counter-clockwise by swapping its last two vertices
  if (P::orient2d_value(p1, q1, r1) < T(0)) {
    if (P::orient2d_value(p2, q2, r2) < T(0)) return ccw_overlap_2d<T, P>(p1, r1, q1, p2, r2, q2);
    return ccw_overlap_2d<T, P>(p1, r1, q1, p2, q2, r2);
  }
  if (P::orient2d_value(p2, q2, r2) < T(0)) return ccw_overlap_2d<T, P>(p1, q1, r1, p2, r2, q2);
  return ccw_overlap_2d<T, P>(p1, q1, r1, p2, q2, r2);
}

// Step 3's coplanar branch (coplanar_tri_tri3d): project and run the 2-D test.
template <class T, class P>
inline bool coplanar_3d(const T* p1, const T* q1, const T* r1, const T* p2, const T* q2,
                        const T* r2, const T (&n1)[3]) {
  const T nx = n1[0] < T(0) ? -n1[0] : n1[0];
  const T ny = n1[1] < T(0) ? -n1[1] : n1[1];
  const T nz = n1[2] < T(0) ? -n1[2] : n1[2];
  T a[3][2], b[3][2];  // T1 and T2 in the plane, in the order the 2-D test receives them
  // The published projections onto the yz and xz planes also exchange p and q (which keeps
  // the orientation the same as the xy projection's for a normal along +x or +y).
  const auto keep = [&](int u, int v, bool swap_pq) {
    const T* t1[3] = {swap_pq ? q1 : p1, swap_pq ? p1 : q1, r1};
    const T* t2[3] = {swap_pq ? q2 : p2, swap_pq ? p2 : q2, r2};
    for (int i = 0; i < 3; ++i) {
      a[i][0] = t1[i][u], a[i][1] = t1[i][v];
      b[i][0] = t2[i][u], b[i][1] = t2[i][v];
    }
  };
  if (nx > nz && nx >= ny) keep(2, 1, true);       // drop x: (z, y)
  else if (ny > nz && ny >= nx) keep(0, 2, true);  // drop y: (x, z)
  else keep(0, 1, false);                          // drop z: (x, y)
  return overlap_2d<T, P>(a[0], a[1], a[2], b[0], b[1], b[2]);
}

// ---- steps 1–3, shared by both variants ----

// The two sign tables of step 3. `Last` is the step after them: `Last::general(p1, q1, r1, p2,
// q2, r2)` on the canonical vertices, `Last::coplanar(same)` when all signs vanish.

// Second table: T1 already rotated; rotate T2 by the signs of its vertices against π1.
template <class T, class Last>
inline auto by_t2(const T* p1, const T* q1, const T* r1, const T* p2, const T* q2, const T* r2,
                  const T& dp2, const T& dq2, const T& dr2, Last& last) {
  if (dp2 > T(0)) {
    if (dq2 > T(0)) return last.general(p1, r1, q1, r2, p2, q2);
    if (dr2 > T(0)) return last.general(p1, r1, q1, q2, r2, p2);
    return last.general(p1, q1, r1, p2, q2, r2);
  }
  if (dp2 < T(0)) {
    if (dq2 < T(0)) return last.general(p1, q1, r1, r2, p2, q2);
    if (dr2 < T(0)) return last.general(p1, q1, r1, q2, r2, p2);
    return last.general(p1, r1, q1, p2, q2, r2);
  }
  if (dq2 < T(0)) {
    if (dr2 >= T(0)) return last.general(p1, r1, q1, q2, r2, p2);
    return last.general(p1, q1, r1, p2, q2, r2);
  }
  if (dq2 > T(0)) {
    if (dr2 > T(0)) return last.general(p1, r1, q1, p2, q2, r2);
    return last.general(p1, q1, r1, q2, r2, p2);
  }
  if (dr2 > T(0)) return last.general(p1, q1, r1, r2, p2, q2);
  if (dr2 < T(0)) return last.general(p1, r1, q1, r2, p2, q2);
  return last.coplanar(p1, q1, r1, p2, q2, r2);
}

// Steps 1–3. `Last::rejected()` is the answer when a plane test separates the triangles.
template <class T, class P, class Last>
inline auto canonical(const PairT<T>& pair, T (&n1)[3], T (&n2)[3], Last& last) {
  const T* p1 = pair.t1[0].data();
  const T* q1 = pair.t1[1].data();
  const T* r1 = pair.t1[2].data();
  const T* p2 = pair.t2[0].data();
  const T* q2 = pair.t2[1].data();
  const T* r2 = pair.t2[2].data();
  T d1[3], d2[3];
  P::plane_values(r2, p2, q2, r2, p1, q1, r1, n2, d1);  // step 1: N2 from r2, base r2
  if (d1[0] * d1[1] > T(0) && d1[0] * d1[2] > T(0)) return last.rejected();
  P::plane_values(p1, q1, r1, r1, p2, q2, r2, n1, d2);  // step 2: N1 from p1, base r1
  if (d2[0] * d2[1] > T(0) && d2[0] * d2[2] > T(0)) return last.rejected();
  const T &dp1 = d1[0], &dq1 = d1[1], &dr1 = d1[2];
  const T &dp2 = d2[0], &dq2 = d2[1], &dr2 = d2[2];
  // First table: rotate T1 by the signs of its vertices against π2.
  if (dp1 > T(0)) {
    if (dq1 > T(0)) return by_t2(r1, p1, q1, p2, r2, q2, dp2, dr2, dq2, last);
    if (dr1 > T(0)) return by_t2(q1, r1, p1, p2, r2, q2, dp2, dr2, dq2, last);
    return by_t2(p1, q1, r1, p2, q2, r2, dp2, dq2, dr2, last);
  }
  if (dp1 < T(0)) {
    if (dq1 < T(0)) return by_t2(r1, p1, q1, p2, q2, r2, dp2, dq2, dr2, last);
    if (dr1 < T(0)) return by_t2(q1, r1, p1, p2, q2, r2, dp2, dq2, dr2, last);
    return by_t2(p1, q1, r1, p2, r2, q2, dp2, dr2, dq2, last);
  }
  if (dq1 < T(0)) {
    if (dr1 >= T(0)) return by_t2(q1, r1, p1, p2, r2, q2, dp2, dr2, dq2, last);
    return by_t2(p1, q1, r1, p2, q2, r2, dp2, dq2, dr2, last);
  }
  if (dq1 > T(0)) {
    if (dr1 > T(0)) return by_t2(p1, q1, r1, p2, r2, q2, dp2, dr2, dq2, last);
    return by_t2(q1, r1, p1, p2, q2, r2, dp2, dq2, dr2, last);
  }
  if (dr1 > T(0)) return by_t2(r1, p1, q1, p2, q2, r2, dp2, dq2, dr2, last);
  if (dr1 < T(0)) return by_t2(r1, p1, q1, p2, r2, q2, dp2, dr2, dq2, last);
  return last.coplanar(p1, q1, r1, p2, q2, r2);
}

// Step 4 of the overlap test.
template <class T, class P>
struct OverlapLast {
  const T (&n1)[3];

  bool rejected() const { return false; }
  bool general(const T* p1, const T* q1, const T* r1, const T* p2, const T* q2, const T* r2) const {
    if (P::orient3d_value(q1, p2, p1, q2) > T(0)) return false;
    return !(P::orient3d_value(p1, p2, r1, r2) > T(0));
  }
  bool coplanar(const T* p1, const T* q1, const T* r1, const T* p2, const T* q2, const T* r2) const {
    return coplanar_3d<T, P>(p1, q1, r1, p2, q2, r2, n1);
  }
};

// ---- the segment variant ----

// A crossing on the line: x − α·(x − y), α = ((x − o)·N) / ((x − y)·N), the point where edge
// x→y meets the plane through o with normal N.
template <class T>
inline void crossing(const T* x, const T* y, const T* o, const T (&n)[3], T (&out)[3]) {
  const T xo[3] = {x[0] - o[0], x[1] - o[1], x[2] - o[2]};
  const T xy[3] = {x[0] - y[0], x[1] - y[1], x[2] - y[2]};
  const T alpha = (xo[0] * n[0] + xo[1] * n[1] + xo[2] * n[2]) / (xy[0] * n[0] + xy[1] * n[1] + xy[2] * n[2]);
  out[0] = x[0] - alpha * xy[0];
  out[1] = x[1] - alpha * xy[1];
  out[2] = x[2] - alpha * xy[2];
}

enum class SegmentOutcome { disjoint, coplanar_meet, coplanar_apart, segment };

template <class T, class P>
struct SegmentLast {
  const T (&n1)[3];
  const T (&n2)[3];
  T (&source)[3];
  T (&target)[3];

  SegmentOutcome rejected() const { return SegmentOutcome::disjoint; }
  SegmentOutcome coplanar(const T* p1, const T* q1, const T* r1, const T* p2, const T* q2,
                          const T* r2) const {
    return coplanar_3d<T, P>(p1, q1, r1, p2, q2, r2, n1) ? SegmentOutcome::coplanar_meet
                                                         : SegmentOutcome::coplanar_apart;
  }
  // The published CONSTRUCT_INTERSECTION: the overlap decision and, when they meet, which
  // crossings bound the segment: i on p1q1 / j on p1r1 (with N2), k on p2q2 / l on p2r2 (with N1).
  SegmentOutcome general(const T* p1, const T* q1, const T* r1, const T* p2, const T* q2,
                         const T* r2) const {
    if (P::orient3d_value(p1, q1, r2, p2) > T(0)) {
      if (!(P::orient3d_value(p1, r1, r2, p2) <= T(0))) return SegmentOutcome::disjoint;
      if (P::orient3d_value(p1, r1, q2, p2) > T(0)) {
        crossing(p1, r1, p2, n2, source);  // j
      } else {
        crossing(p2, q2, p1, n1, source);  // k
      }
      crossing(p2, r2, p1, n1, target);  // l
      return SegmentOutcome::segment;
    }
    if (P::orient3d_value(p1, q1, q2, p2) < T(0)) return SegmentOutcome::disjoint;
    if (P::orient3d_value(p1, r1, q2, p2) >= T(0)) {
      crossing(p1, r1, p2, n2, source);  // j
    } else {
      crossing(p2, q2, p1, n1, source);  // k
    }
    crossing(p1, q1, p2, n2, target);  // i
    return SegmentOutcome::segment;
  }
};

}  // namespace detail

// ---- tri_tri_overlap_test_3d ----

template <class T, class Predicates = FloatPredicates<T>>
bool overlap(const PairT<T>& pair) {
  T n1[3], n2[3];
  const detail::OverlapLast<T, Predicates> last{n1};
  return detail::canonical<T, Predicates>(pair, n1, n2, last);
}

// ---- tri_tri_intersection_test_3d ----

template <class T, class Predicates = FloatPredicates<T>>
SegmentAnswer segment(const PairT<T>& pair) {
  using detail::SegmentOutcome;
  SegmentAnswer out;
  out.kind = SegmentKind::empty;
  T n1[3], n2[3], source[3], target[3];
  const detail::SegmentLast<T, Predicates> last{n1, n2, source, target};
  switch (detail::canonical<T, Predicates>(pair, n1, n2, last)) {
    case SegmentOutcome::disjoint:
    case SegmentOutcome::coplanar_apart: return out;
    case SegmentOutcome::coplanar_meet: out.kind = SegmentKind::coplanar; return out;
    case SegmentOutcome::segment: break;
  }
  out.p = Vec3<double>(static_cast<double>(source[0]), static_cast<double>(source[1]), static_cast<double>(source[2]));
  out.q = Vec3<double>(static_cast<double>(target[0]), static_cast<double>(target[1]), static_cast<double>(target[2]));
  out.kind = out.p == out.q ? SegmentKind::point : SegmentKind::segment;
  return out;
}

// The segment variant's own 0/1 (its overlap decision uses other orientations than the
// overlap test's step 4, so the two booleans can differ where a determinant rounds to 0).
template <class T, class Predicates = FloatPredicates<T>>
bool overlap_with_segment(const PairT<T>& pair) {
  T n1[3], n2[3], source[3], target[3];  // the segment is constructed, as published, not returned
  const detail::SegmentLast<T, Predicates> last{n1, n2, source, target};
  const auto o = detail::canonical<T, Predicates>(pair, n1, n2, last);
  return o == detail::SegmentOutcome::segment || o == detail::SegmentOutcome::coplanar_meet;
}

}  // namespace tritri::guigue03
