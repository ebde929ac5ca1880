// FCL 0.7 (the Flexible Collision Library) as a peer: its triangle–triangle test
// fcl::detail::Intersect<double>::intersect_Triangle, from
// fcl/narrowphase/detail/traversal/collision/intersect.h.
//
// What the peer is (read from FCL 0.7's intersect-inl.h, not from a paper): a separating-axis
// test. Both triangles are translated so that P1 is the origin; then 17 candidate axes are
// tried in a fixed order — the normal of P, the normal of Q, the nine cross products of an edge
// of P with an edge of Q, and the three in-plane edge normals (edge × normal) of each triangle.
// An axis separates when the two triangles' projections on it are strictly apart
// (min P > max Q or min Q > max P), so touching counts as meeting: closed. No tolerance (every
// comparison is on the raw projections). Coplanar pairs are decided by the six in-plane edge
// normals; a zero axis (parallel edges) never separates.
//
// Not chosen: FCL's intersect_Triangle_ODE_style, a plane-clip and deepest-point test that is
// a different and weaker test (it rejects every coplanar pair by construction).
//
// Degenerate (zero-area) triangles: FCL states nothing; with a zero normal several axes vanish
// and the axis set is no longer complete. Not accepted.
//
// FCL's code is not ours: the peer is not templated, and only double is registered, because
// FCL's library instantiates only Intersect<double>.
#pragma once

#include "tritri/geometry.hpp"

namespace tritri::fcl_peer {

// FCL's boolean answer for the pair, with P = pair.t1 and Q = pair.t2.
bool overlap(const TrianglePair& pair);

}  // namespace tritri::fcl_peer
