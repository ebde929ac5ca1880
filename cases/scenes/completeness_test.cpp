// The completeness test of the scene broad phase: no truly intersecting pair is missing from the
// recorded candidates.
//
// For every small scene, frame, body pair, BV type and transform mode: every pair of triangles
// that truly intersects (closed triangles, exact CGAL Epeck test; within one mesh, the CGAL
// self-intersection rule of oracle.hpp) must be among the candidates FCL's traversal recorded.
// Also checked: no candidate twice, no triangle paired with itself in a self query. Reported
// beside it: how the candidates compare with all pairs whose axis-aligned boxes overlap.
//
//   completeness_test [--full SCENE] [--frames F] [--bv B]...
// Without --full: all Size::Small scenes. With --full: that Full-size scene (e.g. knot_torus).
// Ends with "N passed, N failed" (one test per scene x BV x mode); exit status 1 on a failure.
// Misses in configurations with a known FCL 0.7 defect (RSS, kIOS, world-refit) print "known"
// and count as passed unless --strict.
#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <string>

#include "cases/scenes/broadphase.hpp"
#include "cases/scenes/oracle.hpp"
#include "cases/scenes/scenes.hpp"

using namespace tritri::scenes;

namespace {

using PairList = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

struct Tally {
  std::size_t cand = 0, dup = 0, self_pairs = 0, truth = 0, missing = 0, aabb = 0, cand_not_aabb = 0,
              aabb_not_cand = 0;
  std::vector<std::string> examples;
  std::map<std::string, std::size_t> missing_kinds;
};

template <class Kind>
void compare(const std::vector<Candidate>& cand_in, bool self, const PairList& aabb, const PairList& truth,
             Tally& t, const std::string& where, Kind&& kind) {
  PairList cand;
  cand.reserve(cand_in.size());
  for (const auto& c : cand_in) {
    auto p = std::make_pair(c.a, c.b);
    if (self) {
      if (p.first == p.second) ++t.self_pairs;
      if (p.first > p.second) std::swap(p.first, p.second);
    }
    cand.push_back(p);
  }
  std::sort(cand.begin(), cand.end());
  const auto before = cand.size();
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  t.dup += before - cand.size();
  t.cand += before;
  t.truth += truth.size();
  t.aabb += aabb.size();
  PairList miss;
  std::set_difference(truth.begin(), truth.end(), cand.begin(), cand.end(), std::back_inserter(miss));
  t.missing += miss.size();
  for (auto [a, b] : miss) ++t.missing_kinds[kind(a, b)];
  for (std::size_t m = 0; m < miss.size() && t.examples.size() < 5; ++m)
    t.examples.push_back(where + " misses (" + std::to_string(miss[m].first) + ", " + std::to_string(miss[m].second) + ")");
  PairList d1, d2;
  std::set_difference(cand.begin(), cand.end(), aabb.begin(), aabb.end(), std::back_inserter(d1));
  std::set_difference(aabb.begin(), aabb.end(), cand.begin(), cand.end(), std::back_inserter(d2));
  t.cand_not_aabb += d1.size();
  t.aabb_not_cand += d2.size();
}

// Truth and box pairs per frame and body pair of a scene, computed once for every BV and mode.
struct Item { int k, i, j; std::shared_ptr<const Mesh> mi, mj; Rigid ti, tj; PairList aabb, truth; };

std::vector<Item> scene_items(const Scene& s) {
  std::vector<Item> items;
  for (int k = 0; k < s.frames; ++k)
    for (auto [i, j] : s.body_pairs()) {
      Item it{k, i, j, s.mesh_at(i, k), s.mesh_at(j, k), s.transform_at(i, k), s.transform_at(j, k), {}, {}};
      const auto Vi = transformed(*it.mi, it.ti), Vj = s.self ? Vi : transformed(*it.mj, it.tj);
      it.aabb = overlapping_box_pairs(Vi, it.mi->faces, Vj, it.mj->faces, s.self);
      for (auto [a, b] : it.aabb) {
        const auto& f = it.mi->faces[a];
        const auto& g = it.mj->faces[b];
        const bool hit = s.self ? self_pair_intersects(Vi, f, g)
                                : exact_intersect(Vi[f[0]], Vi[f[1]], Vi[f[2]], Vj[g[0]], Vj[g[1]], Vj[g[2]]);
        if (hit) it.truth.emplace_back(a, b);
      }
      items.push_back(std::move(it));
    }
  return items;
}

}  // namespace

