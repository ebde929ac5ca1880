// The scene workload: the triangle pairs a collision query really asks about. Each value is a
// scene and a bounding-volume type ("knot_torus/bv:OBB"; a bare scene name means bv:OBB, the box
// of RAPID, where Möller timed his test). Its pools come from cases/scenes: every frame's
// candidate pairs, the leaf pairs FCL's BVH traversal lets through, in traversal order, labelled
// by the oracle. Three pools per value, each answering one query of the scene:
//   scene:V           all candidates in traversal order: the "all contacts" query (overlap
//                     level); for a self scene the "intersection curve" query (segment level);
//   scene-shuffled:V  the same pairs shuffled once: what the order itself is worth;
//   scene-any:V       the "any contact" query (not for self scenes): per frame, the candidates
//                     up to and including the first intersecting one, where the query stops;
//                     a frame with no contact contributes all its candidates (the query has to
//                     test them all to say so). Timing that prefix stream through the batch
//                     interface is timing exactly the pairs an early-exit loop would test; it
//                     leaves out only the exit branch itself, one per frame.
// Each pool is timed at the one level its query needs (Pool::query: overlap, or segment for a
// self scene), an algorithm that does not answer it at the lowest level asked for above it.
// Beside the pools, the context key "scene V" records FCL's own times for the same query
// (traversal only, its triangle test, fcl::collide), from which the report derives the share of
// a whole query spent in the triangle test.
#include "harness/bench/workload.hpp"
#include "cases/scenes/stream.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace tritri::bench {
namespace {

// Moderate pools: ./scripts/run times the default set on 2 cores within its budget.
constexpr int kFrames = 8;
constexpr int kQuickFrames = 4;

const std::vector<std::string> kDefault = {
    "approach/bv:OBB",       "approach/bv:AABB",   "graze/bv:OBB",         "graze/bv:AABB",
    "box_stack/bv:OBB",      "box_stack/bv:AABB",  "box_stack/bv:KDOP24",  "box_stack/bv:RSS",
    "rotate_through/bv:OBB", "rotate_through/bv:AABB", "spindle_self/bv:OBB", "spindle_self/bv:AABB",
    "knot_torus/bv:OBB",     "knot_torus/bv:AABB", "knot_torus/bv:KDOP24", "knot_torus/bv:kIOS",
    "herd/bv:OBB",           "herd/bv:AABB"};

std::string fixed3(double x) {
  char b[64];
  std::snprintf(b, sizeof b, "%.4f", x);
  return b;
}

class SceneWorkload : public Workload {
 public:
  SceneWorkload() : Workload("scene", "scene[:NAME[/bv:TYPE]]") {}
  std::vector<std::string> default_values() const override { return kDefault; }
  // Scenes read meshes and run FCL before anything is timed: only when asked for.
  bool in_default_set(const std::vector<const Algorithm*>&) const override { return false; }

  std::string parse_value(const std::string& value) const override {
    const auto slash = value.find("/bv:");
    const std::string name = value.substr(0, slash), bv = slash == std::string::npos ? "OBB" : value.substr(slash + 4);
    bool known = false;
    for (const auto& s : scenes::scene_catalogue()) known = known || (s.name == name && !s.user_mesh);
    const auto types = scenes::bv_types();
    if (!known || std::find(types.begin(), types.end(), bv) == types.end()) {
      std::string names;
      for (const auto& s : scenes::scene_catalogue())
        if (!s.user_mesh) names += (names.empty() ? "" : " ") + s.name;
      throw std::invalid_argument("scene: wants NAME or NAME/bv:TYPE, NAME one of " + names +
                                  ", TYPE one of OBB RSS OBBRSS kIOS AABB KDOP16 KDOP18 KDOP24 (tritri scene --list)");
    }
    return name + "/bv:" + bv;
  }

  WorkloadPools build(const std::vector<std::string>& values, const WorkloadInput& input) const override {
    WorkloadPools built;
    for (const auto& value : values) {
      const auto slash = value.find("/bv:");
      scenes::StreamOptions o;
      o.bv = value.substr(slash + 4);
      o.frames = input.quick ? kQuickFrames : kFrames;
      o.small = input.quick;
      o.time_fcl = true;
      scenes::SceneStream s;
      try {
        s = scenes::scene_stream(value.substr(0, slash), o);
      } catch (const std::runtime_error& e) {  // CGAL's meshes missing, say: skip, and say so
        std::fprintf(stderr, "bench: scene:%s skipped: %s\n", value.c_str(), e.what());
        built.context.emplace_back("scene " + value, std::string("skipped: ") + e.what());
        continue;
      }
      add_pools(value, s, input, built);
    }
    return built;
  }

