// Open3D's headers are included here only, so nothing else compiles against them.
#include "algorithms/open3d/open3d_peer.hpp"

#include "tritri/algorithm.hpp"

#include <open3d/geometry/IntersectionTest.h>

namespace tritri {
namespace open3d_peer {

bool overlap(const TrianglePair& pair) {
  // tritri's Vec3<double> is Eigen::Vector3d, Open3D's argument type: passed as they are.
  return ::open3d::geometry::IntersectionTest::TriangleTriangle3d(pair.t1[0], pair.t1[1], pair.t1[2],
                                                                  pair.t2[0], pair.t2[1], pair.t2[2]);
}

}  // namespace open3d_peer

void register_open3d(Registry& registry) {
  Algorithm a({.name = "open3d",
               .citation = "Q.-Y. Zhou, J. Park, V. Koltun. Open3D: A Modern Library for 3D Data Processing. "
                           "arXiv:1801.09847, 2018. Code: Open3D 0.16, "
                           "open3d::geometry::IntersectionTest::TriangleTriangle3d",
               .summary = "Open3D 0.16 TriangleTriangle3d: Moller 1997 (epsilon 1e-6) after centring and "
                          "per-axis scaling by the pair's spread (closed)",
               .tolerance = {.value = 1e-6,
                             .quantity = "|N.X+d| (unnormalised plane distance) after centring the six points "
                                         "and dividing each axis by its standard deviation",
                             .relative = true}});
  a.set_batch<Level::overlap>(Scalar::double_, overlap_batch<&open3d_peer::overlap>);
  registry.add(std::move(a));
}

}  // namespace tritri
