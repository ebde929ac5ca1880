// FCL's headers are included here only, so nothing else compiles against them.
#include "algorithms/fcl/fcl_peer.hpp"

#include "tritri/algorithm.hpp"

#include <fcl/narrowphase/detail/traversal/collision/intersect.h>

namespace tritri {
namespace fcl_peer {

bool overlap(const TrianglePair& pair) {
  // Eigen::Vector3d is fcl::Vector3<double>: the vertices are passed as they are.
  return ::fcl::detail::Intersect<double>::intersect_Triangle(pair.t1[0], pair.t1[1], pair.t1[2],
                                                              pair.t2[0], pair.t2[1], pair.t2[2]);
}

}  // namespace fcl_peer

void register_fcl(Registry& registry) {
  Algorithm a({.name = "fcl",
               .citation = "J. Pan, S. Chitta, D. Manocha. FCL: A General Purpose Library for Collision and "
                           "Proximity Queries. IEEE ICRA 2012, pp. 3859-3866. Code: FCL 0.7, "
                           "fcl::detail::Intersect<double>::intersect_Triangle",
               .summary = "FCL 0.7 intersect_Triangle: separating-axis test on 17 axes, strict separation (closed)"});
  // The batch loop is generated in this file, beside the kernel, so the per-pair call inlines.
  a.set_batch<Level::overlap>(Scalar::double_, overlap_batch<&fcl_peer::overlap>);
  registry.add(std::move(a));
}

}  // namespace tritri
