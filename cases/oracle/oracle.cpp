#include "cases/oracle/oracle.hpp"

#include "cases/oracle/cgal_result.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <CGAL/squared_distance_3.h>
#include <CGAL/version.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <variant>

namespace tritri {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = K::Point_3;
using Segment = K::Segment_3;
using Tri = K::Triangle_3;

Point to_exact(const Vec3<double>& v) { return Point(v.x(), v.y(), v.z()); }

Vec3<double> to_double(const Point& p) {
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

struct ExactTriangle {
  std::array<Point, 3> v;
  explicit ExactTriangle(const Triangle& t) : v{to_exact(t[0]), to_exact(t[1]), to_exact(t[2])} {}
  bool degenerate() const { return CGAL::collinear(v[0], v[1], v[2]); }
  Tri triangle() const { return Tri(v[0], v[1], v[2]); }
};

// A zero-area triangle is the convex hull of its vertices: a point or a segment. CGAL's
// Triangle_3 predicates assume a proper triangle (the precondition is skipped in Release builds
// and the answers are then wrong), so degenerate input is judged through these shapes instead.
using Shape = std::variant<Point, Segment, Tri>;

Shape shape_of(const ExactTriangle& t) {
  if (!t.degenerate()) return t.triangle();
  const auto& v = t.v;
  if (v[0] == v[1] && v[1] == v[2]) return v[0];
  // Collinear: the hull is the segment between the two vertices farthest apart.
  Segment best(v[0], v[1]);
  for (auto [i, j] : {std::pair{0, 2}, std::pair{1, 2}}) {
    Segment s(v[i], v[j]);
    if (s.squared_length() > best.squared_length()) best = s;
  }
  return best;
}

bool shapes_meet(const Shape& a, const Shape& b) {
  return std::visit(
      [](const auto& x, const auto& y) -> bool {
        using X = std::decay_t<decltype(x)>;
        using Y = std::decay_t<decltype(y)>;
        if constexpr (std::is_same_v<X, Point> && std::is_same_v<Y, Point>) return x == y;
        else if constexpr (std::is_same_v<X, Point>) return y.has_on(x);
        else if constexpr (std::is_same_v<Y, Point>) return x.has_on(y);
        else return CGAL::do_intersect(x, y);
      },
      a, b);
}

// The dimension of the intersection of two shapes known to meet, at least one of them not a
// proper triangle.
Dimension degenerate_meet_dimension(const Shape& a, const Shape& b) {
  if (std::holds_alternative<Point>(a) || std::holds_alternative<Point>(b)) return Dimension::point;
  return std::visit(
      [](const auto& x, const auto& y) -> Dimension {
        using X = std::decay_t<decltype(x)>;
        using Y = std::decay_t<decltype(y)>;
        if constexpr (std::is_same_v<X, Point> || std::is_same_v<Y, Point>) {
          return Dimension::point;
        } else if constexpr (std::is_same_v<X, Tri> && std::is_same_v<Y, Tri>) {
          return Dimension::unknown;  // unreachable: one shape is degenerate
        } else {
          auto result = CGAL::intersection(x, y);
          if (!result) return Dimension::none;
          return alternative<Segment>(*result) ? Dimension::segment : Dimension::point;
        }
      },
      a, b);
}

OracleRecord label_degenerate(const ExactTriangle& t1, const ExactTriangle& t2) {
  OracleRecord r;
  r.degenerate = true;
  r.relation = Relation::degenerate;
  r.stage = Stage::degenerate;
  const Shape a = shape_of(t1), b = shape_of(t2);
  r.overlap = shapes_meet(a, b);
  r.dimension = r.overlap ? degenerate_meet_dimension(a, b) : Dimension::none;
  r.separation = r.overlap ? 0.0 : std::numeric_limits<double>::quiet_NaN();
  return r;
}

bool all_strictly(const std::array<CGAL::Orientation, 3>& o, CGAL::Orientation side) {
  return o[0] == side && o[1] == side && o[2] == side;
}

bool one_side(const std::array<CGAL::Orientation, 3>& o) {
  return all_strictly(o, CGAL::POSITIVE) || all_strictly(o, CGAL::NEGATIVE);
}

// A point of the intersection lies in the relative interior of a triangle it belongs to iff it
// lies on none of the triangle's three edge lines.
bool in_relative_interior(const ExactTriangle& t, const Point& p) {
  for (int i = 0; i < 3; ++i)
    if (CGAL::collinear(t.v[i], t.v[(i + 1) % 3], p)) return false;
  return true;
}

// sqrt of an exact positive number, to double, without the underflow (tiny separations) or
// overflow (huge coordinates) of rounding the square first: scale by powers of 4, which the
// square root turns into exact powers of 2.
// The conversion works on the exact value, not on the lazy number's interval approximation, so
// the same distance computed in another vertex order gives the same double: the nearest one.
double sqrt_to_double(const K::FT& lazy_square) {
  auto square = CGAL::exact(lazy_square);
  using Exact = decltype(square);
  int shift = 0;  // sqrt(square) = sqrt(scaled) * 2^-shift
  const Exact up = std::ldexp(1.0, 100), down = std::ldexp(1.0, -100);
  while (CGAL::to_double(square) < 1e-200) {
    square = square * up;
    shift += 50;
  }
  while (!std::isfinite(CGAL::to_double(square)) || CGAL::to_double(square) > 1e200) {
    square = square * down;
    shift -= 50;
  }
  // The double nearest the exact square root: start from the floating-point estimate and step
  // to a neighbour while the exact midpoint between them is still below (or above) the root.
  double root = std::sqrt(CGAL::to_double(square));
  auto midpoint_at_or_below_root = [&](double below, double above) {
    const Exact mid = (Exact(below) + Exact(above)) / 2;
    return mid * mid <= square;
  };
  const double inf = std::numeric_limits<double>::infinity();
  while (midpoint_at_or_below_root(root, std::nextafter(root, inf))) root = std::nextafter(root, inf);
  while (!midpoint_at_or_below_root(std::nextafter(root, 0.0), root)) root = std::nextafter(root, 0.0);
  return std::ldexp(root, -shift);
}

void store_points(OracleRecord& r, std::initializer_list<Point> points) {
  r.point_count = 0;
  for (const auto& p : points) r.points[static_cast<std::size_t>(r.point_count++)] = to_double(p);
}

}  // namespace

std::string_view to_string(Stage s) {
  switch (s) {
    case Stage::plane2: return "plane2";
    case Stage::plane1: return "plane1";
    case Stage::coplanar: return "coplanar";
    case Stage::interval: return "interval";
    case Stage::degenerate: return "degenerate";
  }
  return "?";
}

std::string oracle_description() {
  return std::string("CGAL ") + CGAL_STR(CGAL_VERSION) + ", Epeck (exact predicates and constructions)";
}

bool has_degenerate_triangle(const TrianglePair& pair) {
  return ExactTriangle(pair.t1).degenerate() || ExactTriangle(pair.t2).degenerate();
}

OracleRecord oracle_label(const TrianglePair& pair) {
  const ExactTriangle t1(pair.t1), t2(pair.t2);
  if (t1.degenerate() || t2.degenerate()) return label_degenerate(t1, t2);

  OracleRecord r;
  std::array<CGAL::Orientation, 3> side1{}, side2{};  // T1 against T2's plane; T2 against T1's
  for (int i = 0; i < 3; ++i) {
    side1[i] = CGAL::orientation(t2.v[0], t2.v[1], t2.v[2], t1.v[i]);
    side2[i] = CGAL::orientation(t1.v[0], t1.v[1], t1.v[2], t2.v[i]);
  }
  r.coplanar = all_strictly(side2, CGAL::COPLANAR);
  if (!r.coplanar) {
    const auto n1 = CGAL::normal(t1.v[0], t1.v[1], t1.v[2]);
    const auto n2 = CGAL::normal(t2.v[0], t2.v[1], t2.v[2]);
    r.parallel = CGAL::cross_product(n1, n2) == CGAL::NULL_VECTOR;
  }
  r.stage = one_side(side1) ? Stage::plane2
            : one_side(side2) ? Stage::plane1
            : r.coplanar ? Stage::coplanar
                         : Stage::interval;

  const Tri a = t1.triangle(), b = t2.triangle();
  r.overlap = CGAL::do_intersect(a, b);
  const auto meet = CGAL::intersection(a, b);
  // Two independent CGAL code paths must agree; if they ever do not, the judge is not to be
  // trusted on this pair and we say so rather than guess. This and the checks below are the
  // oracle contradicting itself, never bad input: an internal error (std::logic_error).
  if (r.overlap != static_cast<bool>(meet))
    throw std::logic_error("oracle: CGAL's do_intersect and intersection disagree");

  if (!r.overlap) {
    r.relation = r.coplanar ? Relation::coplanar_disjoint
                 : r.parallel ? Relation::parallel
                              : Relation::disjoint;
    r.dimension = Dimension::none;
    const auto squared = CGAL::squared_distance(a, b);
    if (squared == 0) throw std::logic_error("oracle: disjoint triangles at distance zero");
    r.separation = sqrt_to_double(squared);
    return r;
  }

  r.separation = 0.0;
  if (const Point* p = alternative<Point>(*meet)) {
    r.dimension = Dimension::point;
    r.relation = r.coplanar ? Relation::coplanar_point : Relation::touch_point;
    store_points(r, {*p});
  } else if (const Segment* s = alternative<Segment>(*meet)) {
    r.dimension = Dimension::segment;
    store_points(r, {s->source(), s->target()});
    if (r.coplanar) {
      r.relation = Relation::coplanar_segment;
    } else {
      const Point mid = CGAL::midpoint(s->source(), s->target());
      r.relation = in_relative_interior(t1, mid) && in_relative_interior(t2, mid)
                       ? Relation::cross
                       : Relation::touch_segment;
    }
  } else {
    if (!r.coplanar) throw std::logic_error("oracle: an area intersection of non-coplanar triangles");
    r.dimension = Dimension::area;
    r.relation = Relation::coplanar_overlap;
    if (const Tri* t = alternative<Tri>(*meet)) {
      store_points(r, {t->vertex(0), t->vertex(1), t->vertex(2)});
    } else {
      const auto* polygon = alternative<std::vector<Point>>(*meet);
      if (!polygon) throw std::logic_error("oracle: an area intersection neither a triangle nor a polygon");
      r.point_count = 0;
      for (const auto& p : *polygon)
        if (r.point_count < 6) r.points[static_cast<std::size_t>(r.point_count++)] = to_double(p);
    }
  }
  return r;
}

}  // namespace tritri
