// VTK's headers are included here only.
#include "algorithms/vtk/vtk_peer.hpp"

#include "tritri/algorithm.hpp"

#include <vtkIntersectionPolyDataFilter.h>

namespace tritri {
namespace vtk_peer {
namespace {

constexpr double kTolerance = 1e-6;  // vtkIntersectionPolyDataFilter's default Tolerance

struct Result {
  int intersects = 0;
  int coplanar = 0;
  double p[3] = {0, 0, 0}, q[3] = {0, 0, 0};
};

Result intersect(const TrianglePair& pair) {
  // The function takes non-const double[3]: copies, as a user holding const data makes them.
  double v[6][3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      v[i][k] = pair.t1[i][k];
      v[3 + i][k] = pair.t2[i][k];
    }
  Result r;
  double surface_id[2] = {0, 0};
  r.intersects = vtkIntersectionPolyDataFilter::TriangleTriangleIntersection(
      v[0], v[1], v[2], v[3], v[4], v[5], r.coplanar, r.p, r.q, surface_id, kTolerance);
  return r;
}

}  // namespace

SegmentAnswer segment(const TrianglePair& pair) {
  const Result r = intersect(pair);
  SegmentAnswer s;
  if (r.intersects) {
    s.p = {r.p[0], r.p[1], r.p[2]};
    s.q = {r.q[0], r.q[1], r.q[2]};
    s.kind = s.p == s.q ? SegmentKind::point : SegmentKind::segment;
  } else {
    s.kind = r.coplanar ? SegmentKind::coplanar : SegmentKind::empty;
  }
  return s;
}

Overlap overlap(const TrianglePair& pair) {
  const Result r = intersect(pair);
  if (r.intersects) return Overlap::yes;
  return r.coplanar ? Overlap::unsupported : Overlap::no;
}

}  // namespace vtk_peer

void register_vtk(Registry& registry) {
  Algorithm a({.name = "vtk",
               .citation = "W. Schroeder, K. Martin, B. Lorensen. The Visualization Toolkit, 4th ed., Kitware 2006. "
                           "Code: VTK 9.1, vtkIntersectionPolyDataFilter::TriangleTriangleIntersection",
               .summary = "VTK 9.1 TriangleTriangleIntersection, tolerance 1e-6 (the filter's default): "
                          "plane-line intervals; declines coplanar pairs it recognises",
               .tolerance = {.value = 1e-6,
                             .quantity = "product of two signed distances to a unit-normal plane (early exit); "
                                         "slack on each edge parameter t",
                             .relative = false}});
  a.set_batch<Level::overlap>(Scalar::double_, overlap_batch<&vtk_peer::overlap>);
  a.set_batch<Level::segment>(Scalar::double_, segment_batch<&vtk_peer::segment>);
  registry.add(std::move(a));
}

}  // namespace tritri
