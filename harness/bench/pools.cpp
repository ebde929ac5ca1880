#include "harness/bench/pools.hpp"

#include "cases/util/random.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <functional>
#include <mutex>
#include <random>
#include <stdexcept>
#include <thread>
#include <unordered_set>

namespace tritri::bench {
namespace {

// The seed of one named workload, derived from the run's seed.
std::uint64_t sub_seed(std::uint64_t seed, const std::string& tag) { return splitmix(seed ^ fnv1a(tag)); }

using V = Vec3<double>;

V random_in_cube(Rng& r, double half) {
  return {r.uniform(-half, half), r.uniform(-half, half), r.uniform(-half, half)};
}

V integer_vector(Rng& r, std::int64_t m) {
  return V(static_cast<double>(r.integer(-m, m)), static_cast<double>(r.integer(-m, m)),
           static_cast<double>(r.integer(-m, m)));
}

// Sizes spread over two orders of magnitude, so small triangles are rejected by the first plane
// test, long thin ones reach the interval stage, and both kinds meet.
double mixed_size(Rng& r) { return std::exp2(r.uniform(-6.0, 0.0)); }

Triangle triangle_around(Rng& r, const V& center, double size) {
  return {{center + size * random_in_cube(r, 1), center + size * random_in_cube(r, 1),
           center + size * random_in_cube(r, 1)}};
}

// Random order of the vertices and of the triangles, so no algorithm always sees the contact on
// the same vertex or the same triangle.
TrianglePair scramble(TrianglePair p, Rng& r) {
  for (Triangle* t : {&p.t1, &p.t2}) {
    const auto k = r.integer(0, 2);
    std::rotate(t->v.begin(), t->v.begin() + k, t->v.end());
    if (r.coin()) std::swap(t->v[1], t->v[2]);
  }
  if (r.coin()) std::swap(p.t1, p.t2);
  return p;
}

// ---- candidate kinds ----

// Two triangles anywhere in the unit cube: mostly rejected by a plane test.
TrianglePair scatter_pair(Rng& r) {
  const V c1(r.unit(), r.unit(), r.unit()), c2(r.unit(), r.unit(), r.unit());
  return {triangle_around(r, c1, mixed_size(r)), triangle_around(r, c2, mixed_size(r))};
}

// T2 centred on a point of T1: they meet about half the time, and the disjoint ones mostly
// reach the interval stage.
TrianglePair near_pair(Rng& r) {
  const V c(r.unit(), r.unit(), r.unit());
  const Triangle t1 = triangle_around(r, c, mixed_size(r));
  double a = r.unit(), b = r.unit();
  if (a + b > 1) a = 1 - a, b = 1 - b;
  const V at = t1[0] + a * (t1[1] - t1[0]) + b * (t1[2] - t1[0]);
  const double s = mixed_size(r);
  V d[3] = {random_in_cube(r, s), random_in_cube(r, s), random_in_cube(r, s)};
  const V mean = (d[0] + d[1] + d[2]) / 3.0;
  return {t1, {{at + d[0] - mean, at + d[1] - mean, at + d[2] - mean}}};
}

// Exactly coplanar: integer points o + a·e1 + b·e2 of one plane, scaled by a power of two and
// translated by an integer vector first, so every coordinate is exact.
struct IntegerPlane {
  V origin, e1, e2;
  V at(std::int64_t a, std::int64_t b) const {
    return origin + static_cast<double>(a) * e1 + static_cast<double>(b) * e2;
  }
};

IntegerPlane integer_plane(Rng& r) {
  IntegerPlane p;
  do {
    p.e1 = integer_vector(r, 4);
    p.e2 = integer_vector(r, 4);
  } while (p.e1.cross(p.e2).isZero());
  p.origin = integer_vector(r, 64);
  return p;
}

double power_of_two_scale(Rng& r) { return std::ldexp(1.0, static_cast<int>(r.integer(-7, -3))); }

TrianglePair scaled(TrianglePair p, double scale) {
  for (Triangle* t : {&p.t1, &p.t2})
    for (auto& v : t->v) v *= scale;
  return p;
}

Triangle plane_triangle(Rng& r, const IntegerPlane& plane, std::int64_t ca, std::int64_t cb) {
  const std::int64_t w = r.integer(1, 12);
  Triangle t;
  for (auto& v : t.v) v = plane.at(ca + r.integer(-w, w), cb + r.integer(-w, w));
  return t;
}

TrianglePair coplanar_pair(Rng& r) {
  const IntegerPlane plane = integer_plane(r);
  const auto da = r.integer(-10, 10), db = r.integer(-10, 10);
  return scaled({plane_triangle(r, plane, 0, 0), plane_triangle(r, plane, da, db)},
                power_of_two_scale(r));
}

// An integer triangle with a non-zero integer normal (exact: the products stay below 2^53).
struct IntegerTriangle {
  Triangle t;
  V normal;
};

IntegerTriangle integer_triangle(Rng& r) {
  IntegerTriangle it;
  do {
    const V o = integer_vector(r, 64);
    const std::int64_t m = r.integer(2, 32);
    it.t = {{o + integer_vector(r, m), o + integer_vector(r, m), o + integer_vector(r, m)}};
    it.normal = (it.t[1] - it.t[0]).cross(it.t[2] - it.t[0]);
  } while (it.normal.isZero());
  return it;
}

// An integer vector strictly on the positive side of `normal`.
V above(Rng& r, const V& normal, std::int64_t m) {
  for (;;) {
    const V u = integer_vector(r, m);
    if (normal.dot(u) > 0) return u;
  }
}

// Point contacts, each exact by construction (the oracle still has the last word).
TrianglePair point_contact(Rng& r) {
  const IntegerTriangle a = integer_triangle(r);
  const Triangle& t = a.t;
  const std::int64_t m = r.integer(2, 32);
  const double sign = r.coin() ? 1.0 : -1.0;
  TrianglePair p;
  switch (r.integer(0, 3)) {
    case 0: {  // a vertex of T2 inside T1's face, the rest of T2 on one side
      std::int64_t w0 = r.integer(1, 14), w1 = r.integer(1, 15 - w0), w2 = 16 - w0 - w1;
      const V at = (static_cast<double>(w0) * t[0] + static_cast<double>(w1) * t[1] +
                    static_cast<double>(w2) * t[2]) / 16.0;
      p = {t, {{at, at + above(r, sign * a.normal, m), at + above(r, sign * a.normal, m)}}};
      break;
    }
    case 1:  // a shared vertex, T2 on one side
      p = {t, {{t[0], t[0] + above(r, sign * a.normal, m), t[0] + above(r, sign * a.normal, m)}}};
      break;
    case 2: {  // an edge of T2 through the midpoint of an edge of T1, leaving T1 at once
      const V mid = (t[0] + t[1]) / 2.0;
      const V u = above(r, a.normal, m);
      p = {t, {{mid + u, mid - u, t[0] + t[1] - t[2]}}};
      break;
    }
    default: {  // coplanar, sharing a vertex
      const IntegerPlane plane = integer_plane(r);
      p = {plane_triangle(r, plane, 0, 0), {}};
      p.t2 = {{p.t1[0], plane.at(r.integer(-12, 12), r.integer(-12, 12)),
               plane.at(r.integer(-12, 12), r.integer(-12, 12))}};
      break;
    }
  }
  return scaled(p, power_of_two_scale(r));
}

// Segment contacts: crossing pairs and pairs sharing an edge.
TrianglePair segment_contact(Rng& r) {
  if (r.integer(0, 3) != 0) return near_pair(r);  // mostly `cross`
  const IntegerTriangle a = integer_triangle(r);
  const Triangle& t = a.t;
  TrianglePair p;
  if (r.coin()) {  // a shared edge, T2 leaving T1's plane
    p = {t, {{t[0], t[1], t[0] + above(r, (r.coin() ? 1.0 : -1.0) * a.normal, r.integer(2, 32))}}};
  } else {  // coplanar, sharing an edge, T2 on the far side of it
    p = {t, {{t[0], t[1], t[0] + t[1] - t[2]}}};
  }
  return scaled(p, power_of_two_scale(r));
}

// ---- labelling and collecting ----

std::uint64_t pair_hash(const TrianglePair& p) {
  std::uint64_t h = kFnvOffset;
  for (const Triangle* t : {&p.t1, &p.t2})
    for (const auto& v : t->v) h = fnv1a(v.data(), 3 * sizeof(double), h);
  return h;
}

struct Candidate {
  TrianglePair pair;
  Truth truth;
};

// Draws `count` candidates with `make`, labels them, and returns the non-degenerate ones not
// seen before (in generation order, so the result depends on the seed only).
std::vector<Candidate> draw(std::size_t count, Rng& rng, const std::function<TrianglePair(Rng&)>& make,
                            std::unordered_set<std::uint64_t>& seen) {
  std::vector<TrianglePair> pairs(count);
  for (auto& p : pairs) p = scramble(make(rng), rng);
  const auto truth = label_pairs(pairs);
  std::vector<Candidate> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    if (truth[i].relation == Relation::degenerate) continue;
    if (!seen.insert(pair_hash(pairs[i])).second) continue;
    out.push_back({pairs[i], truth[i]});
  }
  return out;
}

Pool make_pool(std::string workload, std::string value, std::uint64_t seed, std::vector<Candidate> c) {
  Rng rng(seed);
  rng.shuffle(c);
  Pool p{std::move(workload), std::move(value), seed, {}, {}};
  p.pairs.reserve(c.size());
  p.truth.reserve(c.size());
  for (const auto& x : c) {
    p.pairs.push_back(x.pair);
    p.truth.push_back(x.truth);
  }
  return p;
}

// The ratio workloads' candidate kinds and their shares.
TrianglePair ratio_candidate(Rng& r, bool disjoint_full) {
  const double u = r.unit();
  if (!disjoint_full) {
    if (u < 0.55) return scatter_pair(r);
    if (u < 0.95) return near_pair(r);
    return coplanar_pair(r);
  }
  // Once enough disjoint pairs are in hand, draw only the kinds that often meet, in the same
  // proportions to each other as before.
  return u < 0.40 / 0.45 ? near_pair(r) : coplanar_pair(r);
}

}  // namespace

