#include "cases/scenes/stream.hpp"

#include "cases/scenes/broadphase.hpp"
#include "cases/scenes/oracle.hpp"
#include "cases/scenes/scenes.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace tritri::scenes {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

template <class F>
double fastest(int reps, F&& f) {
  double best = 1e300;
  for (int r = 0; r < std::max(1, reps); ++r) best = std::min(best, f());
  return best;
}

TriangleT<double> triangle(const std::vector<Vec3>& v, const Face& f) {
  return {{v[f[0]], v[f[1]], v[f[2]]}};
}

double fcl_tests(const std::vector<StreamPair>& pairs, std::size_t from, int reps) {
  return fastest(reps, [&] {
    std::size_t hits = 0;
    const auto t0 = Clock::now();
    for (std::size_t n = from; n < pairs.size(); ++n) {
      const auto& p = pairs[n].pair;
      hits += fcl_triangle_test(p.t1[0], p.t1[1], p.t1[2], p.t2[0], p.t2[1], p.t2[2]);
    }
    const double s = since(t0);
    return hits == SIZE_MAX ? 0.0 : s;  // uses hits, so the loop is not optimised away
  });
}

void self_frame(const Scene& s, int k, BV bv, const StreamOptions& o, SceneStream& out) {
  const auto mesh = s.mesh_at(0, k);
  const auto t0 = Clock::now();
  auto bp = make_self_broad_phase(bv, *mesh);
  const double build = since(t0);
  std::vector<Candidate> cand;
  TraversalStats st;
  const double trav = fastest(o.time_fcl ? o.repetitions : 1, [&] {
    cand.clear();
    st = bp->collect_self(cand);
    return st.traverse_seconds;
  });
  const std::size_t from = out.pairs.size();
  for (const auto& c : cand) {
    const Face& f = mesh->faces[c.a];
    const Face& g = mesh->faces[c.b];
    const int shared = shared_vertices(f, g);
    if (shared > 0 && !o.adjacent) {
      ++out.dropped_adjacent;
      continue;
    }
    out.pairs.push_back({{triangle(mesh->vertices, f), triangle(mesh->vertices, g)}, k, 0, 0, c.a, c.b, shared});
  }
  if (!o.time_fcl) return;
  out.times.setup_ms += 1e3 * build;
  out.times.traverse_ms += 1e3 * trav;
  out.times.fcl_triangle_ms += 1e3 * fcl_tests(out.pairs, from, o.repetitions);
}

void pair_frame(const Scene& s, int k, const StreamOptions& o,
                std::vector<std::unique_ptr<BroadPhase>>& bps, SceneStream& out) {
  const auto body_pairs = s.body_pairs();
  for (std::size_t b = 0; b < body_pairs.size(); ++b) {
    const auto [i, j] = body_pairs[b];
    const Rigid ti = s.transform_at(i, k), tj = s.transform_at(j, k);
    std::vector<Candidate> cand;
    TraversalStats st;
    double setup = 1e300;
    const double trav = fastest(o.time_fcl ? o.repetitions : 1, [&] {
      cand.clear();
      st = bps[b]->collect(ti, tj, cand);
      setup = std::min(setup, st.setup_seconds);
      return st.traverse_seconds;
    });
    const auto vi = transformed(*s.bodies[i].mesh, ti), vj = transformed(*s.bodies[j].mesh, tj);
    const std::size_t from = out.pairs.size();
    for (const auto& c : cand)
      out.pairs.push_back({{triangle(vi, s.bodies[i].mesh->faces[c.a]), triangle(vj, s.bodies[j].mesh->faces[c.b])},
                           k, i, j, c.a, c.b, 0});
    if (!o.time_fcl) continue;
    CollideTiming all;
    out.times.setup_ms += 1e3 * setup;
    out.times.traverse_ms += 1e3 * trav;
    out.times.fcl_triangle_ms += 1e3 * fcl_tests(out.pairs, from, o.repetitions);
    out.times.collide_any_ms += 1e3 * fastest(o.repetitions, [&] { return bps[b]->fcl_collide(ti, tj, 1).seconds; });
    out.times.collide_all_ms += 1e3 * fastest(o.repetitions, [&] {
      all = bps[b]->fcl_collide(ti, tj, std::size_t(1) << 40);
      return all.seconds;
    });
    out.times.contacts += double(all.contacts);
  }
}

}  // namespace

