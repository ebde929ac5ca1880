// FCL 0.7 broad phase with candidate recording. See broadphase.hpp.
//
// How the recording works: FCL's traversal nodes (fcl::detail::MeshCollisionTraversalNode<BV>
// and its oriented variants ...OBB, ...RSS, ...kIOS, ...OBBRSS) are public, their leafTesting()
// and canStop() are virtual (declared in CollisionTraversalNodeBase), and FCL's recursion
// (detail::collide -> collisionRecurse, detail::selfCollide -> selfCollisionRecurse) calls
// leafTesting(b1, b2) exactly for the leaf pairs whose BVs passed BVTesting. A subclass that
// overrides leafTesting to store (primitiveId of b1, primitiveId of b2) and canStop to return
// false therefore yields FCL's candidate pairs, in FCL's order, with FCL's own BV tests.
#include "cases/scenes/broadphase.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include <fcl/fcl.h>
#include <fcl/narrowphase/detail/traversal/collision/mesh_collision_traversal_node.h>
#include <fcl/narrowphase/detail/traversal/collision_node.h>

namespace tritri::scenes {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// ------------------------------------------------------------------------------- BV type map

template <BV> struct BVType;
template <> struct BVType<BV::OBB> { using type = fcl::OBB<double>; };
template <> struct BVType<BV::RSS> { using type = fcl::RSS<double>; };
template <> struct BVType<BV::OBBRSS> { using type = fcl::OBBRSS<double>; };
template <> struct BVType<BV::kIOS> { using type = fcl::kIOS<double>; };
template <> struct BVType<BV::AABB> { using type = fcl::AABB<double>; };
template <> struct BVType<BV::KDOP16> { using type = fcl::KDOP<double, 16>; };
template <> struct BVType<BV::KDOP18> { using type = fcl::KDOP<double, 18>; };
template <> struct BVType<BV::KDOP24> { using type = fcl::KDOP<double, 24>; };

// Calls f(std::integral_constant<BV, kBV>{}) for the BV type bv: the one switch over BV types.
template <class F>
decltype(auto) with_bv(BV bv, F&& f) {
  switch (bv) {
    case BV::OBB: return f(std::integral_constant<BV, BV::OBB>{});
    case BV::RSS: return f(std::integral_constant<BV, BV::RSS>{});
    case BV::OBBRSS: return f(std::integral_constant<BV, BV::OBBRSS>{});
    case BV::kIOS: return f(std::integral_constant<BV, BV::kIOS>{});
    case BV::AABB: return f(std::integral_constant<BV, BV::AABB>{});
    case BV::KDOP16: return f(std::integral_constant<BV, BV::KDOP16>{});
    case BV::KDOP18: return f(std::integral_constant<BV, BV::KDOP18>{});
    case BV::KDOP24: return f(std::integral_constant<BV, BV::KDOP24>{});
  }
  throw std::invalid_argument("bad BV");
}

// The traversal node that keeps trees local and applies the relative transform (void: none).
template <class T> struct OrientedNode { using type = void; };
template <> struct OrientedNode<fcl::OBB<double>> { using type = fcl::detail::MeshCollisionTraversalNodeOBB<double>; };
template <> struct OrientedNode<fcl::RSS<double>> { using type = fcl::detail::MeshCollisionTraversalNodeRSS<double>; };
template <> struct OrientedNode<fcl::kIOS<double>> { using type = fcl::detail::MeshCollisionTraversalNodekIOS<double>; };
template <> struct OrientedNode<fcl::OBBRSS<double>> { using type = fcl::detail::MeshCollisionTraversalNodeOBBRSS<double>; };

// ------------------------------------------------------------------------------ the recorder

template <class Node>
class Recording final : public Node {
 public:
  std::vector<Candidate>* out = nullptr;
  void leafTesting(int b1, int b2) const override {
    out->push_back({std::uint32_t(this->model1->getBV(b1).primitiveId()),
                    std::uint32_t(this->model2->getBV(b2).primitiveId())});
  }
  bool canStop() const override { return false; }
};

// Runs FCL's recursion `recurse(&node)` over an initialised recording node whose setup began at
// t0, recording its candidates into `out`; times the setup and the traversal apart.
template <class Node, class Recurse>
TraversalStats record(Node& node, std::vector<Candidate>& out, Clock::time_point t0, Recurse recurse) {
  TraversalStats st;
  node.enable_statistics = true;
  node.out = &out;
  st.setup_seconds = seconds_since(t0);
  t0 = Clock::now();
  recurse(&node, nullptr);
  st.traverse_seconds = seconds_since(t0);
  st.bv_tests = node.num_bv_tests;
  return st;
}

template <class T>
std::shared_ptr<fcl::BVHModel<T>> build_model(const Mesh& m) {
  auto model = std::make_shared<fcl::BVHModel<T>>();
  std::vector<fcl::Vector3d> points(m.vertices.begin(), m.vertices.end());
  std::vector<fcl::Triangle> tris;
  tris.reserve(m.faces.size());
  for (const auto& f : m.faces) tris.emplace_back(f[0], f[1], f[2]);
  if (model->beginModel(int(tris.size()), int(points.size())) != fcl::BVH_OK ||
      model->addSubModel(points, tris) != fcl::BVH_OK || model->endModel() != fcl::BVH_OK)
    throw std::runtime_error("FCL could not build a BVH for " + m.name);
  model->computeLocalAABB();
  return model;
}

template <BV kBV>
class Impl final : public BroadPhase {
  using T = typename BVType<kBV>::type;
  using Oriented = typename OrientedNode<T>::type;
  static constexpr bool kHasOriented = !std::is_void_v<Oriented>;