std::size_t Pool::intersecting() const {
  return static_cast<std::size_t>(std::count_if(truth.begin(), truth.end(), [](const Truth& t) { return t.overlap; }));
}

std::array<std::size_t, 5> Pool::stage_mix() const {
  std::array<std::size_t, 5> mix{};
  for (const auto& t : truth) ++mix[static_cast<std::size_t>(t.stage)];
  return mix;
}

std::string Pool::stage_mix_text() const {
  const auto mix = stage_mix();
  std::string out;
  for (Stage s : {Stage::plane2, Stage::plane1, Stage::coplanar, Stage::interval, Stage::degenerate}) {
    if (s == Stage::degenerate && mix[static_cast<std::size_t>(s)] == 0) continue;
    if (!out.empty()) out += ' ';
    out += std::string(to_string(s)) + "=" + std::to_string(mix[static_cast<std::size_t>(s)]);
  }
  return out;
}

std::vector<double> default_ratios() {
  std::vector<double> r;
  for (int i = 0; i <= 10; ++i) r.push_back(i / 10.0);
  return r;
}

std::string ratio_text(double r) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", r);
  return buf;
}

std::string type_text(Dimension d) {
  switch (d) {
    case Dimension::none: return "disjoint";
    case Dimension::point: return "point";
    case Dimension::segment: return "segment";
    case Dimension::area: return "area";
    default: return "unknown";
  }
}

