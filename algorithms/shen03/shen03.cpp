#include "algorithms/shen03/shen03.hpp"

#include "tritri/add_level.hpp"

namespace tritri {

void register_shen03(Registry& registry) {
  Algorithm a;
  a.name = "shen03";
  a.citation =
      "Hao Shen, Pheng Ann Heng, Zesheng Tang. A Fast Triangle-Triangle Overlap Test Using Signed "
      "Distances. journal of graphics tools 8(1):3-15, 2003.";
  a.summary =
      "the published routine (tri_tri.c): signed plane distances and unnormalised line-line triple "
      "products, absolute 1e-7 tolerance";
  a.boundary = Boundary::closed;
  a.tolerance = {shen03::kTolerance,
                 "|N·V+d| (unnormalised plane distance) snapped to 0 below it; line-line triple products "
                 "((e×f)·(U0−V0)) compared with ±1e-7",
                 false};
  // Degenerate input reaches the path where the published code reads unset pointers; the port is
  // defined there (the coplanar branch) but makes no claim for such input.
  a.accepts_degenerate = false;
  add_level<Level::overlap>(a, []<class T>(const PairT<T>& p) { return shen03::overlap<T>(p); });
  registry.add(std::move(a));
}

}  // namespace tritri
