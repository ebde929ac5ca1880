#include "harness/bench/workloads/type.hpp"

#include "cases/generator/shapes.hpp"
#include "harness/bench/workload.hpp"

#include <stdexcept>

namespace tritri::bench {
namespace {

using namespace shapes;

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

Dimension parse_type(const std::string& value) {
  for (Dimension d : kTypes)
    if (type_text(d) == value) return d;
  throw std::invalid_argument("type '" + value + "' is not one of disjoint, point, segment, area");
}

class TypeWorkload : public Workload {
 public:
  TypeWorkload() : Workload("type", "type[:T]") {}
  std::vector<std::string> default_values() const override { return texts_of(kTypes, type_text); }
  std::string parse_value(const std::string& value) const override { return type_text(parse_type(value)); }
  WorkloadPools build(const std::vector<std::string>& values, const WorkloadInput& input) const override {
    WorkloadPools built;
    for (const auto& v : values) built.pools.push_back(type_pool(parse_type(v), input.pool));
    return built;
  }
};

}  // namespace

std::unique_ptr<Workload> make_type_workload() { return std::make_unique<TypeWorkload>(); }

std::string type_text(Dimension d) {
  switch (d) {
    case Dimension::none: return "disjoint";
    case Dimension::point: return "point";
    case Dimension::segment: return "segment";
    case Dimension::area: return "area";
    default: return "unknown";
  }
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
    for (auto& c : draw(std::max<std::size_t>(1024, missing * 2), rng, make, seen, "type:" + value + " pool"))
      if (c.truth.dimension == type && kept.size() < options.size) kept.push_back(c);
  }
  return make_pool("type", value, seed, std::move(kept));
}

}  // namespace tritri::bench
