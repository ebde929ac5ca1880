#include "algorithms/guigue03/guigue03.hpp"

#include "tritri/algorithm.hpp"
#include "tritri/counting.hpp"

namespace tritri {
namespace {

constexpr const char* kCitation =
    "Philippe Guigue, Olivier Devillers. Fast and Robust Triangle-Triangle Overlap Test Using "
    "Orientation Predicates. journal of graphics tools 8(1):25-32, 2003. "
    "doi:10.1080/10867651.2003.10487580";

Algorithm entry(std::string name, std::string summary) {
  Algorithm a;
  a.name = std::move(name);
  a.citation = kCitation;
  a.summary = std::move(summary);
  a.boundary = Boundary::closed;
  a.accepts_degenerate = false;  // tolerance: none, every decision is the sign of a determinant
  return a;
}

}  // namespace

void register_guigue03(Registry& registry) {
  Algorithm published = entry("guigue03", "the published overlap test: orientation signs only, no construction");
  published.overlap = overlap_batch<&guigue03::overlap<double>>;
  published.overlap_float = overlap_batch<&guigue03::overlap<float>>;
  published.overlap_counted = overlap_batch<&guigue03::overlap<Counted>>;
  registry.add(std::move(published));

  Algorithm with_segment = entry(
      "guigue03-segment",
      "the variant returning the intersection segment (constructed after the signs decide) and a coplanar flag");
  with_segment.overlap = overlap_batch<&guigue03::overlap_with_segment<double>>;
  with_segment.segment = segment_batch<&guigue03::segment<double>>;
  with_segment.overlap_float = overlap_batch<&guigue03::overlap_with_segment<float>>;
  with_segment.segment_float = segment_batch<&guigue03::segment<float>>;
  with_segment.overlap_counted = overlap_batch<&guigue03::overlap_with_segment<Counted>>;
  with_segment.segment_counted = segment_batch<&guigue03::segment<Counted>>;
  registry.add(std::move(with_segment));
}

}  // namespace tritri
