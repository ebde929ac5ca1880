// exact triangle answers. See oracle.hpp.
#include "cases/scenes/oracle.hpp"

#include "cases/oracle/cgal_result.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>

namespace tritri::scenes {

namespace {
using EK = CGAL::Exact_predicates_exact_constructions_kernel;
EK::Point_3 P(const Vec3& v) { return EK::Point_3(v.x(), v.y(), v.z()); }

// CGAL's Triangle_3 / Triangle_3 do_intersect requires non-degenerate triangles; the broad phase
// may see degenerate ones only if a mesh carries them, so handle them by their hull.
bool degenerate(const EK::Point_3& a, const EK::Point_3& b, const EK::Point_3& c) {
  return CGAL::collinear(a, b, c);
}
// A degenerate triangle as a segment (its two farthest corners) or a point.
template <class Obj>
bool meets_degenerate(const EK::Point_3& a, const EK::Point_3& b, const EK::Point_3& c, const Obj& other) {
  if (a == b && b == c) return CGAL::do_intersect(other, a);
  // The longest of the three segments covers the collinear set.
  EK::Segment_3 s1(a, b), s2(b, c), s3(a, c);
  auto l1 = s1.squared_length(), l2 = s2.squared_length(), l3 = s3.squared_length();
  const EK::Segment_3& s = (l1 >= l2 && l1 >= l3) ? s1 : (l2 >= l3 ? s2 : s3);
  return CGAL::do_intersect(other, s);
}
}  // namespace

bool exact_intersect(const Vec3& p1, const Vec3& p2, const Vec3& p3,
                     const Vec3& q1, const Vec3& q2, const Vec3& q3) {
  const EK::Point_3 a = P(p1), b = P(p2), c = P(p3), d = P(q1), e = P(q2), f = P(q3);
  const bool dt = degenerate(a, b, c), ds = degenerate(d, e, f);
  if (!dt && !ds) return CGAL::do_intersect(EK::Triangle_3(a, b, c), EK::Triangle_3(d, e, f));
  if (!dt) return meets_degenerate(d, e, f, EK::Triangle_3(a, b, c));
  if (!ds) return meets_degenerate(a, b, c, EK::Triangle_3(d, e, f));
  // both degenerate: segment/point against segment/point
  EK::Segment_3 s1(a, b), s2(b, c), s3(a, c);
  for (const auto& s : {s1, s2, s3})
    if (!s.is_degenerate() ? meets_degenerate(d, e, f, s) : meets_degenerate(d, e, f, s.source()))
      return true;
  return false;
}

std::string contact_kind(const Vec3& p1, const Vec3& p2, const Vec3& p3,
                         const Vec3& q1, const Vec3& q2, const Vec3& q3) {
  const EK::Point_3 a = P(p1), b = P(p2), c = P(p3), d = P(q1), e = P(q2), f = P(q3);
  if (CGAL::collinear(a, b, c) || CGAL::collinear(d, e, f)) return "degenerate";
  const bool coplanar = CGAL::coplanar(a, b, c, d) && CGAL::coplanar(a, b, c, e) && CGAL::coplanar(a, b, c, f);
  const auto x = CGAL::intersection(EK::Triangle_3(a, b, c), EK::Triangle_3(d, e, f));
  std::string kind = "none";
  if (x) {
    if (alternative<EK::Point_3>(*x)) kind = "point";
    else if (alternative<EK::Segment_3>(*x)) kind = "segment";
    else kind = "area";
  }
  return (coplanar ? "coplanar " : "") + kind;
}

int shared_vertices(const Face& f, const Face& g) {
  int n = 0;
  for (auto i : f)
    for (auto j : g) n += (i == j);
  return n;
}

bool self_pair_intersects(const std::vector<Vec3>& v, const Face& f, const Face& g) {
  const int shared = shared_vertices(f, g);
  if (shared == 0) return exact_intersect(v[f[0]], v[f[1]], v[f[2]], v[g[0]], v[g[1]], v[g[2]]);
  if (shared >= 3) return true;  // same face twice (duplicate face): they coincide
  if (shared == 2) {
    // f = (u, w, a) with uw shared; b = g's corner not on f.
    std::uint32_t a = 0, b = 0;
    for (auto i : f) if (i != g[0] && i != g[1] && i != g[2]) a = i;
    for (auto j : g) if (j != f[0] && j != f[1] && j != f[2]) b = j;
    std::uint32_t u = 0, w = 0;
    int k = 0;
    for (auto i : f) if (i != a) (k++ == 0 ? u : w) = i;
    const EK::Point_3 pu = P(v[u]), pw = P(v[w]), pa = P(v[a]), pb = P(v[b]);
    return CGAL::coplanar(pu, pw, pa, pb) && CGAL::coplanar_orientation(pu, pw, pa, pb) == CGAL::POSITIVE;
  }
  // one shared vertex s: the edge of each face opposite s against the other face
  std::uint32_t s = 0;
  for (auto i : f) for (auto j : g) if (i == j) s = i;
  auto opposite = [&](const Face& h) {
    std::array<std::uint32_t, 2> e{};
    int k = 0;
    for (auto i : h) if (i != s) e[k++] = i;
    return e;
  };
  const auto ef = opposite(f), eg = opposite(g);
  const EK::Triangle_3 tf(P(v[f[0]]), P(v[f[1]]), P(v[f[2]])), tg(P(v[g[0]]), P(v[g[1]]), P(v[g[2]]));
  if (tf.is_degenerate() || tg.is_degenerate()) return true;  // conservative; meshes here have none
  return CGAL::do_intersect(tf, EK::Segment_3(P(v[eg[0]]), P(v[eg[1]]))) ||
         CGAL::do_intersect(tg, EK::Segment_3(P(v[ef[0]]), P(v[ef[1]])));
}

bool boxes_overlap(const Vec3& p1, const Vec3& p2, const Vec3& p3,
                   const Vec3& q1, const Vec3& q2, const Vec3& q3) {
  for (int i = 0; i < 3; ++i) {
    const double lo1 = std::min({p1[i], p2[i], p3[i]}), hi1 = std::max({p1[i], p2[i], p3[i]});
    const double lo2 = std::min({q1[i], q2[i], q3[i]}), hi2 = std::max({q1[i], q2[i], q3[i]});
    if (hi1 < lo2 || hi2 < lo1) return false;
  }
  return true;
}

namespace {
struct Box3 { Vec3 lo, hi; };
std::vector<Box3> boxes_of(const std::vector<Vec3>& v, const std::vector<Face>& f) {
  std::vector<Box3> out;
  out.reserve(f.size());
  for (const Face& t : f) {
    const Vec3 &a = v[t[0]], &b = v[t[1]], &c = v[t[2]];
    out.push_back({a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)});
  }
  return out;
}
bool yz_overlap(const Box3& a, const Box3& b) {
  return !(a.hi.y() < b.lo.y() || b.hi.y() < a.lo.y() || a.hi.z() < b.lo.z() || b.hi.z() < a.lo.z());
}
}  // namespace

