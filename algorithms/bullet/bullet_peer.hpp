// Bullet 3.24 as a peer: GImpact's two triangle–triangle tests, from
// BulletCollision/Gimpact/btTriangleShapeEx.h and BulletCollision/Gimpact/gim_tri_collision.h
// (Debian libbullet-dev, the default float build: btScalar is float, so each coordinate is
// rounded to float as a user's btVector3 would round it).
//
// Neither is a set-intersection test (read from Bullet 3.24's sources):
//  - btPrimitiveTriangle: buildTriPlane() on both, overlap_test_conservative(), then
//    find_triangle_collision_clip_method() — what btGImpactCollisionAlgorithm runs for each
//    candidate triangle pair of GImpact mesh–mesh collision. Each triangle carries a margin
//    (0.01 by default); the two are summed and compared, absolute, with the Euclidean distance
//    *in front of* the other triangle's plane. Points behind a plane always count (a
//    penetration test for oriented faces of solids), so the answer depends on vertex order.
//    The clip keeps points within FLT_EPSILON (absolute) outside the edge planes.
//  - GIM_TRIANGLE::collide_triangle: an AABB test widened by the margins (0.1 each by default),
//    then collide_triangle_hard_test: both planes oriented towards the other triangle, one
//    direction clipped. Its normals use a fast inverse square root that reads btScalar's bits
//    as a 32-bit integer: it is correct only in the float build (in Debian's double build it
//    reads uninitialised bytes), which is one more reason to link the float build.
// Zero-area triangles give a NaN plane (0/0) in both: every comparison fails, answers are
// meaningless but there is no crash.
#pragma once

#include "tritri/geometry.hpp"

namespace tritri::bullet_peer {

// sizeof(btScalar) in the linked build: 4 (float) or 8.
int scalar_bytes();

// btPrimitiveTriangle conservative test + clip method, each triangle with m_margin = margin.
bool gimpact_overlap(const TrianglePair& pair, double margin);
inline bool gimpact_default(const TrianglePair& pair) { return gimpact_overlap(pair, 0.01); }
inline bool gimpact_margin0(const TrianglePair& pair) { return gimpact_overlap(pair, 0.0); }

// GIM_TRIANGLE::collide_triangle, each triangle with m_margin = margin.
bool gim_triangle_overlap(const TrianglePair& pair, double margin);
inline bool gim_triangle_default(const TrianglePair& pair) { return gim_triangle_overlap(pair, 0.1); }

}  // namespace tritri::bullet_peer
