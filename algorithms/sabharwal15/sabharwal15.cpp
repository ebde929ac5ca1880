#include "algorithms/sabharwal15/sabharwal15.hpp"

#include "tritri/add_level.hpp"

namespace tritri {
void register_sabharwal15(Registry& registry) {
  // Closed: 0 ≤ u, v, s, t and u + v, s + t ≤ 1. Not degenerate input: δ = |U×V|² = 0 divides.
  const Declaration paper{.citation = "Chaman L. Sabharwal, Jennifer L. Leopold. A Triangle-Triangle Intersection Algorithm. In "
                                      "D. C. Wyld et al. (eds.), WiMo, ITCSE, ICAIT, NC 2015, Computer Science & Information "
                                      "Technology (CS & IT), pp. 27-35, 2015. doi:10.5121/csit.2015.51003"};
  using namespace sabharwal15;
  Algorithm published = variant(paper,
      "sabharwal15",
      "§3 as published: (s,t) inequalities and none/point/segment/area by float equality "
      "(decides overlap of T2's projection onto T1's plane, not intersection)");
  add_level<Level::relation>(published, []<class T>(const PairT<T>& p) { return published_relation<T>(p); });
  add_level<Level::segment>(published, []<class T>(const PairT<T>& p) { return published_segment<T>(p); });
  registry.add(std::move(published));

  Algorithm plane = variant(paper,
      "sabharwal15-plane",
      "§3 plus the dropped equation N·AP + s N·S + t N·T = 0: one interval when the planes cross, "
      "the published system when coplanar");
  add_level<Level::relation>(plane, []<class T>(const PairT<T>& p) { return plane_relation<T>(p); });
  add_level<Level::segment>(plane, []<class T>(const PairT<T>& p) { return plane_segment<T>(p); });
  registry.add(std::move(plane));
}

}  // namespace tritri
