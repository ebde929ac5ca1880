// The three answer levels and their vocabulary, shared by algorithms, the oracle, files and reports.
#pragma once

#include "tritri/geometry.hpp"

#include <cstdint>
#include <optional>
#include <string_view>

namespace tritri {

enum class Level : std::uint8_t { overlap, relation, segment };

// Level overlap: do the two triangles share at least one point?
enum class Overlap : std::uint8_t { no = 0, yes = 1, unsupported = 2 };

// Level relation: Yu–He's nine return codes (their numeric values are the paper's), plus three
// values that are not relations of two proper triangles.
enum class Relation : std::int8_t {
  disjoint = 0,
  cross = 1,          // planes cross; the intersection is a segment meeting both relative interiors
  touch_point = 2,    // planes cross; they meet in one point
  touch_segment = 3,  // planes cross; a segment, but inside the boundary of at least one triangle
  coplanar_overlap = -1,
  coplanar_disjoint = -2,
  coplanar_point = -3,
  coplanar_segment = -4,
  parallel = -5,      // distinct parallel planes
  degenerate = -6,    // the oracle's label when a triangle has zero area
  unknown = -7,       // an algorithm that states only the dimension of the intersection
  unsupported = -8,   // an algorithm that declined the case
};

enum class Dimension : std::int8_t { none = 0, point = 1, segment = 2, area = 3, unknown = -1 };

struct RelationAnswer {
  Relation relation = Relation::unsupported;
  Dimension dimension = Dimension::unknown;
};

// Level segment: the intersection itself where it is at most one-dimensional.
//   area: the triangles are coplanar and overlap in a region (no segment to give).
//   coplanar: the algorithm found coplanar contact but computes no intersection for it.
enum class SegmentKind : std::uint8_t { empty, point, segment, area, coplanar, unsupported };

struct SegmentAnswer {
  SegmentKind kind = SegmentKind::unsupported;
  Vec3<double> p = Vec3<double>::Zero();  // point, or first endpoint
  Vec3<double> q = Vec3<double>::Zero();  // second endpoint (equal to p for a point)
};

constexpr Dimension dimension_of(Relation r) {
  switch (r) {
    case Relation::disjoint:
    case Relation::coplanar_disjoint:
    case Relation::parallel: return Dimension::none;
    case Relation::touch_point:
    case Relation::coplanar_point: return Dimension::point;
    case Relation::cross:
    case Relation::touch_segment:
    case Relation::coplanar_segment: return Dimension::segment;
    case Relation::coplanar_overlap: return Dimension::area;
    default: return Dimension::unknown;
  }
}

constexpr bool is_coplanar_relation(Relation r) {
  return r == Relation::coplanar_overlap || r == Relation::coplanar_disjoint ||
         r == Relation::coplanar_point || r == Relation::coplanar_segment;
}

constexpr RelationAnswer answer_with(Relation r) { return {r, dimension_of(r)}; }

std::string_view to_string(Level);
std::string_view to_string(Overlap);
std::string_view to_string(Relation);
std::string_view to_string(Dimension);
std::string_view to_string(SegmentKind);

std::optional<Level> parse_level(std::string_view);
std::optional<Relation> parse_relation(std::string_view);
std::optional<Dimension> parse_dimension(std::string_view);

inline constexpr Relation kAllRelations[] = {
    Relation::disjoint,          Relation::cross,           Relation::touch_point,
    Relation::touch_segment,     Relation::coplanar_overlap, Relation::coplanar_disjoint,
    Relation::coplanar_point,    Relation::coplanar_segment, Relation::parallel};

}  // namespace tritri
