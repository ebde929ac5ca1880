// Rapier runs in Node.js (parry compiled to WebAssembly), as a process peer (rapier.mjs,
// README.md): registered here with what its documentation and behaviour say about it, and
// reached by the harness over the process protocol.
#include "tritri/algorithm.hpp"

namespace tritri {

void register_rapier(Registry& registry) {
  // The coordinates become float32 on their way into WebAssembly: a relative 2^-24 on each.
  const Tolerance float32{0x1p-24, "each coordinate, rounded to float32; then GJK's termination tests in float32", true};
  registry.add(process_peer(
      {"rapier",
       "S. Crozet et al. Rapier 0.21.0 (@dimforge/rapier3d-compat, npm): parry3d's intersection test compiled to "
       "WebAssembly, Shape.intersectsShape on two Triangle shapes",
       "Rapier 0.21 (parry, WebAssembly) Shape.intersectsShape on two Triangles in Node.js: GJK in float32 (closed)",
       Boundary::closed, float32},
      "node {peers}/rapier/rapier.mjs"));
}

}  // namespace tritri
