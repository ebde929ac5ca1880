// three-mesh-bvh runs in Node.js, as a process peer (three_mesh_bvh.mjs, README.md): registered
// here with what its source says about it, and reached by the harness over the process protocol.
#include "tritri/algorithm.hpp"

namespace tritri {
namespace {
constexpr const char* kCitation =
    "G. Johnson et al. three-mesh-bvh 0.9.17 (npm), src/math/ExtendedTriangle.js, ExtendedTriangle.prototype."
    "intersectsTriangle; after T. Moller, A Fast Triangle-Triangle Intersection Test, JGT 2(2), 1997";
}  // namespace

// Built when registering, not at namespace scope: the registry may be filled during another
// file's static initialisation (a test suite's), before a namespace-scope Declaration exists.
void register_three_mesh_bvh(Registry& registry) {
  // It handles triangles collapsed to a segment or a point itself: it is handed zero-area pairs.
  const Declaration declaration{
      .name = "three-mesh-bvh", .citation = kCitation,
      .summary = "three-mesh-bvh 0.9.17 ExtendedTriangle.intersectsTriangle in Node.js: Moller 1997 on unit normals "
                 "(snap |d| < 1e-15), coplanar by separating axes (closed)",
      .tolerance = {1e-15, "|n.p - c|, plane distance along the unit normal (and edge lengths, for triangles "
                           "collapsed to a segment or point)"},
      .accepts_degenerate = true};
  registry.add(process_peer(declaration, "node {peers}/three-mesh-bvh/three_mesh_bvh.mjs"));
}

}  // namespace tritri
