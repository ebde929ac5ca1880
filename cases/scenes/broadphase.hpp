// FCL 0.7 BVH broad phase that records candidate triangle pairs.
//
// For one bounding-volume type, a BroadPhase owns FCL BVHModels of the two meshes (built once, in
// the meshes' own frames) and, per frame, runs FCL's own bounding-volume-tree traversal with the
// leaf test replaced by a recorder: every leaf pair whose leaf BVs overlap - exactly the pairs on
// which FCL would call its triangle test - is appended in traversal order. Nothing is tested.
//
// Transforms (see NOTES.md): for OBB, OBBRSS and kIOS, fcl::collide keeps both trees in their
// local frames and tests BVs under the relative transform R, T = tf1^-1 tf2 (Mode::Relative).
// For AABB, the k-DOPs and - in 0.7 - also RSS, fcl::collide copies both models, moves every
// vertex into the world frame and rebuilds both trees on every query (Mode::WorldRebuild). The
// recorder can reproduce either, and also a cheaper world-frame refit (Mode::WorldRefit).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "cases/scenes/mesh.hpp"

namespace tritri::scenes {

enum class BV { OBB, RSS, OBBRSS, kIOS, AABB, KDOP16, KDOP18, KDOP24 };
enum class Mode {
  Default,       // what fcl::collide does for this BV type (see above)
  Relative,      // local trees, relative transform (OBB, RSS, OBBRSS, kIOS only)
  WorldRebuild,  // copy, transform vertices, rebuild the tree (any BV)
  WorldRefit     // copy, transform vertices, refit the local tree's topology bottom-up (any BV)
};

const char* bv_name(BV bv);
const char* mode_name(Mode m);
BV parse_bv(const std::string& s);        // throws std::invalid_argument
Mode parse_mode(const std::string& s);
std::vector<BV> all_bvs();
Mode resolve(BV bv, Mode m);              // Default -> the concrete mode; throws if unsupported

// One candidate: triangle a of the first mesh, triangle b of the second (same mesh for self).
struct Candidate {
  std::uint32_t a, b;
  bool operator==(const Candidate& o) const { return a == o.a && b == o.b; }
};

struct TraversalStats {
  double setup_seconds = 0;      // per query: transform + rebuild/refit (world modes), node set-up
  double traverse_seconds = 0;   // the BVTT recursion with the recording leaf
  long long bv_tests = 0;        // BV overlap tests FCL counted (enable_statistics)
};

struct CollideTiming {
  double seconds = 0;
  std::size_t contacts = 0;
};

class BroadPhase {
 public:
  virtual ~BroadPhase() = default;
  virtual BV bv() const = 0;
  virtual Mode mode() const = 0;
  virtual double build_seconds() const = 0;

  // Candidates of mesh1 at tf1 against mesh2 at tf2, appended to `out` in traversal order.
  virtual TraversalStats collect(const Rigid& tf1, const Rigid& tf2, std::vector<Candidate>& out) = 0;
  // Self query (the object must have been made with make_self_broad_phase): every leaf pair of
  // the tree against itself, each unordered pair once, never a triangle with itself. FCL has no
  // self query in fcl::collide; this is detail::selfCollide on a mesh traversal node.
  virtual TraversalStats collect_self(std::vector<Candidate>& out) = 0;

  // FCL's whole query (broad + narrow phase) through fcl::collide, with its default request
  // except num_max_contacts (enable_contact = false: yes/no per triangle pair, no contact points).
  virtual CollideTiming fcl_collide(const Rigid& tf1, const Rigid& tf2, std::size_t max_contacts) = 0;
};

std::unique_ptr<BroadPhase> make_broad_phase(BV bv, Mode mode, const Mesh& m1, const Mesh& m2);
std::unique_ptr<BroadPhase> make_self_broad_phase(BV bv, const Mesh& m);

// Does every BV of FCL's tree contain the triangles under it? For each node and each corner of
// each triangle below it, the "excess" is how far the point lies outside the BV (OBB: beyond an
// extent; RSS: distance to the rectangle minus the radius; kIOS: the worse of its spheres and its
// OBB; AABB / k-DOP: beyond a slab). Positive excess means the BV is not conservative and a
// touching contact at that point can be pruned. Also reports how far the RSS / OBB frames are
// from orthonormal. The tree is built from `m` (local frame); with `world`, the vertices are then
// moved by tf and the tree is rebuilt (refit = false) or refitted bottom-up (refit = true), as the
// world modes of the broad phase do.
struct BVAudit {
  long long checked = 0;          // (node, corner) incidences
  long long outside = 0;          // of which with positive excess
  double max_excess = 0;          // largest excess (absolute, mesh units)
  double max_frame_error = 0;     // max |A^T A - I| over oriented frames (OBB, RSS, kIOS's OBB)
  int nodes = 0;
};
BVAudit audit_bvh(BV bv, const Mesh& m, bool world, const Rigid& tf, bool refit);

// FCL's own triangle test (fcl::detail::Intersect<double>::intersect_Triangle, the one its mesh
// traversal calls) on world-frame triangles; used to time the narrow-phase share of a query.
bool fcl_triangle_test(const Vec3& p1, const Vec3& p2, const Vec3& p3,
                       const Vec3& q1, const Vec3& q2, const Vec3& q3);

}  // namespace tritri::scenes
