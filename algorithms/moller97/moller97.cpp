#include "algorithms/moller97/moller97.hpp"

#include "tritri/algorithm.hpp"
#include "tritri/counting.hpp"

namespace tritri {
namespace {

constexpr const char* kCitation =
    "Tomas Möller. A Fast Triangle-Triangle Intersection Test. journal of graphics tools "
    "2(2):25-30, 1997. doi:10.1080/10867651.1997.10487472";

Tolerance published_snap() {
  return {moller97::kEpsilon, "|N·V + d|, unnormalised plane distance, snapped to 0 below it", false};
}

Algorithm moller_entry(std::string name, std::string summary, bool snap) {
  return Algorithm({.name = std::move(name), .citation = kCitation, .summary = std::move(summary),
                    .tolerance = snap ? published_snap() : Tolerance{}});
}

}  // namespace

void register_moller97(Registry& registry) {
  using moller97::overlap;
  using moller97::overlap_division_free;
  using moller97::segment;

  Algorithm published =
      moller_entry("moller97", "the published test: interval overlap with divisions, EPSILON snap", true);
  add_level<Level::overlap>(published, []<class T>(const PairT<T>& p) { return overlap<T, true>(p); });
  registry.add(std::move(published));

  Algorithm exact_zero = moller_entry(
      "moller97-nosnap", "the published test without the EPSILON snap (exact-zero comparisons)", false);
  add_level<Level::overlap>(exact_zero, []<class T>(const PairT<T>& p) { return overlap<T, false>(p); });
  registry.add(std::move(exact_zero));

  Algorithm division_free = moller_entry(
      "moller97-nodiv", "the author's division-free interval test (later code), EPSILON snap", true);
  add_level<Level::overlap>(division_free, []<class T>(const PairT<T>& p) { return overlap_division_free<T, true>(p); });
  registry.add(std::move(division_free));

  Algorithm with_segment = moller_entry(
      "moller97-segment",
      "the author's variant returning the intersection segment and a coplanar flag, EPSILON snap", true);
  add_level<Level::overlap>(with_segment, []<class T>(const PairT<T>& p) { return moller97::overlap_with_segment<T, true>(p); });
  add_level<Level::segment>(with_segment, []<class T>(const PairT<T>& p) { return segment<T, true>(p); });
  registry.add(std::move(with_segment));
}

}  // namespace tritri