 public:
  Impl(Mode mode, const Mesh& m1, const Mesh* m2) : mode_(mode) {
    const auto t0 = Clock::now();
    model1_ = build_model<T>(m1);
    model2_ = m2 ? build_model<T>(*m2) : model1_;
    build_seconds_ = seconds_since(t0);
  }
  BV bv() const override { return kBV; }
  Mode mode() const override { return mode_; }
  double build_seconds() const override { return build_seconds_; }

  TraversalStats collect(const Rigid& tf1, const Rigid& tf2, std::vector<Candidate>& out) override {
    fcl::CollisionRequestd request;
    fcl::CollisionResultd result;
    if constexpr (kHasOriented) {
      if (mode_ == Mode::Relative) {
        auto t0 = Clock::now();
        Recording<Oriented> node;
        fcl::detail::initialize(static_cast<Oriented&>(node), *model1_, fcl::Transform3d(tf1), *model2_,
                                fcl::Transform3d(tf2), request, result);
        return record(node, out, t0, fcl::detail::collide<double>);
      }
    }
    if (mode_ == Mode::Relative) throw std::logic_error("Relative mode needs an oriented BV");
    // World modes: as fcl::collide's generic path, on copies moved into the world frame.
    auto t0 = Clock::now();
    fcl::BVHModel<T> c1(*model1_), c2(*model2_);
    fcl::Transform3d w1(tf1), w2(tf2);
    Recording<fcl::detail::MeshCollisionTraversalNode<T>> node;
    const bool refit = mode_ == Mode::WorldRefit;
    fcl::detail::initialize(static_cast<fcl::detail::MeshCollisionTraversalNode<T>&>(node), c1, w1, c2, w2,
                            request, result, refit, /*refit_bottomup=*/true);
    return record(node, out, t0, fcl::detail::collide<double>);
  }

  TraversalStats collect_self(std::vector<Candidate>& out) override {
    if (model1_ != model2_) throw std::logic_error("collect_self on a pair broad phase");
    fcl::CollisionRequestd request;
    fcl::CollisionResultd result;
    auto t0 = Clock::now();
    fcl::Transform3d identity = fcl::Transform3d::Identity();
    fcl::Transform3d identity2 = identity;
    // Generic node: BVs of one tree in one frame (identity transforms leave the model untouched).
    Recording<fcl::detail::MeshCollisionTraversalNode<T>> node;
    fcl::detail::initialize(static_cast<fcl::detail::MeshCollisionTraversalNode<T>&>(node), *model1_, identity,
                            *model1_, identity2, request, result);
    return record(node, out, t0, fcl::detail::selfCollide<double>);
  }

