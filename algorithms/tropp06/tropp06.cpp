#include "algorithms/tropp06/tropp06.hpp"

#include "tritri/add_level.hpp"

namespace tritri {
void register_tropp06(Registry& registry) {
  // Closed; no tolerance: every comparison is against zero.
  const Declaration paper{.citation = "Oren Tropp, Ayellet Tal, Ilan Shimshoni. A fast triangle to triangle intersection test for "
                                      "collision detection. Computer Animation and Virtual Worlds 17(5):527-535, 2006. doi:10.1002/cav.115"};
  using tropp06::Projection;
  Algorithm published = variant(paper,
      "tropp06",
      "the published routine: Cramer's rule with shared minors, division-free, 2-D step in x-y, "
      "edge vectors computed inside the call");
  add_level<Level::overlap>(published, []<class T>(const PairT<T>& p) { return tropp06::overlap<T, Projection::xy, false>(p); });
  // The published interface: the caller supplies the edge vectors, formed before the timed loop.
  published.stages = {{"edges-given", stage_run<&tropp06::overlap_with_edges>, stage_prepare<&tropp06::with_edges>}};
  registry.add(std::move(published));

  Algorithm fixed = variant(paper,
      "tropp06-fixed",
      "corrected: 2-D step in the projection dropping N_A's largest component (x-y fails when A contains "
      "the z direction); D1 on plane A cut along Q1,Q3; a point cut tested as a point; a cut line "
      "through C1 tested against edge 3");
  add_level<Level::overlap>(fixed, []<class T>(const PairT<T>& p) { return tropp06::overlap<T, Projection::dominant, true>(p); });
  registry.add(std::move(fixed));
}

}  // namespace tritri