std::vector<Pool> ratio_pools(const std::vector<double>& ratios, const PoolOptions& options) {
  const std::size_t n = options.size;
  std::size_t need_yes = 0, need_no = 0;
  for (double r : ratios) {
    if (!(r >= 0.0 && r <= 1.0)) throw std::invalid_argument("ratio " + std::to_string(r) + " is not in [0, 1]");
    const auto k = static_cast<std::size_t>(std::llround(r * static_cast<double>(n)));
    need_yes = std::max(need_yes, k);
    need_no = std::max(need_no, n - k);
  }
  // One candidate set for every ratio: the classes' mixtures are the same in every pool.
  Rng rng(sub_seed(options.seed, "ratio"));
  std::unordered_set<std::uint64_t> seen;
  std::vector<Candidate> yes, no;
  for (int round = 0; yes.size() < need_yes || no.size() < need_no; ++round) {
    if (round > 200) throw std::runtime_error("ratio pools: the generator yields too few pairs");
    const bool disjoint_full = no.size() >= need_no;
    const std::size_t missing = std::max(need_yes - std::min(need_yes, yes.size()),
                                         need_no - std::min(need_no, no.size()));
    const std::size_t count = std::max<std::size_t>(2048, disjoint_full ? 2 * missing : missing + missing / 4);
    for (auto& c : draw(count, rng, [&](Rng& r) { return ratio_candidate(r, disjoint_full); }, seen)) {
      auto& cls = c.truth.overlap ? yes : no;
      if (cls.size() < (c.truth.overlap ? need_yes : need_no)) cls.push_back(c);
    }
  }
  std::vector<Pool> pools;
  for (double r : ratios) {
    const auto k = static_cast<std::size_t>(std::llround(r * static_cast<double>(n)));
    std::vector<Candidate> chosen(yes.begin(), yes.begin() + static_cast<std::ptrdiff_t>(k));
    chosen.insert(chosen.end(), no.begin(), no.begin() + static_cast<std::ptrdiff_t>(n - k));
    const std::string value = ratio_text(r);
    pools.push_back(make_pool("ratio", value, sub_seed(options.seed, "ratio:" + value), std::move(chosen)));
  }
  return pools;
}