  CollideTiming fcl_collide(const Rigid& tf1, const Rigid& tf2, std::size_t max_contacts) override {
    fcl::CollisionRequestd request(max_contacts, /*enable_contact=*/false);
    fcl::CollisionResultd result;
    const fcl::Transform3d a(tf1), b(tf2);
    const auto t0 = Clock::now();
    fcl::collide(model1_.get(), a, model2_.get(), b, request, result);
    CollideTiming t;
    t.seconds = seconds_since(t0);
    t.contacts = result.numContacts();
    return t;
  }

 private:
  Mode mode_;
  std::shared_ptr<fcl::BVHModel<T>> model1_, model2_;
  double build_seconds_ = 0;
};

std::unique_ptr<BroadPhase> dispatch(BV bv, Mode mode, const Mesh& m1, const Mesh* m2) {
  return with_bv(bv, [&](auto kBV) -> std::unique_ptr<BroadPhase> {
    return std::make_unique<Impl<decltype(kBV)::value>>(mode, m1, m2);
  });
}

// ------------------------------------------------------------------------------- BV audit

double frame_error(const fcl::Matrix3d& A) {
  return (A.transpose() * A - fcl::Matrix3d::Identity()).cwiseAbs().maxCoeff();
}
double excess(const fcl::OBB<double>& b, const fcl::Vector3d& p, double& ferr) {
  ferr = std::max(ferr, frame_error(b.axis));
  const fcl::Vector3d q = b.axis.transpose() * (p - b.To);
  return (q.cwiseAbs() - b.extent).maxCoeff();
}
double excess(const fcl::RSS<double>& b, const fcl::Vector3d& p, double& ferr) {
  ferr = std::max(ferr, frame_error(b.axis));
  const fcl::Vector3d q = b.axis.transpose() * (p - b.To);
  const fcl::Vector3d c(std::clamp(q[0], 0.0, b.l[0]), std::clamp(q[1], 0.0, b.l[1]), 0.0);
  return (q - c).norm() - b.r;
}
double excess(const fcl::OBBRSS<double>& b, const fcl::Vector3d& p, double& ferr) {
  return std::max(excess(b.obb, p, ferr), excess(b.rss, p, ferr));
}
double excess(const fcl::kIOS<double>& b, const fcl::Vector3d& p, double& ferr) {
  double e = excess(b.obb, p, ferr);
  for (unsigned i = 0; i < b.num_spheres; ++i) e = std::max(e, (p - b.spheres[i].o).norm() - b.spheres[i].r);
  return e;
}
double excess(const fcl::AABB<double>& b, const fcl::Vector3d& p, double&) {
  return std::max((b.min_ - p).maxCoeff(), (p - b.max_).maxCoeff());
}
template <std::size_t N>
double excess(const fcl::KDOP<double, N>& b, const fcl::Vector3d& p, double&) {
  const fcl::KDOP<double, N> point(p);  // its slabs are the projections of p
  double e = -1e300;
  for (std::size_t i = 0; i < N / 2; ++i)
    e = std::max({e, b.dist(i) - point.dist(i), point.dist(i + N / 2) - b.dist(i + N / 2)});
  return e;
}

template <class T>
std::vector<int> audit_node(const fcl::BVHModel<T>& model, int id, BVAudit& a) {
  const auto& node = model.getBV(id);
  std::vector<int> prims;
  if (node.isLeaf()) prims.push_back(node.primitiveId());
  else {
    prims = audit_node(model, node.leftChild(), a);
    auto r = audit_node(model, node.rightChild(), a);
    prims.insert(prims.end(), r.begin(), r.end());
  }
  ++a.nodes;
  for (int t : prims)
    for (int c = 0; c < 3; ++c) {
      const double e = excess(node.bv, model.vertices[model.tri_indices[t][c]], a.max_frame_error);
      ++a.checked;
      if (e > 0) { ++a.outside; a.max_excess = std::max(a.max_excess, e); }
    }
  return prims;
}

template <BV kBV>
BVAudit audit_typed(const Mesh& m, bool world, const Rigid& tf, bool refit) {
  using T = typename BVType<kBV>::type;
  auto model = build_model<T>(m);
  if (world) {
    std::vector<fcl::Vector3d> moved;
    for (const auto& p : m.vertices) moved.push_back(tf * p);
    model->beginReplaceModel();
    model->replaceSubModel(moved);
    model->endReplaceModel(refit, /*bottomup=*/true);
  }
  BVAudit a;
  audit_node(*model, 0, a);
  return a;
}

}  // namespace