std::vector<std::pair<std::uint32_t, std::uint32_t>> overlapping_box_pairs(
    const std::vector<Vec3>& va, const std::vector<Face>& fa,
    const std::vector<Vec3>& vb, const std::vector<Face>& fb, bool self) {
  const auto A = boxes_of(va, fa);
  const auto B = self ? A : boxes_of(vb, fb);
  auto order = [](const std::vector<Box3>& X) {
    std::vector<std::uint32_t> idx(X.size());
    for (std::uint32_t i = 0; i < idx.size(); ++i) idx[i] = i;
    std::sort(idx.begin(), idx.end(), [&](auto p, auto q) { return X[p].lo.x() < X[q].lo.x(); });
    return idx;
  };
  const auto oa = order(A), ob = self ? oa : order(B);
  std::vector<double> sb(ob.size()), sa(oa.size());
  for (std::size_t k = 0; k < ob.size(); ++k) sb[k] = B[ob[k]].lo.x();
  for (std::size_t k = 0; k < oa.size(); ++k) sa[k] = A[oa[k]].lo.x();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  auto emit = [&](std::uint32_t i, std::uint32_t j) {
    if (self) { if (i == j) return; if (i > j) std::swap(i, j); }
    out.emplace_back(i, j);
  };
  // Each pair overlapping in x has lo_b in [lo_a, hi_a] or lo_a in (lo_b, hi_b]: exactly one.
  for (std::uint32_t i = 0; i < A.size(); ++i) {
    auto k = std::lower_bound(sb.begin(), sb.end(), A[i].lo.x()) - sb.begin();
    for (; k < std::ptrdiff_t(sb.size()) && sb[k] <= A[i].hi.x(); ++k)
      if (yz_overlap(A[i], B[ob[k]])) emit(i, ob[k]);
  }
  for (std::uint32_t j = 0; j < B.size(); ++j) {
    auto k = std::upper_bound(sa.begin(), sa.end(), B[j].lo.x()) - sa.begin();
    for (; k < std::ptrdiff_t(sa.size()) && sa[k] <= B[j].hi.x(); ++k)
      if (yz_overlap(A[oa[k]], B[j])) emit(oa[k], j);
  }
  std::sort(out.begin(), out.end());
  if (self) out.erase(std::unique(out.begin(), out.end()), out.end());  // each unordered pair was seen twice
  return out;
}

}  // namespace tritri::scenes
