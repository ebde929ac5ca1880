#include "algorithms/held97/held97.hpp"

#include "tritri/algorithm.hpp"
#include "tritri/counting.hpp"

namespace tritri {
namespace {

constexpr const char* kCitation =
    "Martin Held. ERIT - A Collection of Efficient and Reliable Intersection Tests. journal of "
    "graphics tools 2(4):25-44, 1997. (Triangle-triangle test reconstructed from the descriptions "
    "by Moller 1997 and Tropp et al. 2006; the source was never published.)";

Tolerance length_tolerance() {
  return {held97::kZero,
          "length (input units): distance of T2's vertices to T1's plane (unit normal) and, in the 2-D "
          "projection, of a point to an edge line; within it counts as on",
          false};
}

Algorithm entry(std::string name, std::string summary, bool tolerant) {
  return Algorithm({.name = std::move(name), .citation = kCitation, .summary = std::move(summary),
                    .tolerance = tolerant ? length_tolerance() : Tolerance{}});
}

}  // namespace

void register_held97(Registry& registry) {
  Algorithm published = entry(
      "held97",
      "ERIT (reconstructed): cut T2 by T1's plane, 2-D segment-vs-triangle; segment = s clipped to T1",
      true);
  add_level<Level::overlap>(published, []<class T>(const PairT<T>& p) { return held97::overlap<T, true>(p); });
  add_level<Level::segment>(published, []<class T>(const PairT<T>& p) { return held97::segment<T, true>(p); });
  registry.add(std::move(published));

  Algorithm exact = entry(
      "held97-notol",
      "the same reconstruction with the tolerance set to 0 (exact-zero comparisons), to show what it buys",
      false);
  add_level<Level::overlap>(exact, []<class T>(const PairT<T>& p) { return held97::overlap<T, false>(p); });
  add_level<Level::segment>(exact, []<class T>(const PairT<T>& p) { return held97::segment<T, false>(p); });
  registry.add(std::move(exact));
}

}  // namespace tritri