int main(int argc, char** argv) {
  std::string full;
  int frames = 8;
  bool strict = false;
  std::vector<BV> bvs;
  for (int i = 1; i < argc; ++i) {
    std::string s = argv[i];
    if (s == "--full" && i + 1 < argc) full = argv[++i];
    else if (s == "--frames" && i + 1 < argc) frames = std::stoi(argv[++i]);
    else if (s == "--bv" && i + 1 < argc) bvs.push_back(parse_bv(argv[++i]));
    else if (s == "--strict") strict = true;
    else { std::fprintf(stderr, "usage: completeness_test [--full SCENE] [--frames F] [--bv B]... [--strict]\n"); return 2; }
  }
  if (bvs.empty()) bvs = all_bvs();
  SceneConfig cfg;
  cfg.size = full.empty() ? Size::Small : Size::Full;
  cfg.frames = frames;
  const auto names = full.empty() ? scene_names(Size::Small) : std::vector<std::string>{full};

  int passed = 0, failed = 0, known_count = 0;
  std::printf("%-14s %-7s %-13s %9s %9s %9s %7s %9s %9s %5s  %s\n", "scene", "bv", "mode", "cand", "aabb", "truth",
              "missing", "cand-aabb", "aabb-cand", "dup", "result");
  for (const auto& name : names) {
    const Scene s = make_scene(name, cfg);
    const std::vector<Item> items = scene_items(s);
    for (BV bv : bvs) {
      std::vector<Mode> modes;
      if (s.self) modes = {Mode::WorldRebuild};  // self: one tree in its own frame
      else if (bv == BV::OBB || bv == BV::RSS || bv == BV::OBBRSS || bv == BV::kIOS)
        modes = {Mode::Relative, Mode::WorldRebuild, Mode::WorldRefit};
      else modes = {Mode::WorldRebuild, Mode::WorldRefit};
      for (Mode mode : modes) {
        Tally t;
        for (const auto& it : items) {
          std::vector<Candidate> cand;
          if (s.self) make_self_broad_phase(bv, *it.mi)->collect_self(cand);
          else make_broad_phase(bv, mode, *it.mi, *it.mj)->collect(it.ti, it.tj, cand);
          const auto Vi = transformed(*it.mi, it.ti), Vj = s.self ? Vi : transformed(*it.mj, it.tj);
          auto kind = [&](std::uint32_t a, std::uint32_t b) {
            const auto& f = it.mi->faces[a];
            const auto& g = it.mj->faces[b];
            std::string k = contact_kind(Vi[f[0]], Vi[f[1]], Vi[f[2]], Vj[g[0]], Vj[g[1]], Vj[g[2]]);
            if (s.self) k += " shared=" + std::to_string(shared_vertices(f, g));
            return k;
          };
          compare(cand, s.self, it.aabb, it.truth, t,
                  "frame " + std::to_string(it.k) + " bodies " + std::to_string(it.i) + "-" + std::to_string(it.j),
                  kind);
        }
        // AABB in the world frame is exact: its candidates are exactly the box-overlapping pairs.
        const bool aabb_exact = bv != BV::AABB || mode == Mode::WorldRefit || s.self ||
                                (t.cand_not_aabb == 0 && t.aabb_not_cand == 0);
        const bool ok = t.missing == 0 && t.dup == 0 && t.self_pairs == 0 && aabb_exact;
        // FCL 0.7 defects (cases/scenes/README.md): RSS and kIOS overlap tests drop exact touching
        // contacts; bottom-up refit merges (RSS::operator+, OBB merge_smalldist) are not
        // conservative. Misses there are reported as "known" and, unless --strict, not failures.
        const bool known = !ok && t.dup == 0 && t.self_pairs == 0 && aabb_exact &&
                           (bv == BV::RSS || bv == BV::kIOS || mode == Mode::WorldRefit);
        ((ok || (known && !strict)) ? passed : failed)++;
        if (known) ++known_count;
        std::printf("%-14s %-7s %-13s %9zu %9zu %9zu %7zu %9zu %9zu %5zu  %s\n", s.name.c_str(), bv_name(bv),
                    s.self ? "self" : mode_name(mode), t.cand, t.aabb, t.truth, t.missing, t.cand_not_aabb,
                    t.aabb_not_cand, t.dup, ok ? "ok" : known ? "known" : "FAIL");
        for (const auto& e : t.examples) std::printf("    %s\n", e.c_str());
        if (!t.missing_kinds.empty()) {
          std::printf("    missed contacts by kind:");
          for (const auto& [k, n] : t.missing_kinds) std::printf("  %s: %zu", k.c_str(), n);
          std::printf("\n");
        }
        std::fflush(stdout);
      }
    }
  }
  if (known_count)
    std::printf("%d configuration(s) miss contacts through known FCL 0.7 defects (%s)\n", known_count,
                strict ? "counted as failures: --strict" : "not counted as failures; --strict to count them");
  std::printf("%d passed, %d failed\n", passed, failed);
  return failed ? 1 : 0;
}
