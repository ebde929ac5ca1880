#include "algorithms/held97/held97.hpp"

#include "tritri/add_level.hpp"

namespace tritri {
namespace {


Tolerance length_tolerance() {
  return {held97::kZero,
          "length (input units): distance of T2's vertices to T1's plane (unit normal) and, in the 2-D "
          "projection, of a point to an edge line; within it counts as on",
          false};
}


}  // namespace

void register_held97(Registry& registry) {
  const Declaration paper{.citation = "Martin Held. ERIT - A Collection of Efficient and Reliable Intersection Tests. journal of "
                                      "graphics tools 2(4):25-44, 1997. (Triangle-triangle test reconstructed from the descriptions "
                                      "by Moller 1997 and Tropp et al. 2006; the source was never published.)"};
  auto variant_with = [&](std::string name, std::string summary, bool tolerant) {
    Algorithm a = variant(paper, std::move(name), std::move(summary));
    if (tolerant) a.tolerance = length_tolerance();
    return a;
  };
  Algorithm published = variant_with(
      "held97",
      "ERIT (reconstructed): cut T2 by T1's plane, 2-D segment-vs-triangle; segment = s clipped to T1",
      true);
  add_level<Level::overlap>(published, []<class T>(const PairT<T>& p) { return held97::overlap<T, true>(p); });
  add_level<Level::segment>(published, []<class T>(const PairT<T>& p) { return held97::segment<T, true>(p); });
  registry.add(std::move(published));

  Algorithm exact = variant_with(
      "held97-notol",
      "the same reconstruction with the tolerance set to 0 (exact-zero comparisons), to show what it buys",
      false);
  add_level<Level::overlap>(exact, []<class T>(const PairT<T>& p) { return held97::overlap<T, false>(p); });
  add_level<Level::segment>(exact, []<class T>(const PairT<T>& p) { return held97::segment<T, false>(p); });
  registry.add(std::move(exact));
}

}  // namespace tritri
