// the triangle mesh every scene is made of, and the small helpers shared by
// the mesh reader, the procedural generators, the scenes and the broad phase.
//
// A Mesh is an indexed triangle list in its own (local) frame. Coordinates are doubles; indices
// are 32-bit. Nothing here depends on CGAL or FCL, so the harness can include it cheaply.
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace tritri::scenes {

using Vec3 = Eigen::Vector3d;
// Same type as fcl::Transform3d, so world coordinates computed here are bit-identical to the ones
// FCL computes with `tf * p` when it moves vertices into the world frame (AABB and k-DOP paths).
using Rigid = Eigen::Transform<double, 3, Eigen::Isometry>;

struct Mesh {
  std::string name;                              // file name or generator call, for messages
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> faces;

  std::size_t num_triangles() const { return faces.size(); }
};

// Axis-aligned bounds of the vertices (not of the faces: unreferenced vertices count).
struct Bounds {
  Vec3 lo{+1e300, +1e300, +1e300};
  Vec3 hi{-1e300, -1e300, -1e300};
  void add(const Vec3& p) { lo = lo.cwiseMin(p); hi = hi.cwiseMax(p); }
  Vec3 extent() const { return hi - lo; }
};
Bounds bounds_of(const Mesh& m);

// The vertices of `m` moved by `tf`, computed as `tf * p` (Eigen's expression, the one FCL uses).
std::vector<Vec3> transformed(const Mesh& m, const Rigid& tf);

// Scale `m` by a power of two and translate it so that its bounding box is centred on the origin
// and its largest extent lies in [1, 2). The scale is exact; the centring translation is rounded
// to a multiple of 2^-20 first so that it is exact for coordinates below 2^32 (for real meshes the
// input itself is arbitrary, so this only avoids adding rounding of our own).
void normalize_dyadic(Mesh& m);

// Round x to the nearest multiple of 2^-k (ties away from zero by std::nearbyint's mode: to even).
double snap(double x, int k);

}  // namespace tritri::scenes
