// scenes, i.e. meshes in rigid motion over F frames, whose candidate
// triangle pairs (from a BVH broad phase) are the pairs a collision query really asks about.
//
// A scene has bodies; each body has a mesh in its own frame and a transform per frame. A pair
// scene queries every pair of bodies (i < j). A self scene has one body and queries the mesh
// against itself; its mesh may change from frame to frame (a deformation instead of a motion).
//
// World coordinates of a body at frame k are `tf(k) * p` (Eigen, as FCL does it). Scenes marked
// `exact` use translations only, by multiples of 2^-20, on meshes whose coordinates are multiples
// of 2^-20: their world coordinates are exact, so faces that are coplanar by construction (boxes
// stacked at the same z) stay exactly coplanar in every frame.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cases/scenes/mesh.hpp"

namespace tritri::scenes {

struct Body {
  std::string role;                              // short label, e.g. "lower box"
  std::shared_ptr<const Mesh> mesh;              // mesh in its own frame (frame-independent)
  std::function<Rigid(int frame)> motion;        // transform at a frame
};

struct Scene {
  std::string name;
  std::string description;
  std::uint64_t seed = 0;
  int frames = 1;
  bool self = false;                             // one body against itself
  bool exact = false;                            // translations by dyadic amounts only
  std::vector<Body> bodies;
  // Self scenes only: the mesh at a frame when it deforms (empty: bodies[0].mesh every frame).
  std::function<Mesh(int frame)> deform;

  // The body pairs queried each frame: (i, j), i < j; a self scene gives (0, 0).
  std::vector<std::pair<int, int>> body_pairs() const;
  // The mesh of body b at frame k (the deformed one for self scenes with `deform`).
  std::shared_ptr<const Mesh> mesh_at(int b, int k) const;
  Rigid transform_at(int b, int k) const { return bodies[b].motion(k); }
};

enum class Size {
  Small,   // procedural only, a few hundred triangles per body: for the completeness check
  Full     // benchmark size, including meshes read from CGAL's data set
};

struct SceneConfig {
  Size size = Size::Full;
  int frames = 16;                               // per scene (self scenes on a static mesh use 1)
  // CGAL's data/meshes, unpacked from libcgal-demo (empty: cgal_mesh_dir(), see data.hpp).
  std::string mesh_dir;
  // A mesh file the user brings (--mesh): the scenes "mesh_self" and "mesh_sphere" use it.
  std::string user_mesh;
};

// Every built-in scene, in a fixed order. Scenes needing a mesh file that cannot be read are not
// silently skipped: the MeshError propagates (callers decide whether to skip them).
std::vector<std::string> scene_names(Size size);
// Whether a scene reads CGAL's data meshes (libcgal-demo), or the user's mesh.
bool needs_cgal_data(const std::string& name);
bool needs_user_mesh(const std::string& name);
Scene make_scene(const std::string& name, const SceneConfig& config);

}  // namespace tritri::scenes
