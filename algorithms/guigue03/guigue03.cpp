#include "algorithms/guigue03/guigue03.hpp"

#include "tritri/add_level.hpp"

namespace tritri {
namespace guigue03::lanes_kernel {
void register_lanes(Registry& registry, Algorithm variant);  // lanes.cpp
}

void register_guigue03(Registry& registry) {
  // Closed; no tolerance: every decision is the sign of a determinant.
  const Declaration paper{.citation = "Philippe Guigue, Olivier Devillers. Fast and Robust Triangle-Triangle Overlap Test Using "
                                      "Orientation Predicates. journal of graphics tools 8(1):25-32, 2003. "
                                      "doi:10.1080/10867651.2003.10487580"};
  Algorithm published = variant(paper, "guigue03", "the published overlap test: orientation signs only, no construction");
  add_level<Level::overlap>(published, []<class T>(const PairT<T>& p) { return guigue03::overlap<T>(p); });
  registry.add(std::move(published));

  Algorithm with_segment = variant(paper,
      "guigue03-segment",
      "the variant returning the intersection segment (constructed after the signs decide) and a coplanar flag");
  add_level<Level::overlap>(with_segment, []<class T>(const PairT<T>& p) { return guigue03::overlap_with_segment<T>(p); });
  add_level<Level::segment>(with_segment, []<class T>(const PairT<T>& p) { return guigue03::segment<T>(p); });
  registry.add(std::move(with_segment));
  guigue03::lanes_kernel::register_lanes(registry, variant(paper, "guigue03-lanes",
      "the published overlap test on SIMD lanes of pairs (lanes.cpp): the port's answers, bit for bit"));
}

}  // namespace tritri