 private:
  // The stream's frames as [begin, end) row ranges, in order.
  static std::vector<std::pair<std::size_t, std::size_t>> frame_ranges(const scenes::SceneStream& s) {
    std::vector<std::pair<std::size_t, std::size_t>> ranges;
    for (std::size_t begin = 0; begin < s.pairs.size();) {
      std::size_t end = begin;
      while (end < s.pairs.size() && s.pairs[end].frame == s.pairs[begin].frame) ++end;
      ranges.emplace_back(begin, end);
      begin = end;
    }
    return ranges;
  }

  // Whole frames up to the pool size, spread evenly over the motion (the n frames at the middles
  // of n equal parts of it, for the largest n that fits; at least one): taking the first frames
  // instead would time only the start of a scene whose contacts come late.
  static std::vector<std::pair<std::size_t, std::size_t>> frames_in_pool(const scenes::SceneStream& s,
                                                                         std::size_t pool_size) {
    const auto ranges = frame_ranges(s);
    const std::size_t f = ranges.size();
    for (std::size_t n = f; n >= 1; --n) {
      std::vector<std::pair<std::size_t, std::size_t>> chosen;
      std::size_t rows = 0;
      for (std::size_t i = 0; i < n; ++i) {
        chosen.push_back(ranges[(2 * i + 1) * f / (2 * n)]);
        rows += chosen.back().second - chosen.back().first;
      }
      if (rows <= pool_size || n == 1) return chosen;
    }
    return {};
  }

  static void add_pools(const std::string& value, const scenes::SceneStream& s, const WorkloadInput& input,
                        WorkloadPools& built) {
    const auto chosen = frames_in_pool(s, input.pool.size);
    const int frames = static_cast<int>(chosen.size());
    std::vector<TrianglePair> pairs;
    std::vector<std::size_t> frame_end;  // in `pairs`
    for (const auto& [begin, end] : chosen) {
      for (std::size_t r = begin; r < end; ++r) pairs.push_back(s.pairs[r].pair);
      frame_end.push_back(pairs.size());
    }
    const auto truth = label_pairs(pairs);
    std::vector<std::size_t> all, any;
    for (std::size_t r = 0; r < pairs.size(); ++r) all.push_back(r);
    // any contact: each frame's prefix up to its first intersecting pair
    for (std::size_t k = 0, r = 0; k < frame_end.size(); r = frame_end[k++]) {
      for (std::size_t q = r; q < frame_end[k]; ++q) {
        any.push_back(q);
        if (truth[q].overlap) break;
      }
    }
    const std::uint64_t seed = sub_seed(input.pool.seed, "scene:" + value);
    Pool ordered = pool_of_rows("scene", value, seed, pairs, truth, all);
    ordered.query = s.self ? Level::segment : Level::overlap;
    Pool shuffled = ordered;
    shuffled.workload = "scene-shuffled";
    Rng rng(seed);
    std::vector<std::size_t> perm(shuffled.pairs.size());
    for (std::size_t i = 0; i < perm.size(); ++i) perm[i] = i;
    rng.shuffle(perm);
    for (std::size_t i = 0; i < perm.size(); ++i) {
      shuffled.pairs[i] = ordered.pairs[perm[i]];
      shuffled.truth[i] = ordered.truth[perm[i]];
    }
    built.context.emplace_back("scene " + value, describe(s, frames, ordered, any.size()));
    if (ordered.pairs.empty()) return;
    built.pools.push_back(std::move(ordered));
    built.pools.push_back(std::move(shuffled));
    if (!s.self) {
      Pool first = pool_of_rows("scene-any", value, seed, pairs, truth, any);
      first.query = Level::overlap;
      if (!first.pairs.empty()) built.pools.push_back(std::move(first));
    }
  }

  // key=value text the report parses: what the scene is, and FCL's own times per frame (ms).
  static std::string describe(const scenes::SceneStream& s, int frames, const Pool& p, std::size_t any_pairs) {
    const auto& t = s.times;
    return "scene=" + s.scene + " bv=" + s.bv + " mode=" + s.mode + " self=" + (s.self ? "1" : "0") +
           " seed=" + std::to_string(s.seed) + " frames=" + std::to_string(frames) +
           " candidates=" + std::to_string(p.size()) + " intersecting=" + std::to_string(p.intersecting()) +
           " any_pairs=" + std::to_string(any_pairs) + " dropped_adjacent=" + std::to_string(s.dropped_adjacent) +
           " setup_ms=" + fixed3(t.setup_ms) + " traverse_ms=" + fixed3(t.traverse_ms) +
           " fcl_triangle_ms=" + fixed3(t.fcl_triangle_ms) + " collide_all_ms=" + fixed3(t.collide_all_ms) +
           " collide_any_ms=" + fixed3(t.collide_any_ms) + " contacts=" + fixed3(t.contacts) +
           " timed_frames=" + std::to_string(s.frames);
  }
};

}  // namespace

std::unique_ptr<Workload> make_scene_workload() { return std::make_unique<SceneWorkload>(); }

}  // namespace tritri::bench
