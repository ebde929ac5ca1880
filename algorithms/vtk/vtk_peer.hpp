// VTK 9.1 as a peer: the static vtkIntersectionPolyDataFilter::TriangleTriangleIntersection
// (vtkIntersectionPolyDataFilter.h, Debian libvtk9-dev), called with the filter's default
// Tolerance 1e-6, as the filter itself calls it.
//
// What it does (read from VTK 9.1.0's vtkIntersectionPolyDataFilter.cxx): unit normals and
// plane offsets; an early exit when the product of two signed distances to a plane exceeds the
// tolerance (a length², absolute); a coplanar test (normals and offsets equal within 1e-9,
// absolute) that returns 0 with `coplanar` set — coplanar pairs are never intersected, and with
// opposite normals the test misses, so it returns 0 with `coplanar` unset, a plain "no"; then
// the line of the two planes cut by each triangle's edges, each edge parameter widened by the
// tolerance, and the two intervals overlapped. It returns the segment. Closed for crossing
// planes. Zero-area triangles: always 0 (a zero normal makes every edge parallel), no crash.
#pragma once

#include "tritri/answers.hpp"

namespace tritri::vtk_peer {

// The segment level: a point or a segment; `coplanar` when VTK flagged the planes as equal
// (it declines those); empty otherwise.
SegmentAnswer segment(const TrianglePair& pair);

// The overlap level: yes for a point or a segment, unsupported when VTK flagged the pair
// coplanar, no otherwise.
Overlap overlap(const TrianglePair& pair);

}  // namespace tritri::vtk_peer
