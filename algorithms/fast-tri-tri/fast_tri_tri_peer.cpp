// fast-triangle-triangle-intersection runs in Node.js, as a process peer (fast_tri_tri.mjs,
// README.md): registered here with what its source says about it, and reached by the harness
// over the process protocol. Zero-area triangles are not passed: it refuses them itself.
#include "tritri/algorithm.hpp"

namespace tritri {

void register_fast_tri_tri(Registry& registry) {
  Declaration d{.name = "fast-tri-tri"};
  d.citation = "A. Antoine. fast-triangle-triangle-intersection 1.0.7 (npm), trianglesIntersect; after O. Devillers, "
               "P. Guigue, Faster Triangle-Triangle Intersection Tests, INRIA RR-4488, 2002";
  d.summary = "fast-triangle-triangle-intersection 1.0.7 in Node.js: Guigue-Devillers with orientation determinants "
              "snapped to 0 within 1e-10 (closed)";
  d.tolerance.value = 1e-10;
  d.tolerance.quantity = "orient3D, the 4x4 determinant (six times the signed volume; unnormalised), and orient2D "
                         "after its coplanar transform";
  registry.add(process_peer(std::move(d), "node {peers}/fast-tri-tri/fast_tri_tri.mjs"));
}

}  // namespace tritri
