// Sabharwal & Leopold 2015, "A Triangle-Triangle Intersection Algorithm", in D. C. Wyld et al.
// (eds.), WiMo/ITCSE/ICAIT/NC 2015, Computer Science & Information Technology (CS & IT)
// pp. 27–35. doi:10.5121/csit.2015.51003
//
// The single algorithm of §3 ("The Main Algorithm"), which claims to detect, then classify
// (none / point / segment / area), any pair, crossing or coplanar:
//   X = A + uU + vV, U = B − A, V = C − A;  X = P + sS + tT, S = Q − P, T = R − P
//   (1)  uU + vV = AP + sS + tT,  AP = P − A
//   dot (1) with (U×V)×V and (U×V)×U:
//        u = −(γ·V + s α·V + t β·V),  v = γ·U + s α·U + t β·U
//        δ = (U×V)·(U×V),  α = S×(U×V)/δ,  β = T×(U×V)/δ,  γ = AP×(U×V)/δ
//   (a)  −γ·U         ≤ α·U s + β·U t ≤ 1 − γ·U          (0 ≤ v ≤ 1)
//   (b)  −1 − γ·V     ≤ α·V s + β·V t ≤ −γ·V             (0 ≤ u ≤ 1)
//   (c)  −γ·(U−V)     ≤ α·(U−V) s + β·(U−V) t ≤ 1 − γ·(U−V)
//   with 0 ≤ s, t, s + t ≤ 1; eliminate t to get s_m ≤ s ≤ s_M, then t_m(s) ≤ t ≤ t_M(s);
//   classify:  no solution → none;  s_m = s_M and t_m(s) = t_M(s) → point;
//              s_m = s_M or t_m(s) = t_M(s) for s_m ≤ s ≤ s_M → segment;  else → area.
//
// The algebra, checked. The derivation of u and v is right, and so are (a)–(c), but dotting
// (1) with two vectors that lie in ABC's plane throws away (1)'s component along the normal
// N = U×V. (N×V)·U = −δ and (N×U)·V = δ, so u and v are the barycentric coordinates of the
// orthogonal projection of P + sS + tT onto ABC's plane, whatever its height above it. The
// published system therefore decides whether the projection of PQR onto ABC's plane meets
// ABC, and the classification gives the dimension of that overlap: two triangles stacked in
// parallel planes "intersect in an area", and a crossing pair whose projections overlap is an
// "area" too. It does not decide intersection. Both are kept:
//   published<T>  — the system and classification exactly as printed (sabharwal15);
//   with_plane<T> — the same system plus the equation the derivation dropped,
//                   N·AP + s N·S + t N·T = 0 (sabharwal15-plane). For crossing planes it
//                   fixes a line in (s, t); it is solved for the variable with the larger
//                   coefficient and substituted into (a)–(c) and PQR's own bounds, leaving one
//                   interval. Parallel planes (N·S = N·T = 0) are disjoint unless N·AP = 0;
//                   then the pair is coplanar, the projection is the identity, and the
//                   published system and classification are exact in real arithmetic.
//
// Choices the paper leaves open:
// - How t_m(s) = t_M(s) "for s_m ≤ s ≤ s_M" is tested: t_M − t_m is concave (a minimum of
//   lines minus a maximum of lines) and ≥ 0 on the range, so it is zero throughout iff it is
//   zero at s_m, at s_M and at their midpoint. Those three floating-point equality tests are
//   made, exactly as the paper's "=" (no tolerance).
// - Fourier–Motzkin in floating point: each bound on t is written t = p + q s (p, q by one
//   division each); a pair of bounds (lower i, upper j) bounds s where their lines cross.
// - Feasibility is s_m ≤ s_M (the paper: "if there is no solution, return false").
// - The intersection (segment level) is read off the solution: P + sS + tT at the ends of
//   the solution set. For the published system these are points of PQR whose projections lie
//   in ABC, not intersection points: that is what the published method yields.
// - Roles: ABC = T1 (its plane fixes u, v), PQR = T2 (its s, t are solved for).
// - Degenerate triangles: δ = 0 for a zero-area ABC; not accepted.
// - No tolerance anywhere.
#pragma once

#include "tritri/answers.hpp"

#include <algorithm>
#include <cmath>

