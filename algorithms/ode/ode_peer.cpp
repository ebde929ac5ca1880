// ODE's headers are included here only.
#include "algorithms/ode/ode_peer.hpp"

#include "tritri/algorithm.hpp"

#include <ode/ode.h>

namespace tritri {
namespace ode_peer {
namespace {

// Each mesh lists its one triangle twice (a single-triangle OPCODE model crashes dCollide).
const int kIndices[6] = {0, 1, 2, 0, 1, 2};
constexpr int kIndexCount = 6;

// ODE keeps per-thread data: every thread that collides must allocate it, once.
void init_thread() {
  thread_local const bool done = [] {
    dInitODE2(0);
    dAllocateODEDataForThread(dAllocateMaskAll);
    return true;
  }();
  (void)done;
}

void copy(const Triangle& t, double* out) {
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) out[3 * i + k] = t[i][k];
}

dGeomID make_geom(dTriMeshDataID data, const double* vertices) {
  dGeomTriMeshDataBuildDouble(data, vertices, 3 * sizeof(double), 3, kIndices, kIndexCount, 3 * sizeof(int));
  return dCreateTriMesh(nullptr, data, nullptr, nullptr, nullptr);
}

bool any_contact(dGeomID a, dGeomID b) {
  dContactGeom contact;
  return dCollide(a, b, 1 | CONTACTS_UNIMPORTANT, &contact, sizeof(dContactGeom)) > 0;
}

// Two geoms over buffers this object owns; ODE keeps pointers to the buffers, not copies.
class PrebuiltPair {
 public:
  PrebuiltPair() {
    init_thread();
    data_a_ = dGeomTriMeshDataCreate();
    data_b_ = dGeomTriMeshDataCreate();
    geom_a_ = make_geom(data_a_, va_);
    geom_b_ = make_geom(data_b_, vb_);
  }
  ~PrebuiltPair() {
    dGeomDestroy(geom_a_);
    dGeomDestroy(geom_b_);
    dGeomTriMeshDataDestroy(data_a_);
    dGeomTriMeshDataDestroy(data_b_);
  }
  PrebuiltPair(const PrebuiltPair&) = delete;
  PrebuiltPair& operator=(const PrebuiltPair&) = delete;

  bool collide(const TrianglePair& pair) {
    copy(pair.t1, va_);
    copy(pair.t2, vb_);
    dGeomTriMeshDataUpdate(data_a_);
    dGeomTriMeshDataUpdate(data_b_);
    return any_contact(geom_a_, geom_b_);
  }

 private:
  // Any non-degenerate start: overwritten before every query.
  double va_[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  double vb_[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  dTriMeshDataID data_a_ = nullptr, data_b_ = nullptr;
  dGeomID geom_a_ = nullptr, geom_b_ = nullptr;
};

}  // namespace

bool overlap(const TrianglePair& pair) {
  thread_local PrebuiltPair geoms;
  return geoms.collide(pair);
}

bool overlap_rebuild(const TrianglePair& pair) {
  init_thread();
  double va[9], vb[9];
  copy(pair.t1, va);
  copy(pair.t2, vb);
  dTriMeshDataID da = dGeomTriMeshDataCreate();
  dTriMeshDataID db = dGeomTriMeshDataCreate();
  dGeomID ga = make_geom(da, va);
  dGeomID gb = make_geom(db, vb);
  const bool hit = any_contact(ga, gb);
  dGeomDestroy(ga);
  dGeomDestroy(gb);
  dGeomTriMeshDataDestroy(da);
  dGeomTriMeshDataDestroy(db);
  return hit;
}

}  // namespace ode_peer

void register_ode(Registry& registry) {
  Algorithm a({.name = "ode",
               .citation = "R. Smith et al. Open Dynamics Engine 0.16 (libode-dev, double, OPCODE): dCollide on "
                           "two one-triangle trimesh geoms (ode/collision_trimesh.h)",
               .summary = "ODE 0.16 trimesh-trimesh dCollide: OPCODE's float Moller gate, then a double "
                          "clip with one-sided depth >= 0; geoms pre-built, vertices updated per pair",
               .tolerance = {.value = 1e-6,
                             .quantity = "|N.X+d| in float against max(|d|, min(|N|^2,|X|^2)) (OPCODE's "
                                         "gate); then 1e-8 absolute edge-plane slack in the clip",
                             .relative = true}});
  a.set_batch<Level::overlap>(Scalar::double_, overlap_batch<&ode_peer::overlap>);
  a.stages.push_back({.name = "rebuild", .run = stage_run<&ode_peer::overlap_rebuild>});
  a.stages.push_back({.name = "update", .run = stage_run<&ode_peer::overlap>});
  registry.add(std::move(a));
}

}  // namespace tritri
