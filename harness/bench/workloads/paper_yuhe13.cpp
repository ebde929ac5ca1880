// paper:yuhe13: Yu & He 2013, section 7.2, Table 1: "40 pairs of triangles, the intersection
// computed 10⁶ times over", timed as the transform alone, the test in the frame alone, and both.
// The paper prints neither the 40 pairs nor the loop, so this pool is a choice, named here: its
// section 7.1 test set as cases/yuhe13.cases rebuilds it from the figures — the 30 other
// configurations, then the first 10 singular ones, in file order (40 pairs, one A, as the paper's
// test set fixes A and moves B). Repeating the 40 as one pool is the paper's 40 × 10⁶ loop. In
// double, as our port. Yu–He's stages (transform, frame-test, both) are timed on this pool too.
// Takes /shuffled.
#include "harness/bench/workloads/paper.hpp"

#include "cases/casefile.hpp"

#ifndef TRITRI_SOURCE_DIR
#define TRITRI_SOURCE_DIR "."
#endif

namespace tritri::bench::paper {
namespace {

constexpr std::size_t kOthers = 30, kSingular = 10;

DriverPairs forty(const Value& v, const WorkloadInput&) {
  const std::string file = std::string(TRITRI_SOURCE_DIR) + "/cases/yuhe13.cases";
  std::vector<TrianglePair> others, singular;
  for (const Case& c : read_case_file(file)) {
    const bool is_singular = c.label("singular") == std::optional<std::string_view>("yes");
    auto& to = is_singular ? singular : others;
    if (to.size() < (is_singular ? kSingular : kOthers)) to.push_back(c.pair);
  }
  if (others.size() < kOthers || singular.size() < kSingular)
    throw std::runtime_error(file + ": fewer than 30 other and 10 singular cases");
  others.insert(others.end(), singular.begin(), singular.end());
  return {others, "", "driver=YuHe2013/Table1 source=cases/yuhe13.cases(30 other, 10 singular) scalar=double order=" +
                          std::string(v.shuffled ? "shuffled" : "file")};
}

}  // namespace

const Driver& yuhe13_driver() {
  static const Driver d{"yuhe13", "shuffled", &forty};
  return d;
}

}  // namespace tritri::bench::paper
