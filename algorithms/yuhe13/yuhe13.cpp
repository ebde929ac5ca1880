#include "algorithms/yuhe13/yuhe13.hpp"

#include "tritri/add_level.hpp"

namespace tritri {
namespace {



// Yu–He's Table 1 times the transform into A's frame and the test in that frame apart. The
// stage adapters take double pairs, so a transformed pair travels as a TrianglePair.
TrianglePair in_frame_of_a(const TrianglePair& pair) {
  const yuhe13::Framed<double> f = yuhe13::transform(pair);
  return {f.a, f.b};
}

// The test in the frame reads only the transformed triangles, never the frame's axes.
RelationAnswer test_in_frame(const TrianglePair& framed) {
  yuhe13::Framed<double> f;
  f.a = framed.t1;
  f.b = framed.t2;
  return answer_with(yuhe13::intersect_in_frame<double, false>(f).code);
}

}  // namespace

void register_yuhe13(Registry& registry) {
  // Closed: contact is reported (codes 2, 3, -3, -4). The paper: the caller excludes degenerate triangles.
  const Declaration paper{.citation = "Yu Haiyan, He Yuanjun. Testing the Intersection Status of Two Triangles "
                                      "(空间两三角形的相交问题). Journal of Graphics (图学学报) 34(4):54-62, 2013. "
                                      "CN 2095-302X(2013)04-0054-09"};
  using namespace yuhe13;
  Algorithm published = variant(paper,
      "yuhe13",
      "computational frame, V-view crossings, x-extent reject as its words say, Cyrus-Beck in H; "
      "nine codes and the segment");
  add_level<Level::relation>(published, []<class T>(const PairT<T>& p) { return relation<T, false>(p); });
  add_level<Level::segment>(published, []<class T>(const PairT<T>& p) { return segment<T, false>(p); });
  published.stages = {{"transform", stage_run<&in_frame_of_a>},
                      {"frame-test", stage_run<&test_in_frame>, stage_prepare<&in_frame_of_a>},
                      {"both", stage_run<&relation<double, false>>}};
  registry.add(std::move(published));

  Algorithm literal = variant(paper,
      "yuhe13-literal",
      "yuhe13 with the x-extent reject's printed formulas (max(x0,x1) > X_R or min(x0,x1) < X_L)");
  add_level<Level::relation>(literal, []<class T>(const PairT<T>& p) { return relation<T, true>(p); });
  add_level<Level::segment>(literal, []<class T>(const PairT<T>& p) { return segment<T, true>(p); });
  registry.add(std::move(literal));
}

}  // namespace tritri
