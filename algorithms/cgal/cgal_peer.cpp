#include "algorithms/cgal/cgal_peer.hpp"

#include "tritri/algorithm.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

namespace tritri {
namespace cgal_peer {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

Kernel::Point_3 point(const Vec3<double>& v) { return {v[0], v[1], v[2]}; }
Kernel::Triangle_3 triangle(const Triangle& t) { return {point(t[0]), point(t[1]), point(t[2])}; }

}  // namespace

// Converting to CGAL's types is part of what a user of CGAL pays, so it is inside the timed call.
bool overlap(const TrianglePair& pair) {
  return CGAL::do_intersect(triangle(pair.t1), triangle(pair.t2));
}

}  // namespace cgal_peer

void register_cgal(Registry& registry) {
  // Not degenerate input: CGAL's precondition is non-degenerate triangles.
  Algorithm a({.name = "cgal",
               .citation = "The CGAL Project. CGAL User and Reference Manual, 5.5: 3D Intersections, "
                           "CGAL::do_intersect(Triangle_3, Triangle_3), kernel Epick. https://doc.cgal.org/5.5/",
               .summary = "CGAL do_intersect on Epick: exact filtered predicates (closed, no tolerance)"});
  a.set_batch<Level::overlap>(Scalar::double_, overlap_batch<&cgal_peer::overlap>);
  registry.add(std::move(a));
}

}  // namespace tritri
