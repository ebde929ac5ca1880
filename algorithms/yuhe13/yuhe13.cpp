#include "yuhe13.hpp"

#include "tritri/algorithm.hpp"

namespace tritri {
namespace {

constexpr const char* kCitation =
    "Yu Haiyan, He Yuanjun. Testing the Intersection Status of Two Triangles "
    "(空间两三角形的相交问题). Journal of Graphics (图学学报) 34(4):54-62, 2013. "
    "CN 2095-302X(2013)04-0054-09";

Algorithm entry(std::string name, std::string summary) {
  Algorithm a;
  a.name = std::move(name);
  a.citation = kCitation;
  a.summary = std::move(summary);
  a.boundary = Boundary::closed;  // contact is reported (codes 2, 3, -3, -4)
  a.accepts_degenerate = false;   // the paper: the caller excludes degenerate triangles
  return a;
}

}  // namespace

void register_yuhe13(Registry& registry) {
  using namespace yuhe13;
  Algorithm published = entry(
      "yuhe13",
      "computational frame, V-view crossings, x-extent reject as its words say, Cyrus-Beck in H; "
      "nine codes and the segment");
  published.relation = relation_batch<&relation<double, false>>;
  published.segment = segment_batch<&segment<double, false>>;
  published.relation_float = relation_batch<&relation<float, false>>;
  published.segment_float = segment_batch<&segment<float, false>>;
  registry.add(std::move(published));

  Algorithm literal = entry(
      "yuhe13-literal",
      "yuhe13 with the x-extent reject's printed formulas (max(x0,x1) > X_R or min(x0,x1) < X_L)");
  literal.relation = relation_batch<&relation<double, true>>;
  literal.segment = segment_batch<&segment<double, true>>;
  literal.relation_float = relation_batch<&relation<float, true>>;
  literal.segment_float = segment_batch<&segment<float, true>>;
  registry.add(std::move(literal));
}

}  // namespace tritri
