#include "algorithms/held97/held97.hpp"

#include "tritri/algorithm.hpp"
#include "tritri/counting.hpp"

namespace tritri {
namespace {

constexpr const char* kCitation =
    "Martin Held. ERIT - A Collection of Efficient and Reliable Intersection Tests. journal of "
    "graphics tools 2(4):25-44, 1997. (Triangle-triangle test reconstructed from the descriptions "
    "by Moller 1997 and Tropp et al. 2006; the source was never published.)";

Algorithm entry(std::string name, std::string summary, bool tolerant) {
  Algorithm a;
  a.name = std::move(name);
  a.citation = kCitation;
  a.summary = std::move(summary);
  a.boundary = Boundary::closed;
  if (tolerant)
    a.tolerance = {held97::kZero,
                   "length (input units): distance of T2's vertices to T1's plane (unit normal) and, in "
                   "the 2-D projection, of a point to an edge line; within it counts as on",
                   false};
  a.accepts_degenerate = false;
  return a;
}

}  // namespace

void register_held97(Registry& registry) {
  Algorithm published = entry(
      "held97",
      "ERIT (reconstructed): cut T2 by T1's plane, 2-D segment-vs-triangle; segment = s clipped to T1",
      true);
  published.overlap = overlap_batch<&held97::overlap<double, true>>;
  published.segment = segment_batch<&held97::segment<double, true>>;
  published.overlap_float = overlap_batch<&held97::overlap<float, true>>;
  published.segment_float = segment_batch<&held97::segment<float, true>>;
  published.overlap_counted = overlap_batch<&held97::overlap<Counted, true>>;
  published.segment_counted = segment_batch<&held97::segment<Counted, true>>;
  registry.add(std::move(published));

  Algorithm exact = entry(
      "held97-notol",
      "the same reconstruction with the tolerance set to 0 (exact-zero comparisons), to show what it buys",
      false);
  exact.overlap = overlap_batch<&held97::overlap<double, false>>;
  exact.segment = segment_batch<&held97::segment<double, false>>;
  exact.overlap_float = overlap_batch<&held97::overlap<float, false>>;
  exact.segment_float = segment_batch<&held97::segment<float, false>>;
  exact.overlap_counted = overlap_batch<&held97::overlap<Counted, false>>;
  exact.segment_counted = segment_batch<&held97::segment<Counted, false>>;
  registry.add(std::move(exact));
}

}  // namespace tritri