namespace tritri::sabharwal15 {

// m ≤ a s + b t ≤ n
template <class T>
struct Row {
  T m, a, b, n;
};

// (a)–(c) and PQR's own 0 ≤ s ≤ 1, 0 ≤ t ≤ 1, 0 ≤ s + t ≤ 1.
template <class T>
struct System {
  Row<T> row[6];
  // For the dropped equation: N·AP + s N·S + t N·T = 0 (N = U×V, unnormalised).
  T plane0, plane_s, plane_t;
};

template <class T>
System<T> build_system(const PairT<T>& pair) {
  const Vec3<T>& A = pair.t1[0];
  const Vec3<T> U = pair.t1[1] - A, V = pair.t1[2] - A;
  const Vec3<T>& P = pair.t2[0];
  const Vec3<T> S = pair.t2[1] - P, Tv = pair.t2[2] - P;
  const Vec3<T> AP = P - A;
  const Vec3<T> N = U.cross(V);
  const T delta = N.dot(N);
  const Vec3<T> alpha = S.cross(N) / delta;
  const Vec3<T> beta = Tv.cross(N) / delta;
  const Vec3<T> gamma = AP.cross(N) / delta;
  const Vec3<T> UmV = U - V;
  System<T> sys;
  const T gU = gamma.dot(U), gV = gamma.dot(V), gUV = gamma.dot(UmV);
  sys.row[0] = {-gU, alpha.dot(U), beta.dot(U), T(1) - gU};             // (a)
  sys.row[1] = {T(-1) - gV, alpha.dot(V), beta.dot(V), -gV};            // (b)
  sys.row[2] = {-gUV, alpha.dot(UmV), beta.dot(UmV), T(1) - gUV};       // (c)
  sys.row[3] = {T(0), T(1), T(0), T(1)};                                // 0 ≤ s ≤ 1
  sys.row[4] = {T(0), T(0), T(1), T(1)};                                // 0 ≤ t ≤ 1
  sys.row[5] = {T(0), T(1), T(1), T(1)};                                // 0 ≤ s + t ≤ 1
  sys.plane0 = N.dot(AP);
  sys.plane_s = N.dot(S);
  sys.plane_t = N.dot(Tv);
  return sys;
}

// A bound t ≥ p + q s (lower) or t ≤ p + q s (upper).
template <class T>
struct Bound {
  T p, q;
  T at(T s) const { return p + q * s; }
};

// The solution of the published system by eliminating t (Fourier–Motzkin).
template <class T>
struct Solution {
  bool feasible = false;
  T s_min = T(0), s_max = T(0);
  Bound<T> lower[6], upper[6];
  int lower_count = 0, upper_count = 0;

  T t_min(T s) const {
    T t = lower[0].at(s);
    for (int i = 1; i < lower_count; ++i) t = std::max(t, lower[i].at(s));
    return t;
  }
  T t_max(T s) const {
    T t = upper[0].at(s);
    for (int i = 1; i < upper_count; ++i) t = std::min(t, upper[i].at(s));
    return t;
  }
};

template <class T>
Solution<T> solve(const System<T>& sys) {
  Solution<T> sol;
  T s_lo = T(0), s_hi = T(1);  // PQR's 0 ≤ s ≤ 1 (row 3 states it again)
  bool contradiction = false;
  for (const Row<T>& r : sys.row) {
    if (r.b > T(0)) {
      sol.lower[sol.lower_count++] = {r.m / r.b, -r.a / r.b};
      sol.upper[sol.upper_count++] = {r.n / r.b, -r.a / r.b};
    } else if (r.b < T(0)) {
      sol.lower[sol.lower_count++] = {r.n / r.b, -r.a / r.b};
      sol.upper[sol.upper_count++] = {r.m / r.b, -r.a / r.b};
    } else if (r.a > T(0)) {
      s_lo = std::max(s_lo, r.m / r.a), s_hi = std::min(s_hi, r.n / r.a);
    } else if (r.a < T(0)) {
      s_lo = std::max(s_lo, r.n / r.a), s_hi = std::min(s_hi, r.m / r.a);
    } else if (!(r.m <= T(0) && T(0) <= r.n)) {
      contradiction = true;  // 0 = a s + b t must lie in [m, n]
    }
  }
  // Eliminate t: every lower bound must lie below every upper bound.
  for (int i = 0; i < sol.lower_count; ++i)
    for (int j = 0; j < sol.upper_count; ++j) {
      const Bound<T>& lo = sol.lower[i];
      const Bound<T>& up = sol.upper[j];
      const T dq = lo.q - up.q, dp = up.p - lo.p;  // lo ≤ up  ⟺  dq s ≤ dp
      if (dq > T(0)) {
        s_hi = std::min(s_hi, dp / dq);
      } else if (dq < T(0)) {
        s_lo = std::max(s_lo, dp / dq);
      } else if (dp < T(0)) {
        contradiction = true;
      }
    }
  sol.s_min = s_lo;
  sol.s_max = s_hi;
  sol.feasible = !contradiction && s_lo <= s_hi;
  return sol;
}

// §3's classification, with its equality tests on floating-point values.
template <class T>
Dimension classify(const Solution<T>& sol) {
  if (!sol.feasible) return Dimension::none;
  const T sm = sol.s_min, sM = sol.s_max;
  const bool single_s = sm == sM;
  const T mid = (sm + sM) / T(2);
  const bool single_t = sol.t_min(sm) == sol.t_max(sm) && sol.t_min(sM) == sol.t_max(sM) &&
                        sol.t_min(mid) == sol.t_max(mid);
  if (single_s && single_t) return Dimension::point;
  if (single_s || single_t) return Dimension::segment;
  return Dimension::area;
}

template <class T>
Vec3<double> point_of(const PairT<T>& pair, T s, T t) {
  const Vec3<T>& P = pair.t2[0];
  return (P + (pair.t2[1] - P) * s + (pair.t2[2] - P) * t).template cast<double>();
}

template <class T>
SegmentAnswer segment_from(const PairT<T>& pair, const Solution<T>& sol, Dimension d) {
  SegmentAnswer out;
  switch (d) {
    case Dimension::none: out.kind = SegmentKind::empty; break;
    case Dimension::area: out.kind = SegmentKind::area; break;
    case Dimension::point:
      out.kind = SegmentKind::point;
      out.p = out.q = point_of(pair, sol.s_min, sol.t_min(sol.s_min));
      break;
    case Dimension::segment:
      out.kind = SegmentKind::segment;
      if (sol.s_min == sol.s_max) {
        out.p = point_of(pair, sol.s_min, sol.t_min(sol.s_min));
        out.q = point_of(pair, sol.s_min, sol.t_max(sol.s_min));
      } else {
        out.p = point_of(pair, sol.s_min, sol.t_min(sol.s_min));
        out.q = point_of(pair, sol.s_max, sol.t_min(sol.s_max));
      }
      break;
    default: out.kind = SegmentKind::unsupported;
  }
  return out;
}

// ---- sabharwal15: as published ----

template <class T>
RelationAnswer published_relation(const PairT<T>& pair) {
  return {Relation::unknown, classify(solve(build_system(pair)))};
}

template <class T>
SegmentAnswer published_segment(const PairT<T>& pair) {
  const Solution<T> sol = solve(build_system(pair));
  return segment_from(pair, sol, classify(sol));
}

// ---- sabharwal15-plane: with the equation along N that the derivation dropped ----

// The solution on the line N·AP + s N·S + t N·T = 0: the free parameter (s, or t when t's
// coefficient is the smaller) runs over [lo, hi]; the other is p + q·free.
template <class T>
struct LineSolution {
  bool feasible = false;
  bool free_is_s = true;
  T lo = T(0), hi = T(0), p = T(0), q = T(0);

