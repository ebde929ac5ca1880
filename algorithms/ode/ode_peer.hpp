// ODE 0.16 as a peer: dCollide on two trimesh geoms of one triangle each (ode/ode.h,
// ode/collision_trimesh.h; Debian libode-dev, built with dReal = double and the OPCODE
// trimesh backend with its "new" trimesh–trimesh collider).
//
// What the call does (read from ODE 0.16.2's collision_trimesh_trimesh.cpp and OPCODE):
//  1. OPCODE's AABBTreeCollider rounds the vertices to float and, at the leaves, runs Möller's
//     1997 test in float with the epsilon 1e-6 × max(|d|, min(|N|², |P|²)) (relative).
//  2. Each pair that passes is clipped in double by the other's edge planes (1e-8 absolute
//     slack), and contacts are reported when the deepest point *behind* the other's plane has
//     depth >= 0 (-0.0 included: touching counts, but depending on orientation).
// A trimesh of one triangle crashes trimesh–trimesh dCollide (OPCODE builds no tree for a single
// triangle and its AABBTreeCollider does not check): each mesh lists its triangle twice, the
// same point set, which is what a user has to do.
//
// Timed as a user with moving triangles pays: two geoms built once per thread over vertex
// buffers, and per pair the vertices copied in, dGeomTriMeshDataUpdate on both (OPCODE refit),
// and dCollide asking for one contact with CONTACTS_UNIMPORTANT. Building the geoms from scratch
// per query costs more and is timed as the stage "rebuild".
#pragma once

#include "tritri/geometry.hpp"

namespace tritri::ode_peer {

// Per-thread pre-built geoms, vertices updated: the registered, timed path.
bool overlap(const TrianglePair& pair);

// Everything from scratch: two dTriMeshData and two geoms built, dCollide, four destroys.
bool overlap_rebuild(const TrianglePair& pair);

}  // namespace tritri::ode_peer
