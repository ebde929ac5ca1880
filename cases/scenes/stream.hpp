// A scene's candidate stream: what the harness reads of a scene. For one scene and one
// bounding-volume type, every frame's candidate triangle pairs (the leaf pairs FCL's BVH traversal
// lets through), in traversal order, as world-coordinate triangle pairs; plus, on request, the time
// FCL spends on the same query (traversal only, its own triangle test on the candidates, and its
// whole fcl::collide), so a reader can put a triangle test's time beside the traversal's.
//
// This header is all the harness needs: it hides FCL, CGAL and the scene catalogue.
#pragma once

#include "tritri/geometry.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace tritri::scenes {

struct StreamOptions {
  std::string bv = "OBB";  // OBB, RSS, OBBRSS, kIOS, AABB, KDOP16, KDOP18, KDOP24
  int frames = 16;         // frames of a moving scene (self scenes on a fixed mesh have one)
  bool small = false;      // the scenes' small sizes (procedural only, a few hundred triangles a body)
  std::string user_mesh;   // --mesh FILE, for mesh_self and mesh_sphere
  bool adjacent = false;   // self scenes: keep pairs of faces sharing a vertex (see below)
  bool time_fcl = false;   // measure FCL's own times (StreamTimes)
  int repetitions = 3;     // for the times: the fastest of this many
};

struct StreamPair {
  TrianglePair pair;  // world coordinates
  int frame = 0;
  int body1 = 0, body2 = 0;      // which bodies (equal for a self scene)
  std::uint32_t tri1 = 0, tri2 = 0;
  int shared = 0;                // self scenes: vertex indices the two faces share
};

// Per frame, averaged over the frames, in milliseconds; FCL's paths are those fcl::collide takes.
struct StreamTimes {
  double setup_ms = 0;        // per-query copy, transform and rebuild (FCL does this for AABB, k-DOPs, RSS)
  double traverse_ms = 0;     // the BVH traversal alone (its leaf test records instead of testing)
  double fcl_triangle_ms = 0; // FCL's own triangle test over the candidates
  double collide_all_ms = 0;  // fcl::collide, all contacts (self scenes: not available, 0)
  double collide_any_ms = 0;  // fcl::collide, stop at the first contact
  double contacts = 0;        // intersecting pairs fcl::collide reports
};

struct SceneStream {
  std::string scene, description, bv, mode;
  std::uint64_t seed = 0;
  int frames = 0;
  bool self = false;
  std::string bodies;                    // "knot1.off 6400 + torus 8192"
  std::vector<StreamPair> pairs;         // frame by frame, each in traversal order
  std::size_t dropped_adjacent = 0;      // self scenes without `adjacent`: pairs left out
  StreamTimes times;                     // zero unless time_fcl
};

// Self scenes: FCL's self traversal also yields faces sharing a vertex or an edge. A triangle
// test answers "intersect" for every one of them (they touch), and mesh-repair tools judge them
// by other rules, so by default they are left out and counted (dropped_adjacent).

// Throws std::invalid_argument (unknown scene or BV type), std::runtime_error (mesh data missing
// or a mesh file that cannot be read: the message names file and line).
SceneStream scene_stream(const std::string& scene, const StreamOptions& options);

// For pictures: each body's triangles in world coordinates at `frame` (clamped to the scene's),
// every k-th face so that a body has at most `max_per_body`.
std::vector<std::vector<TriangleT<double>>> scene_bodies(const std::string& scene, const StreamOptions& options,
                                                         int frame, std::size_t max_per_body);

struct SceneInfo {
  std::string name, description;
  std::uint64_t seed = 0;
  bool self = false, cgal_data = false, user_mesh = false;
};
// Every scene, built-in ones first; the ones needing data are listed too (flags tell).
std::vector<SceneInfo> scene_catalogue();
// The BV types, in FCL's order, and the ones whose candidates are complete (see the
// completeness test: RSS and kIOS drop exactly touching pairs in FCL 0.7).
std::vector<std::string> bv_types();
bool bv_complete(const std::string& bv);

}  // namespace tritri::scenes
