#include "algorithms/moller97/moller97.hpp"

#include "tritri/add_level.hpp"

namespace tritri {
namespace moller97::lanes_kernel {
void register_lanes(Registry& registry, Algorithm variant);  // lanes.cpp
}

namespace {


Tolerance published_snap() {
  return {moller97::kEpsilon, "|N·V + d|, unnormalised plane distance, snapped to 0 below it", false};
}


}  // namespace

void register_moller97(Registry& registry) {
  const Declaration paper{.citation = "Tomas Möller. A Fast Triangle-Triangle Intersection Test. journal of graphics tools "
                                      "2(2):25-30, 1997. doi:10.1080/10867651.1997.10487472"};
  auto variant_with = [&](std::string name, std::string summary, bool snap) {
    Algorithm a = variant(paper, std::move(name), std::move(summary));
    if (snap) a.tolerance = published_snap();
    return a;
  };
  using moller97::overlap;
  using moller97::overlap_division_free;
  using moller97::segment;

  Algorithm published =
      variant_with("moller97", "the published test: interval overlap with divisions, EPSILON snap", true);
  add_level<Level::overlap>(published, []<class T>(const PairT<T>& p) { return overlap<T, true>(p); });
  registry.add(std::move(published));
  moller97::lanes_kernel::register_lanes(registry, variant_with("moller97-lanes",
      "the published test on SIMD lanes of pairs (lanes.cpp): the port's answers, bit for bit", true));

  Algorithm exact_zero = variant_with(
      "moller97-nosnap", "the published test without the EPSILON snap (exact-zero comparisons)", false);
  add_level<Level::overlap>(exact_zero, []<class T>(const PairT<T>& p) { return overlap<T, false>(p); });
  registry.add(std::move(exact_zero));

  Algorithm division_free = variant_with(
      "moller97-nodiv", "the author's division-free interval test (later code), EPSILON snap", true);
  add_level<Level::overlap>(division_free, []<class T>(const PairT<T>& p) { return overlap_division_free<T, true>(p); });
  registry.add(std::move(division_free));

  Algorithm with_segment = variant_with(
      "moller97-segment",
      "the author's variant returning the intersection segment and a coplanar flag, EPSILON snap", true);
  add_level<Level::overlap>(with_segment, []<class T>(const PairT<T>& p) { return moller97::overlap_with_segment<T, true>(p); });
  add_level<Level::segment>(with_segment, []<class T>(const PairT<T>& p) { return segment<T, true>(p); });
  registry.add(std::move(with_segment));
}

}  // namespace tritri
