// the exact answers the completeness check compares the broad phase with.
//
// Triangles are closed (touching counts as intersecting) and exact: CGAL's
// Exact_predicates_exact_constructions_kernel on the world-frame doubles.
//
// Pairs within one mesh follow the rule of CGAL's Polygon_mesh_processing::self_intersections
// (read in CGAL 5.5's self_intersections.h, restated here in our words), which is what mesh-repair
// tools report as a self-intersection:
//   * no shared vertex index: the two closed triangles meet;
//   * one shared vertex w: they meet somewhere other than w, decided by testing each triangle's
//     edge opposite w against the other triangle;
//   * a shared edge uv: the two faces fold onto each other, i.e. the four corners are coplanar
//     and the two opposite corners lie on the same side of uv.
// Adjacency is by index, so distinct vertices at the same place (an unwelded seam) count as an
// intersection, as in CGAL.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "cases/scenes/mesh.hpp"

namespace tritri::scenes {

using Face = std::array<std::uint32_t, 3>;

bool exact_intersect(const Vec3& p1, const Vec3& p2, const Vec3& p3,
                     const Vec3& q1, const Vec3& q2, const Vec3& q3);

// What two intersecting closed triangles share, for reports: "point", "segment" or "area"
// (coplanar overlap), prefixed "coplanar " when all six corners lie in one plane.
std::string contact_kind(const Vec3& p1, const Vec3& p2, const Vec3& p3,
                         const Vec3& q1, const Vec3& q2, const Vec3& q3);

// Number of vertex indices the two faces share (0 to 3).
int shared_vertices(const Face& f, const Face& g);

// The self-intersection rule above, for faces f != g of one mesh with vertex positions `v`.
bool self_pair_intersects(const std::vector<Vec3>& v, const Face& f, const Face& g);

// Closed axis-aligned boxes of the triangles overlap (exact: comparisons of the doubles).
bool boxes_overlap(const Vec3& p1, const Vec3& p2, const Vec3& p3,
                   const Vec3& q1, const Vec3& q2, const Vec3& q3);

// All pairs (i, j) of triangles whose closed axis-aligned boxes overlap, triangles of mesh A
// (vertices va, faces fa) against mesh B; with `self`, A and B are one mesh and only i < j is
// listed. Sweep over x (sorted box starts), so the cost follows the number of pairs whose x
// ranges overlap rather than |A| * |B|. Sorted by (i, j).
std::vector<std::pair<std::uint32_t, std::uint32_t>> overlapping_box_pairs(
    const std::vector<Vec3>& va, const std::vector<Face>& fa,
    const std::vector<Vec3>& vb, const std::vector<Face>& fb, bool self);

}  // namespace tritri::scenes