BVAudit audit_bvh(BV bv, const Mesh& m, bool world, const Rigid& tf, bool refit) {
  return with_bv(bv, [&](auto kBV) { return audit_typed<decltype(kBV)::value>(m, world, tf, refit); });
}

const char* bv_name(BV bv) {
  switch (bv) {
    case BV::OBB: return "OBB";
    case BV::RSS: return "RSS";
    case BV::OBBRSS: return "OBBRSS";
    case BV::kIOS: return "kIOS";
    case BV::AABB: return "AABB";
    case BV::KDOP16: return "KDOP16";
    case BV::KDOP18: return "KDOP18";
    case BV::KDOP24: return "KDOP24";
  }
  return "?";
}

const char* mode_name(Mode m) {
  switch (m) {
    case Mode::Default: return "default";
    case Mode::Relative: return "relative";
    case Mode::WorldRebuild: return "world-rebuild";
    case Mode::WorldRefit: return "world-refit";
  }
  return "?";
}

std::vector<BV> all_bvs() {
  return {BV::OBB, BV::RSS, BV::OBBRSS, BV::kIOS, BV::AABB, BV::KDOP16, BV::KDOP18, BV::KDOP24};
}

BV parse_bv(const std::string& s) {
  for (BV b : all_bvs())
    if (s == bv_name(b)) return b;
  throw std::invalid_argument("unknown BV '" + s + "' (OBB RSS OBBRSS kIOS AABB KDOP16 KDOP18 KDOP24)");
}

Mode parse_mode(const std::string& s) {
  for (Mode m : {Mode::Default, Mode::Relative, Mode::WorldRebuild, Mode::WorldRefit})
    if (s == mode_name(m)) return m;
  throw std::invalid_argument("unknown mode '" + s + "'");
}

Mode resolve(BV bv, Mode m) {
  const bool oriented = bv == BV::OBB || bv == BV::RSS || bv == BV::OBBRSS || bv == BV::kIOS;
  if (m == Mode::Default) {
    // fcl 0.7 collision_func_matrix: only OBB, OBBRSS and kIOS have an oriented specialisation of
    // BVHCollideImpl; RSS falls to the generic (copy + world rebuild) one like AABB and k-DOPs.
    return (bv == BV::OBB || bv == BV::OBBRSS || bv == BV::kIOS) ? Mode::Relative : Mode::WorldRebuild;
  }
  if (m == Mode::Relative && !oriented)
    throw std::invalid_argument(std::string("mode relative needs an oriented BV, not ") + bv_name(bv));
  return m;
}

std::unique_ptr<BroadPhase> make_broad_phase(BV bv, Mode mode, const Mesh& m1, const Mesh& m2) {
  return dispatch(bv, resolve(bv, mode), m1, &m2);
}

std::unique_ptr<BroadPhase> make_self_broad_phase(BV bv, const Mesh& m) {
  return dispatch(bv, Mode::WorldRebuild, m, nullptr);
}

bool fcl_triangle_test(const Vec3& p1, const Vec3& p2, const Vec3& p3,
                       const Vec3& q1, const Vec3& q2, const Vec3& q3) {
  return fcl::detail::Intersect<double>::intersect_Triangle(p1, p2, p3, q1, q2, q3);
}

}  // namespace tritri::scenes
