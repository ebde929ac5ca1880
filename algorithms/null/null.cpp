#include "algorithms/null/null.hpp"

#include "tritri/algorithm.hpp"

namespace tritri {

void register_null(Registry& registry) {
  // It reads coordinates and nothing else: any input is as good, degenerate included.
  Algorithm a({.name = "null",
               .citation = "none: the timing floor of tritri (reads every coordinate, returns a bit derived from them)",
               .summary = "NOT a test: answers a bit of the XOR of the 18 coordinates' bit patterns; its check "
                          "results are meaningless",
               .accepts_degenerate = true});
  a.set_batch<Level::overlap>(Scalar::double_, overlap_batch<&null_floor::overlap<double>>);
  a.set_batch<Level::overlap>(Scalar::float_, overlap_batch<&null_floor::overlap<float>>);
  registry.add(std::move(a));
}

}  // namespace tritri
