// the scene catalogue. See scenes.hpp.
#include "cases/scenes/scenes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cases/scenes/data.hpp"
#include "cases/scenes/mesh_io.hpp"
#include "cases/scenes/procedural.hpp"

namespace tritri::scenes {

namespace {

constexpr double kPi = 3.141592653589793;

std::shared_ptr<const Mesh> share(Mesh m) { return std::make_shared<const Mesh>(std::move(m)); }

// t in [0, 1] over the frames (0 when there is a single frame).
double phase(int k, int frames) { return frames > 1 ? double(k) / (frames - 1) : 0.0; }

Rigid translation(double x, double y, double z) {
  Rigid t = Rigid::Identity();
  t.translation() = Vec3(x, y, z);
  return t;
}
Rigid rotation(const Vec3& axis, double angle) {
  Rigid t = Rigid::Identity();
  t.linear() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  return t;
}
std::function<Rigid(int)> fixed() { return [](int) { return Rigid(Rigid::Identity()); }; }

std::shared_ptr<const Mesh> load(const SceneConfig& c, const std::string& file) {
  ReadOptions o;
  o.degenerate = Degenerate::Drop;  // scans carry a few zero-area faces; they are not pairs to test
  Mesh m = read_mesh((c.mesh_dir.empty() ? cgal_mesh_dir() : c.mesh_dir) + "/" + file, o);
  normalize_dyadic(m);
  m.name = file;
  return share(std::move(m));
}

// ------------------------------------------------------------------------------------- scenes

Scene approach(const SceneConfig& c) {
  const bool small = c.size == Size::Small;
  Scene s;
  s.name = "approach";
  s.description = "noisy blob (r~1) flies along -x into a sphere (r=1) while turning about z: "
                  "separated, first contact, then centres 0.25 apart (deep penetration)";
  s.seed = 11;
  s.frames = c.frames;
  const int level = small ? 2 : 4;
  s.bodies.push_back({"sphere", share(make_sphere(level, 1.0)), fixed()});
  const int F = s.frames;
  s.bodies.push_back({"blob", share(make_blob(level, 1.0, 0.25, 1.5, s.seed)), [F](int k) {
                        const double t = phase(k, F);
                        return Rigid(translation(2.75 - 2.5 * t, 0.0, 0.0) * rotation(Vec3::UnitZ(), 0.6 * t));
                      }});
  return s;
}

// Smallest distance from the origin to the plane of a face: the polyhedron's inscribed radius.
double inradius(const Mesh& m) {
  double r = 1e300;
  for (const auto& f : m.faces) {
    const Vec3 &a = m.vertices[f[0]], &b = m.vertices[f[1]], &c = m.vertices[f[2]];
    const Vec3 n = (b - a).cross(c - a).normalized();
    r = std::min(r, std::abs(n.dot(a)));
  }
  return r;
}

Scene graze(const SceneConfig& c) {
  const bool small = c.size == Size::Small;
  Scene s;
  s.name = "graze";
  s.description = "small sphere (r=0.5) orbits a sphere (r=1) at a constant centre distance a "
                  "quarter of the way from the sum of the polyhedra's inscribed radii to the sum "
                  "of their vertex radii: faces and vertices brush each other, contact comes and "
                  "goes from frame to frame";
  s.seed = 12;
  s.frames = c.frames;
  const int level = small ? 2 : 4;
  auto big = share(make_sphere(level, 1.0)), little = share(make_sphere(level, 0.5));
  const double in = inradius(*big) + inradius(*little), out = 1.5;
  const double d = in + 0.25 * (out - in);
  s.bodies.push_back({"big sphere", big, fixed()});
  const int F = s.frames;
  s.bodies.push_back({"small sphere", little, [F, d](int k) {
                        const double a = kPi * (1.0 / 6 + (2.0 / 3) * phase(k, F));
                        return translation(d * std::cos(a), d * std::sin(a), 0.0);
                      }});
  return s;
}

Scene box_stack(const SceneConfig& c) {
  const bool small = c.size == Size::Small;
  Scene s;
  s.name = "box_stack";
  s.description = "three axis-aligned subdivided boxes in resting contact (A's top and B's bottom "
                  "at z=0, B's top and C's bottom at z=1, exactly coplanar); B slides along x "
                  "off A's edges, C slides along y on B; dyadic translations only (exact)";
  s.seed = 13;
  s.frames = c.frames;
  s.exact = true;
  const int n = small ? 4 : 16;
  s.bodies.push_back({"A (base)", share(make_box({-1, -1, -1}, {1, 1, 0}, n)), fixed()});
  s.bodies.push_back({"B (on A)", share(make_box({-0.5, -0.5, 0}, {0.5, 0.5, 1}, n)), {}});
  s.bodies.push_back({"C (on B)", share(make_box({-0.25, -0.25, 1}, {0.25, 0.25, 1.5}, n)), {}});
  const int F = s.frames;
  // Steps rounded to multiples of 2^-20, so every translation is exact.
  const double step_x = F > 1 ? snap(3.0 / (F - 1), 20) : 0.0;
  const double step_y = F > 1 ? snap(1.0 / (F - 1), 20) : 0.0;
  s.bodies[1].motion = [step_x](int k) { return translation(-1.5 + k * step_x, 0.0, 0.0); };
  s.bodies[2].motion = [step_x, step_y](int k) {
    return translation(-1.5 + k * step_x, -0.5 + k * step_y, 0.0);
  };
  return s;
}

Scene rotate_through(const SceneConfig& c) {
  const bool small = c.size == Size::Small;
  Scene s;
  s.name = "rotate_through";
  s.description = "two linked tori (R=1, r=0.25, like chain links); the second turns half a "
                  "revolution about the vertical axis through its centre, which lies on the "
                  "first one's core circle, so the tubes pass through each other";
  s.seed = 14;
  s.frames = c.frames;
  const int nu = small ? 24 : 96, nv = small ? 8 : 32;
  auto torus = share(make_torus(1.0, 0.25, nu, nv));
  s.bodies.push_back({"ring A", torus, fixed()});
  const int F = s.frames;
  s.bodies.push_back({"ring B", torus, [F](int k) {
                        return Rigid(translation(1.0, 0.0, 0.0) * rotation(Vec3::UnitZ(), kPi * phase(k, F)) *
                                     rotation(Vec3::UnitX(), kPi / 2));
                      }});
  return s;
}

Scene shell_terrain(const SceneConfig& c) {
  const bool small = c.size == Size::Small;
  Scene s;
  s.name = "shell_terrain";
  s.description = "thin spherical shell (r=0.5, wall 2^-6) drops onto a noisy height field and "
                  "sinks into it while drifting along x";
  s.seed = 15;
  s.frames = c.frames;
  s.bodies.push_back({"terrain", share(make_terrain(small ? 16 : 64, 4.0, 0.5, s.seed)), fixed()});
  s.bodies.push_back({"shell", share(make_thin_shell(small ? 2 : 4, 0.5, 0x1p-6)), {}});
  const int F = s.frames;
  s.bodies[1].motion = [F](int k) {
    const double t = phase(k, F);
    return translation(-0.5 + 1.0 * t, 0.25, 1.5 - 1.75 * t);
  };
  return s;
}

Scene spindle_self(const SceneConfig& c) {
  const bool small = c.size == Size::Small;
  Scene s;
  s.name = "spindle_self";
  s.description = "one torus against itself while its tube radius grows from 0.75 to 1.25 "
                  "(major radius 1): a ring torus, then a spindle torus whose inner part "
                  "passes through itself around the axis";
  s.seed = 16;
  s.frames = c.frames;
  s.self = true;
  const int nu = small ? 24 : 96, nv = small ? 12 : 48;
  const int F = s.frames;
  s.deform = [F, nu, nv](int k) { return make_torus(1.0, 0.75 + 0.5 * phase(k, F), nu, nv); };
  s.bodies.push_back({"torus", share(s.deform(0)), fixed()});
  return s;
}

Scene blobs_self(const SceneConfig& c) {
  const bool small = c.size == Size::Small;
  Scene s;
  s.name = "blobs_self";
  s.description = "one mesh made of two blobs (as in a merged asset) against itself; the second "
                  "component moves through the first over the frames";
  s.seed = 17;
  s.frames = c.frames;
  s.self = true;
  const int level = small ? 2 : 4;
  auto a = std::make_shared<Mesh>(make_blob(level, 1.0, 0.2, 1.5, s.seed));
  auto b = std::make_shared<Mesh>(make_blob(level, 0.6, 0.3, 2.0, s.seed + 1));
  const int F = s.frames;
  s.deform = [F, a, b](int k) {
    Mesh moved = *b;
    const double x = snap(1.9 - 1.9 * phase(k, F), 20);
    for (Vec3& p : moved.vertices) p.x() += x;  // exact: both multiples of 2^-20
    return concat(*a, moved, "two blobs");
  };
  s.bodies.push_back({"two blobs", share(s.deform(0)), fixed()});
  return s;
}

// ---- scenes on CGAL's data meshes (Full only)

Scene dragon_bunny(const SceneConfig& c) {
  Scene s;
  s.name = "dragon_bunny";
  s.description = "ChineseDragon-10kv flies along -x into bunny00 while turning about y "
                  "(both scaled by a power of two to an extent in [1, 2), centred)";
  s.seed = 21;
  s.frames = c.frames;
  s.bodies.push_back({"bunny", load(c, "bunny00.off"), fixed()});
  const int F = s.frames;
  s.bodies.push_back({"dragon", load(c, "ChineseDragon-10kv.off"), [F](int k) {
                        const double t = phase(k, F);
                        return Rigid(translation(2.0 - 2.0 * t, 0.0, 0.0) * rotation(Vec3::UnitY(), 0.8 * t));
                      }});
  return s;
}

Scene knot_torus(const SceneConfig& c) {
  Scene s;
  s.name = "knot_torus";
  s.description = "knot1 fixed; a torus ring (R=0.5, r=0.1, 8192 triangles) offset by 0.35 in x "
                  "turns a full revolution about the x axis, sweeping through the knot's tube";
  s.seed = 22;
  s.frames = c.frames;
  s.bodies.push_back({"knot", load(c, "knot1.off"), fixed()});
  const int F = s.frames;
  s.bodies.push_back({"ring", share(make_torus(0.5, 0.1, 128, 32)), [F](int k) {
                        return Rigid(rotation(Vec3::UnitX(), 2 * kPi * phase(k, F)) * translation(0.35, 0.0, 0.0) *
                                     rotation(Vec3::UnitY(), kPi / 2));
                      }});
  return s;
}

Scene bunny_self(const SceneConfig& c) {
  Scene s;
  s.name = "bunny_self";
  s.description = "bunny00 (a range scan) against itself, one frame";
  s.seed = 23;
  s.frames = 1;
  s.self = true;
  s.bodies.push_back({"bunny", load(c, "bunny00.off"), fixed()});
  return s;
}

Scene herd(const SceneConfig& c) {
  Scene s;
  s.name = "herd";
  s.description = "elephant, cow and fandisk (each scaled to an extent in [1, 2)) start on a "
                  "circle of radius 1.5 and converge on its centre while turning: three body "
                  "pairs per frame, grazing then interpenetrating";
  s.seed = 24;
  s.frames = c.frames;
  const char* files[] = {"elephant.off", "cow.off", "fandisk.off"};
  const int F = s.frames;
  for (int b = 0; b < 3; ++b) {
    const double angle = 2 * kPi * b / 3;
    s.bodies.push_back({files[b], load(c, files[b]), [F, angle](int k) {
                          const double t = phase(k, F), r = 1.5 - 1.1 * t;
                          return Rigid(translation(r * std::cos(angle), r * std::sin(angle), 0.0) *
                                       rotation(Vec3::UnitZ(), angle + 0.5 * t));
                        }});
  }
  return s;
}

// ---- scenes on a mesh the user brings (SceneConfig::user_mesh)

std::shared_ptr<const Mesh> user_mesh(const SceneConfig& c) {
  if (c.user_mesh.empty()) throw std::invalid_argument("this scene needs a mesh file (--mesh FILE)");
  Mesh m = read_mesh(c.user_mesh);
  normalize_dyadic(m);
  return share(std::move(m));
}

Scene mesh_self(const SceneConfig& c) {
  Scene s;
  s.name = "mesh_self";
  s.description = "the given mesh (scaled to an extent in [1, 2), centred) against itself, one frame";
  s.seed = 31;
  s.frames = 1;
  s.self = true;
  s.bodies.push_back({"mesh", user_mesh(c), fixed()});
  return s;
}

Scene mesh_sphere(const SceneConfig& c) {
  Scene s;
  s.name = "mesh_sphere";
  s.description = "a sphere (r=0.5, 1280 triangles) flies along -x through the given mesh "
                  "(scaled to an extent in [1, 2), centred)";
  s.seed = 32;
  s.frames = c.frames;
  s.bodies.push_back({"mesh", user_mesh(c), fixed()});
  const int F = s.frames;
  s.bodies.push_back({"sphere", share(make_sphere(3, 0.5)), [F](int k) {
                        return translation(2.0 - 4.0 * phase(k, F), 0.0, 0.0);
                      }});
  return s;
}

}  // namespace

bool needs_cgal_data(const std::string& name) {
  return name == "dragon_bunny" || name == "knot_torus" || name == "bunny_self" || name == "herd";
}
bool needs_user_mesh(const std::string& name) { return name == "mesh_self" || name == "mesh_sphere"; }

std::vector<std::pair<int, int>> Scene::body_pairs() const {
  std::vector<std::pair<int, int>> out;
  if (self) return {{0, 0}};
  for (int i = 0; i < int(bodies.size()); ++i)
    for (int j = i + 1; j < int(bodies.size()); ++j) out.emplace_back(i, j);
  return out;
}

std::shared_ptr<const Mesh> Scene::mesh_at(int b, int k) const {
  if (self && deform && k != 0) return std::make_shared<const Mesh>(deform(k));
  return bodies[b].mesh;
}

std::vector<std::string> scene_names(Size size) {
  std::vector<std::string> v = {"approach", "graze", "box_stack", "rotate_through",
                                "shell_terrain", "spindle_self", "blobs_self"};
  if (size == Size::Full) {
    v.push_back("dragon_bunny");
    v.push_back("knot_torus");
    v.push_back("bunny_self");
    v.push_back("herd");
  }
  return v;
}

Scene make_scene(const std::string& name, const SceneConfig& c) {
  if (name == "approach") return approach(c);
  if (name == "graze") return graze(c);
  if (name == "box_stack") return box_stack(c);
  if (name == "rotate_through") return rotate_through(c);
  if (name == "shell_terrain") return shell_terrain(c);
  if (name == "spindle_self") return spindle_self(c);
  if (name == "blobs_self") return blobs_self(c);
  if (name == "dragon_bunny") return dragon_bunny(c);
  if (name == "knot_torus") return knot_torus(c);
  if (name == "bunny_self") return bunny_self(c);
  if (name == "herd") return herd(c);
  if (name == "mesh_self") return mesh_self(c);
  if (name == "mesh_sphere") return mesh_sphere(c);
  throw std::invalid_argument("unknown scene '" + name + "'");
}

}  // namespace tritri::scenes