  void at(T free, T& s, T& t) const {
    if (free_is_s) s = free, t = p + q * free;
    else t = free, s = p + q * free;
  }
};

template <class T>
LineSolution<T> solve_on_line(const System<T>& sys) {
  using std::abs;
  LineSolution<T> sol;
  sol.free_is_s = abs(sys.plane_t) >= abs(sys.plane_s);
  const T pivot = sol.free_is_s ? sys.plane_t : sys.plane_s;
  const T other = sol.free_is_s ? sys.plane_s : sys.plane_t;
  sol.p = -sys.plane0 / pivot;
  sol.q = -other / pivot;
  T lo = T(0), hi = T(1);  // the free parameter is itself in [0, 1] (rows 3, 4 repeat it)
  for (const Row<T>& r : sys.row) {
    // m ≤ a s + b t ≤ n with the eliminated variable replaced by p + q·free
    const T c_free = sol.free_is_s ? r.a : r.b;
    const T c_elim = sol.free_is_s ? r.b : r.a;
    const T k = c_free + c_elim * sol.q;
    const T m = r.m - c_elim * sol.p, n = r.n - c_elim * sol.p;
    if (k > T(0)) {
      lo = std::max(lo, m / k), hi = std::min(hi, n / k);
    } else if (k < T(0)) {
      lo = std::max(lo, n / k), hi = std::min(hi, m / k);
    } else if (!(m <= T(0) && T(0) <= n)) {
      return sol;
    }
  }
  sol.lo = lo;
  sol.hi = hi;
  sol.feasible = lo <= hi;
  return sol;
}

template <class T>
struct PlaneResult {
  Dimension dimension;
  SegmentAnswer segment;
};

template <class T>
PlaneResult<T> with_plane(const PairT<T>& pair) {
  const System<T> sys = build_system(pair);
  if (sys.plane_s == T(0) && sys.plane_t == T(0)) {
    SegmentAnswer empty;
    empty.kind = SegmentKind::empty;
    if (sys.plane0 != T(0)) return {Dimension::none, empty};  // parallel planes
    // Coplanar: the projection is the identity and the published system is the right one.
    const Solution<T> sol = solve(sys);
    const Dimension d = classify(sol);
    return {d, segment_from(pair, sol, d)};
  }
  const LineSolution<T> sol = solve_on_line(sys);
  PlaneResult<T> out{Dimension::none, {}};
  out.segment.kind = SegmentKind::empty;
  if (!sol.feasible) return out;
  T s0, t0, s1, t1;
  sol.at(sol.lo, s0, t0);
  sol.at(sol.hi, s1, t1);
  out.segment.p = point_of(pair, s0, t0);
  out.segment.q = point_of(pair, s1, t1);
  const bool single = sol.lo == sol.hi;  // §3's s_m = s_M
  out.dimension = single ? Dimension::point : Dimension::segment;
  out.segment.kind = single ? SegmentKind::point : SegmentKind::segment;
  return out;
}

template <class T>
RelationAnswer plane_relation(const PairT<T>& pair) {
  return {Relation::unknown, with_plane(pair).dimension};
}

template <class T>
SegmentAnswer plane_segment(const PairT<T>& pair) {
  return with_plane(pair).segment;
}

}  // namespace tritri::sabharwal15
