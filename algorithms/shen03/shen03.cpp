#include "algorithms/shen03/shen03.hpp"

#include "tritri/algorithm.hpp"
#include "tritri/counting.hpp"

namespace tritri {

void register_shen03(Registry& registry) {
  Algorithm a;
  a.name = "shen03";
  a.citation =
      "Hao Shen, Pheng Ann Heng, Zesheng Tang. A Fast Triangle-Triangle Overlap Test Using Signed "
      "Distances. journal of graphics tools 8(1), 2003.";
  a.summary =
      "signed vertex-plane and line-line distances (lengths), Guigue-Devillers-like decision, "
      "absolute 1e-7 tolerance (reconstructed from the abstract)";
  a.boundary = Boundary::closed;
  a.tolerance = {shen03::kTolerance,
                 "length (input units): vertex-plane distance (unit normal) and line-line distance; "
                 "|d| <= 1e-7 counts as 0",
                 false};
  a.accepts_degenerate = false;
  add_level<Level::overlap>(a, []<class T>(const PairT<T>& p) { return shen03::overlap<T>(p); });
  registry.add(std::move(a));
}

}  // namespace tritri
