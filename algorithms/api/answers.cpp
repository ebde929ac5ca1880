#include "tritri/answers.hpp"

#include <array>
#include <utility>

namespace tritri {
namespace {

constexpr std::array<std::pair<Relation, std::string_view>, 12> kRelationNames{{
    {Relation::disjoint, "disjoint"},
    {Relation::cross, "cross"},
    {Relation::touch_point, "touch-point"},
    {Relation::touch_segment, "touch-segment"},
    {Relation::coplanar_overlap, "coplanar-overlap"},
    {Relation::coplanar_disjoint, "coplanar-disjoint"},
    {Relation::coplanar_point, "coplanar-point"},
    {Relation::coplanar_segment, "coplanar-segment"},
    {Relation::parallel, "parallel"},
    {Relation::degenerate, "degenerate"},
    {Relation::unknown, "unknown"},
    {Relation::unsupported, "unsupported"},
}};

constexpr std::array<std::pair<Dimension, std::string_view>, 5> kDimensionNames{{
    {Dimension::none, "none"},
    {Dimension::point, "point"},
    {Dimension::segment, "segment"},
    {Dimension::area, "area"},
    {Dimension::unknown, "unknown"},
}};

constexpr std::array<std::pair<Level, std::string_view>, 3> kLevelNames{{
    {Level::overlap, "overlap"},
    {Level::relation, "relation"},
    {Level::segment, "segment"},
}};

constexpr std::array<std::pair<Overlap, std::string_view>, 3> kOverlapNames{{
    {Overlap::no, "0"},
    {Overlap::yes, "1"},
    {Overlap::unsupported, "unsupported"},
}};

constexpr std::array<std::pair<SegmentKind, std::string_view>, 6> kSegmentKindNames{{
    {SegmentKind::empty, "empty"},
    {SegmentKind::point, "point"},
    {SegmentKind::segment, "segment"},
    {SegmentKind::area, "area"},
    {SegmentKind::coplanar, "coplanar"},
    {SegmentKind::unsupported, "unsupported"},
}};

template <class E, std::size_t N>
std::string_view name_of(const std::array<std::pair<E, std::string_view>, N>& table, E value) {
  for (const auto& [e, name] : table)
    if (e == value) return name;
  return "?";
}

template <class E, std::size_t N>
std::optional<E> value_of(const std::array<std::pair<E, std::string_view>, N>& table,
                          std::string_view name) {
  for (const auto& [e, n] : table)
    if (n == name) return e;
  return std::nullopt;
}

}  // namespace

std::string_view to_string(Level l) { return name_of(kLevelNames, l); }
std::string_view to_string(Relation r) { return name_of(kRelationNames, r); }
std::string_view to_string(Dimension d) { return name_of(kDimensionNames, d); }

std::string_view to_string(Overlap o) { return name_of(kOverlapNames, o); }
std::string_view to_string(SegmentKind k) { return name_of(kSegmentKindNames, k); }

std::optional<Level> parse_level(std::string_view s) { return value_of(kLevelNames, s); }
std::optional<Relation> parse_relation(std::string_view s) { return value_of(kRelationNames, s); }
std::optional<Dimension> parse_dimension(std::string_view s) {
  return value_of(kDimensionNames, s);
}

}  // namespace tritri
