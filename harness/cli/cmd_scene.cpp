// `tritri scene`: a scene's candidate pairs as case files, for `tritri check` or any other tool.
#include "harness/cli/args.hpp"
#include "cases/casefile.hpp"
#include "cases/scenes/stream.hpp"
#include "cases/util/atomic_file.hpp"
#include "harness/cli/commands.hpp"

#include <filesystem>
#include <iostream>

namespace tritri::cli {
namespace {

const char* const kHelp =
    "usage: tritri scene --list\n"
    "       tritri scene NAME --out DIR [--bv TYPE] [--frames F] [--small] [--mesh FILE] [--adjacent]\n\n"
    "A scene is meshes in motion over F frames; its candidate pairs are the triangle pairs whose\n"
    "leaf bounding volumes FCL's BVH traversal finds overlapping: the pairs a collision query hands\n"
    "to its triangle test, in traversal order. This writes them, in world coordinates, to\n"
    "DIR/NAME.TYPE.cases (atomically), one case per pair, labelled family=scene:NAME, bv=TYPE,\n"
    "frame=K, bodies=I-J, tri1=, tri2= (face indices) and order= (position in its frame's\n"
    "traversal); `tritri check DIR/NAME.TYPE.cases` then judges every algorithm on them.\n\n"
    "  --list         the scenes: name, seed, whether they need CGAL's meshes (libcgal-demo) or a\n"
    "                 mesh of yours, and what happens in them\n"
    "  --bv TYPE      OBB (default), RSS, OBBRSS, kIOS, AABB, KDOP16, KDOP18, KDOP24. RSS and kIOS\n"
    "                 miss exactly touching pairs in FCL 0.7 (cases/scenes/README.md)\n"
    "  --frames F     frames of a moving scene (default 16)\n"
    "  --small        the procedural scenes at a few hundred triangles per body\n"
    "  --mesh FILE    your mesh (OFF, OBJ, PLY or STL; polygons are fanned) for the scenes\n"
    "                 mesh_self (it against itself) and mesh_sphere (a sphere flies through it)\n"
    "  --picture FILE also write FILE (JSON): each body's triangles at the middle frame, at most\n"
    "                 1500 per body, for the report's pictures\n"
    "  --adjacent     self scenes: keep the pairs of faces sharing a vertex (left out by default:\n"
    "                 they always touch), labelled shared=1 or 2\n\n"
    "Same name, options and seed: the same pairs, bit for bit. Exit status 2 on a bad argument, an\n"
    "unknown scene, or a mesh file that cannot be read (the message names file and line).\n";

int list_scenes() {
  for (const auto& s : scenes::scene_catalogue()) {
    std::cout << s.name << "  (seed " << s.seed << (s.self ? ", self" : "")
              << (s.cgal_data ? ", CGAL meshes" : "") << (s.user_mesh ? ", needs --mesh" : "") << ")\n  "
              << s.description << '\n';
  }
  return kOk;
}

Case to_case(const scenes::SceneStream& s, const scenes::StreamPair& p, std::size_t order) {
  Case c;
  const std::string bodies = std::to_string(p.body1) + "-" + std::to_string(p.body2);
  c.name = s.scene + "." + s.bv + ".f" + std::to_string(p.frame) + ".b" + bodies + "." + std::to_string(order);
  c.pair = p.pair;
  c.labels = {{"family", "scene:" + s.scene}, {"bv", s.bv},       {"frame", std::to_string(p.frame)},
              {"bodies", bodies},             {"tri1", std::to_string(p.tri1)}, {"tri2", std::to_string(p.tri2)},
              {"order", std::to_string(order)}};
  if (s.self) c.labels.emplace_back("shared", std::to_string(p.shared));
  return c;
}

// {"scene": NAME, "frame": K, "bodies": [[[x,y,z],[x,y,z],[x,y,z]], ...], ...]}
void write_picture(const std::string& path, const std::string& name, const scenes::StreamOptions& o) {
  const int frame = o.frames / 2;
  const auto bodies = scenes::scene_bodies(name, o, frame, 1500);
  write_file_atomically(path, [&](std::ostream& f) {
    f << "{\"scene\": \"" << name << "\", \"frame\": " << frame << ", \"bodies\": [";
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      f << (b ? "],\n[" : "\n[");
      for (std::size_t t = 0; t < bodies[b].size(); ++t) {
        f << (t ? "," : "") << '[';
        for (int c = 0; c < 3; ++c)
          f << (c ? ",[" : "[") << format_double(bodies[b][t][c].x()) << ',' << format_double(bodies[b][t][c].y())
            << ',' << format_double(bodies[b][t][c].z()) << ']';
        f << ']';
      }
    }
    f << "]]}\n";
  });
}

}  // namespace

int cmd_scene(int argc, char** argv) {
  Args args(argc, argv,
            {.valued = {"--out", "--bv", "--frames", "--mesh", "--picture"}, .flags = {"--list", "--small", "--adjacent"}});
  if (args.help()) {
    std::cout << kHelp;
    return kOk;
  }
  if (args.flag("--list")) return list_scenes();
  if (args.positional().size() != 1) throw UsageError("scene: wants one scene NAME (tritri scene --list)");
  const auto out = args.value("--out");
  if (!out) throw UsageError("scene: wants --out DIR");
  scenes::StreamOptions o;
  o.bv = args.value("--bv").value_or("OBB");
  o.frames = static_cast<int>(args.count("--frames", 16));
  if (o.frames < 1) throw UsageError("scene: --frames wants at least 1");
  o.small = args.flag("--small");
  o.user_mesh = args.value("--mesh").value_or("");
  o.adjacent = args.flag("--adjacent");
  scenes::SceneStream s;
  try {
    s = scenes::scene_stream(args.positional()[0], o);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("scene: ") + e.what());
  } catch (const std::runtime_error& e) {
    throw UsageError(std::string("scene: ") + e.what());
  }
  if (const auto picture = args.value("--picture")) write_picture(*picture, args.positional()[0], o);
  std::vector<Case> cases;
  int frame = -1;
  std::size_t order = 0;
  for (const auto& p : s.pairs) {
    order = p.frame == frame ? order + 1 : 0;
    frame = p.frame;
    cases.push_back(to_case(s, p, order));
  }
  std::filesystem::create_directories(*out);
  const std::string path = (std::filesystem::path(*out) / (s.scene + "." + s.bv + ".cases")).string();
  write_file_atomically(path, [&](std::ostream& f) {
    f << "# scene " << s.scene << " (seed " << s.seed << ", " << s.frames << " frames, " << s.bodies << "): "
      << s.description << "\n# candidates of FCL's " << s.bv << " BVH traversal (" << s.mode
      << "), in traversal order, world coordinates\n";
    write_cases(f, cases);
  });
  std::cout << path << ": " << cases.size() << " candidate pairs, " << s.frames << " frames";
  if (s.dropped_adjacent) std::cout << " (" << s.dropped_adjacent << " pairs of adjacent faces left out; --adjacent keeps them)";
  std::cout << '\n';
  return kOk;
}

}  // namespace tritri::cli
