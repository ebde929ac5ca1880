// The exact judge. Every label in tritri comes from here: CGAL's exact predicates and exact
// constructions (Epeck) on the double coordinates as given, with no rounding before the answer.
//
// This header includes no CGAL: CGAL is linked privately into the oracle library only, so the
// algorithms, their tests and the benchmarks never compile with CGAL's -frounding-math.
#pragma once

#include "tritri/answers.hpp"

#include <array>
#include <string>
#include <string_view>

namespace tritri {

// The stage at which an ideal plane-rejecting test (Möller's order) decides the pair.
enum class Stage : std::uint8_t {
  plane2,      // T1 strictly on one side of T2's plane
  plane1,      // T2 strictly on one side of T1's plane
  coplanar,    // all six vertices in one plane
  interval,    // the planes cross and both triangles meet their common line
  degenerate,  // a triangle has zero area: the plane tests are undefined
};

std::string_view to_string(Stage);

struct OracleRecord {
  bool degenerate = false;  // T1 or T2 has zero area (collinear or repeated vertices)
  bool overlap = false;     // the closed triangles share a point
  Relation relation = Relation::disjoint;  // Relation::degenerate when `degenerate`
  Dimension dimension = Dimension::none;
  bool coplanar = false;  // all of T2's vertices lie in T1's plane (false when degenerate)
  bool parallel = false;  // distinct parallel planes
  // Euclidean distance between the closed triangles: the square root of CGAL's exact squared
  // distance, within an ulp or two, and never 0 for triangles that do not meet (however close);
  // 0 when they overlap. NaN when it is not computed (a degenerate pair that does not meet: CGAL
  // 5.5 has no exact segment–triangle distance).
  double separation = 0.0;
  Stage stage = Stage::interval;
  // The exact intersection, each coordinate rounded to the nearest double: 0 points when empty,
  // 1 for a point, 2 for a segment, 3 to 6 for a coplanar polygon (in order around it).
  int point_count = 0;
  std::array<Vec3<double>, 6> points{};
};

OracleRecord oracle_label(const TrianglePair& pair);

// Exactly: does either triangle have zero area? (Cheap: two filtered orientation predicates.)
bool has_degenerate_triangle(const TrianglePair& pair);

// "CGAL 5.5.1, Epeck": what judged, for provenance.
std::string oracle_description();

}  // namespace tritri
