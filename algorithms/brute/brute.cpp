#include "algorithms/brute/brute.hpp"

#include "tritri/add_level.hpp"

namespace tritri {

void register_brute(Registry& registry) {
  Algorithm a({.name = "brute",
               .citation =
      "The brute-force baseline of Tomas Moller, A Fast Triangle-Triangle Intersection Test, journal "
      "of graphics tools 2(2):25-30, 1997 (footnote 1); segment test after Tomas Moller, Ben "
      "Trumbore, Fast, Minimum Storage Ray-Triangle Intersection, journal of graphics tools "
      "2(1):21-28, 1997",
               .summary =
      "six closed edge-vs-triangle tests (Moller-Trumbore, edges parallel to the other plane skipped), "
      "Moller's coplanar test when the planes are parallel"});  // closed, no tolerance: exact-zero determinants
  add_level<Level::overlap>(a, []<class T>(const PairT<T>& p) { return brute::overlap<T>(p); });
  registry.add(std::move(a));
}

}  // namespace tritri