Pool type_pool(Dimension type, const PoolOptions& options) {
  const std::string value = type_text(type);
  const std::uint64_t seed = sub_seed(options.seed, "type:" + value);
  Rng rng(seed);
  std::function<TrianglePair(Rng&)> make;
  switch (type) {
    case Dimension::none:
      make = [](Rng& r) { return r.unit() < 0.55 ? scatter_pair(r) : r.unit() < 0.9 ? near_pair(r) : coplanar_pair(r); };
      break;
    case Dimension::point: make = point_contact; break;
    case Dimension::segment: make = segment_contact; break;
    case Dimension::area: make = coplanar_pair; break;
    default: throw std::invalid_argument("no pool for intersection type " + value);
  }
  std::unordered_set<std::uint64_t> seen;
  std::vector<Candidate> kept;
  for (int round = 0; kept.size() < options.size; ++round) {
    if (round > 200) throw std::runtime_error("type:" + value + ": the generator yields too few pairs");
    const std::size_t missing = options.size - kept.size();
    for (auto& c : draw(std::max<std::size_t>(1024, missing * 2), rng, make, seen))
      if (c.truth.dimension == type && kept.size() < options.size) kept.push_back(c);
  }
  return make_pool("type", value, seed, std::move(kept));
}

std::vector<Pool> family_pools(const std::vector<Case>& cases, const PoolOptions& options) {
  std::vector<std::string> order;
  std::vector<std::vector<TrianglePair>> members;
  std::vector<std::unordered_set<std::uint64_t>> seen;
  for (const auto& c : cases) {
    const std::string f = c.family();
    auto it = std::find(order.begin(), order.end(), f);
    if (it == order.end()) {
      order.push_back(f);
      members.emplace_back();
      seen.emplace_back();
      it = order.end() - 1;
    }
    const auto k = static_cast<std::size_t>(it - order.begin());
    if (seen[k].insert(pair_hash(c.pair)).second) members[k].push_back(c.pair);
  }
  std::vector<Pool> pools;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const auto truth = label_pairs(members[k]);
    std::vector<Candidate> kept;
    for (std::size_t i = 0; i < truth.size(); ++i)
      if (truth[i].relation != Relation::degenerate) kept.push_back({members[k][i], truth[i]});
    // A family larger than the pool size is sampled down to it, with the seed.
    const std::uint64_t seed = sub_seed(options.seed, "family:" + order[k]);
    Pool p = make_pool("family", order[k], seed, std::move(kept));
    if (p.size() > options.size) {
      p.pairs.resize(options.size);
      p.truth.resize(options.size);
    }
    if (!p.pairs.empty()) pools.push_back(std::move(p));
  }
  return pools;
}

std::uint64_t hash_pools(const std::vector<const Pool*>& pools) {
  std::uint64_t h = kFnvOffset;
  for (const Pool* p : pools) {
    const std::string name = p->name();
    h = fnv1a(name, h);
    for (const auto& pair : p->pairs)
      for (const Triangle* t : {&pair.t1, &pair.t2})
        for (const auto& v : t->v) h = fnv1a(v.data(), 3 * sizeof(double), h);
  }
  return h;
}

std::string hex64(std::uint64_t x) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(x));
  return buf;
}

}  // namespace tritri::bench