SceneStream scene_stream(const std::string& name, const StreamOptions& o) {
  SceneConfig config;
  config.size = o.small ? Size::Small : Size::Full;
  config.frames = std::max(1, o.frames);
  config.user_mesh = o.user_mesh;
  const BV bv = parse_bv(o.bv);
  const Scene s = make_scene(name, config);
  SceneStream out;
  out.scene = s.name;
  out.description = s.description;
  out.bv = bv_name(bv);
  out.mode = s.self ? "self" : mode_name(resolve(bv, Mode::Default));
  out.seed = s.seed;
  out.frames = s.frames;
  out.self = s.self;
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    out.bodies += (b ? " + " : "") + s.bodies[b].mesh->name + " " + std::to_string(s.bodies[b].mesh->faces.size());
  std::vector<std::unique_ptr<BroadPhase>> bps;
  if (!s.self)
    for (auto [i, j] : s.body_pairs()) bps.push_back(make_broad_phase(bv, Mode::Default, *s.bodies[i].mesh, *s.bodies[j].mesh));
  for (int k = 0; k < s.frames; ++k) {
    if (s.self) self_frame(s, k, bv, o, out);
    else pair_frame(s, k, o, bps, out);
  }
  const double F = s.frames;
  for (double* t : {&out.times.setup_ms, &out.times.traverse_ms, &out.times.fcl_triangle_ms,
                    &out.times.collide_all_ms, &out.times.collide_any_ms, &out.times.contacts})
    *t /= F;
  return out;
}

std::vector<std::vector<TriangleT<double>>> scene_bodies(const std::string& name, const StreamOptions& o,
                                                         int frame, std::size_t max_per_body) {
  SceneConfig config;
  config.size = o.small ? Size::Small : Size::Full;
  config.frames = std::max(1, o.frames);
  config.user_mesh = o.user_mesh;
  const Scene s = make_scene(name, config);
  const int k = std::clamp(frame, 0, s.frames - 1);
  std::vector<std::vector<TriangleT<double>>> out;
  for (int b = 0; b < int(s.bodies.size()); ++b) {
    const auto mesh = s.mesh_at(b, k);
    const auto v = transformed(*mesh, s.transform_at(b, k));
    const std::size_t step = std::max<std::size_t>(1, (mesh->faces.size() + max_per_body - 1) / std::max<std::size_t>(1, max_per_body));
    out.emplace_back();
    for (std::size_t f = 0; f < mesh->faces.size(); f += step) out.back().push_back(triangle(v, mesh->faces[f]));
  }
  return out;
}

std::vector<SceneInfo> scene_catalogue() {
  std::vector<SceneInfo> all;
  SceneConfig small;
  small.size = Size::Small;
  small.frames = 2;
  for (const auto& name : scene_names(Size::Full)) {
    SceneInfo info{name, "", 0, false, needs_cgal_data(name), false};
    try {
      const Scene s = make_scene(name, small);  // real meshes are read whatever the size
      info.description = s.description;
      info.seed = s.seed;
      info.self = s.self;
    } catch (const std::exception& e) {
      info.description = std::string("(unavailable: ") + e.what() + ")";
    }
    all.push_back(info);
  }
  all.push_back({"mesh_self", "the given mesh (--mesh FILE) against itself, one frame", 31, true, false, true});
  all.push_back({"mesh_sphere", "a sphere flies through the given mesh (--mesh FILE)", 32, false, false, true});
  return all;
}

std::vector<std::string> bv_types() {
  std::vector<std::string> v;
  for (BV b : all_bvs()) v.push_back(bv_name(b));
  return v;
}

bool bv_complete(const std::string& bv) { return bv != "RSS" && bv != "kIOS"; }

}  // namespace tritri::scenes
