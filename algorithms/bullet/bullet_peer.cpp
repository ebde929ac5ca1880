// Bullet's headers are included here only; the definitions that select its precision come with
// the library (CMakeLists.txt), so this file and the linked build agree.
#include "algorithms/bullet/bullet_peer.hpp"

#include "tritri/algorithm.hpp"

#include <BulletCollision/Gimpact/btTriangleShapeEx.h>
#include <BulletCollision/Gimpact/gim_tri_collision.h>

namespace tritri {
namespace bullet_peer {
namespace {

btVector3 to_bt(const Vec3<double>& v) { return {btScalar(v[0]), btScalar(v[1]), btScalar(v[2])}; }

void load(btPrimitiveTriangle& t, const Triangle& v, double margin) {
  for (int i = 0; i < 3; ++i) t.m_vertices[i] = to_bt(v[i]);
  t.m_margin = btScalar(margin);
  t.buildTriPlane();
}

}  // namespace

int scalar_bytes() { return int(sizeof(btScalar)); }

bool gimpact_overlap(const TrianglePair& pair, double margin) {
  btPrimitiveTriangle a, b;
  load(a, pair.t1, margin);
  load(b, pair.t2, margin);
  if (!a.overlap_test_conservative(b)) return false;
  GIM_TRIANGLE_CONTACT contact;
  return a.find_triangle_collision_clip_method(b, contact);
}

bool gim_triangle_overlap(const TrianglePair& pair, double margin) {
  GIM_TRIANGLE a, b;
  for (int i = 0; i < 3; ++i) {
    a.m_vertices[i] = to_bt(pair.t1[i]);
    b.m_vertices[i] = to_bt(pair.t2[i]);
  }
  a.m_margin = b.m_margin = btScalar(margin);
  GIM_TRIANGLE_CONTACT_DATA contact;
  return a.collide_triangle(b, contact);
}

}  // namespace bullet_peer

namespace {
const char kCitation[] =
    "E. Coumans et al. Bullet Physics SDK 3.24 (libbullet-dev, float build), GImpact by F. Leon: "
    "BulletCollision/Gimpact/btTriangleShapeEx.h and gim_tri_collision.h";
const char kMarginQuantity[] =
    "Euclidean distance in front of the other triangle's plane, against the sum of both m_margin";
}  // namespace

void register_bullet(Registry& registry) {
  Algorithm gimpact({.name = "bullet-gimpact",
                     .citation = kCitation,
                     .summary = "Bullet 3.24 btPrimitiveTriangle overlap_test_conservative + "
                                "find_triangle_collision_clip_method, margin 0.01 each (as shipped), float",
                     .tolerance = {.value = 0.02, .quantity = kMarginQuantity, .relative = false}});
  gimpact.set_batch<Level::overlap>(Scalar::double_, overlap_batch<&bullet_peer::gimpact_default>);
  registry.add(std::move(gimpact));

  Algorithm m0({.name = "bullet-gimpact-m0",
                .citation = kCitation,
                .summary = "bullet-gimpact with setMargin(0): no margin, the clip's FLT_EPSILON slack only",
                .tolerance = {.value = 1.1920929e-07,
                              .quantity = "distance outside an edge plane in the clip (FLT_EPSILON)",
                              .relative = false}});
  m0.set_batch<Level::overlap>(Scalar::double_, overlap_batch<&bullet_peer::gimpact_margin0>);
  registry.add(std::move(m0));

  Algorithm gim({.name = "bullet-gim-triangle",
                 .citation = kCitation,
                 .summary = "Bullet 3.24 GIM_TRIANGLE::collide_triangle, margin 0.1 each (its default), float",
                 .tolerance = {.value = 0.2, .quantity = kMarginQuantity, .relative = false}});
  gim.set_batch<Level::overlap>(Scalar::double_, overlap_batch<&bullet_peer::gim_triangle_default>);
  registry.add(std::move(gim));
}

}  // namespace tritri
