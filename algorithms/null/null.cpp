#include "algorithms/null/null.hpp"

#include "tritri/add_level.hpp"

#include <concepts>

namespace tritri {

void register_null(Registry& registry) {
  // It reads coordinates and nothing else: any input is as good, degenerate included.
  Algorithm a({.name = "null",
               .citation = "none: the timing floor of tritri (reads every coordinate, returns a bit derived from them)",
               .summary = "NOT a test: answers a bit of the XOR of the 18 coordinates' bit patterns; its check "
                          "results are meaningless",
               .accepts_degenerate = true});
  // Floating point only: it reads the coordinates' bit patterns, which the counting scalar has not.
  add_level<Level::overlap>(a, []<std::floating_point T>(const PairT<T>& p) { return null_floor::overlap<T>(p); });
  registry.add(std::move(a));
}

}  // namespace tritri
