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

// A motion given as a function of the phase t in [0, 1] over the frames (see phase()).
template <class F>
std::function<Rigid(int)> by_phase(int frames, F f) {
  return [frames, f](int k) { return Rigid(f(phase(k, frames))); };
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

// ------------------------------------------------------------------------------------- scenes
// Each builder adds the bodies (and the deformation) to a scene whose name, description, seed,
// frames, self and exact the catalogue below has already filled in; `small` is Size::Small.

void approach(Scene& s, const SceneConfig&, bool small) {
  const int level = small ? 2 : 4;
  s.bodies.push_back({"sphere", share(make_sphere(level, 1.0)), fixed()});
  s.bodies.push_back({"blob", share(make_blob(level, 1.0, 0.25, 1.5, s.seed)), by_phase(s.frames, [](double t) {
                        return translation(2.75 - 2.5 * t, 0.0, 0.0) * rotation(Vec3::UnitZ(), 0.6 * t);
                      })});
}

void graze(Scene& s, const SceneConfig&, bool small) {
  const int level = small ? 2 : 4;
  auto big = share(make_sphere(level, 1.0)), little = share(make_sphere(level, 0.5));
  const double in = inradius(*big) + inradius(*little), out = 1.5;
  const double d = in + 0.25 * (out - in);
  s.bodies.push_back({"big sphere", big, fixed()});
  s.bodies.push_back({"small sphere", little, by_phase(s.frames, [d](double t) {
                        const double a = kPi * (1.0 / 6 + (2.0 / 3) * t);
                        return translation(d * std::cos(a), d * std::sin(a), 0.0);
                      })});
}

void box_stack(Scene& s, const SceneConfig&, bool small) {
  const int n = small ? 4 : 16;
  const int F = s.frames;
  // Steps rounded to multiples of 2^-20, so every translation is exact.
  const double step_x = F > 1 ? snap(3.0 / (F - 1), 20) : 0.0;
  const double step_y = F > 1 ? snap(1.0 / (F - 1), 20) : 0.0;
  s.bodies.push_back({"A (base)", share(make_box({-1, -1, -1}, {1, 1, 0}, n)), fixed()});
  s.bodies.push_back({"B (on A)", share(make_box({-0.5, -0.5, 0}, {0.5, 0.5, 1}, n)),
                      [step_x](int k) { return translation(-1.5 + k * step_x, 0.0, 0.0); }});
  s.bodies.push_back({"C (on B)", share(make_box({-0.25, -0.25, 1}, {0.25, 0.25, 1.5}, n)),
                      [step_x, step_y](int k) { return translation(-1.5 + k * step_x, -0.5 + k * step_y, 0.0); }});
}

void rotate_through(Scene& s, const SceneConfig&, bool small) {
  const int nu = small ? 24 : 96, nv = small ? 8 : 32;
  auto torus = share(make_torus(1.0, 0.25, nu, nv));
  s.bodies.push_back({"ring A", torus, fixed()});
  s.bodies.push_back({"ring B", torus, by_phase(s.frames, [](double t) {
                        return translation(1.0, 0.0, 0.0) * rotation(Vec3::UnitZ(), kPi * t) *
                               rotation(Vec3::UnitX(), kPi / 2);
                      })});
}

void shell_terrain(Scene& s, const SceneConfig&, bool small) {
  s.bodies.push_back({"terrain", share(make_terrain(small ? 16 : 64, 4.0, 0.5, s.seed)), fixed()});
  s.bodies.push_back({"shell", share(make_thin_shell(small ? 2 : 4, 0.5, 0x1p-6)), by_phase(s.frames, [](double t) {
                        return translation(-0.5 + 1.0 * t, 0.25, 1.5 - 1.75 * t);
                      })});
}

void spindle_self(Scene& s, const SceneConfig&, bool small) {
  const int nu = small ? 24 : 96, nv = small ? 12 : 48;
  const int F = s.frames;
  s.deform = [F, nu, nv](int k) { return make_torus(1.0, 0.75 + 0.5 * phase(k, F), nu, nv); };
  s.bodies.push_back({"torus", share(s.deform(0)), fixed()});
}

void blobs_self(Scene& s, const SceneConfig&, bool small) {
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
}

// ---- scenes on CGAL's data meshes (Full only)

void dragon_bunny(Scene& s, const SceneConfig& c, bool) {
  s.bodies.push_back({"bunny", load(c, "bunny00.off"), fixed()});
  s.bodies.push_back({"dragon", load(c, "ChineseDragon-10kv.off"), by_phase(s.frames, [](double t) {
                        return translation(2.0 - 2.0 * t, 0.0, 0.0) * rotation(Vec3::UnitY(), 0.8 * t);
                      })});
}

void knot_torus(Scene& s, const SceneConfig& c, bool) {
  s.bodies.push_back({"knot", load(c, "knot1.off"), fixed()});
  s.bodies.push_back({"ring", share(make_torus(0.5, 0.1, 128, 32)), by_phase(s.frames, [](double t) {
                        return rotation(Vec3::UnitX(), 2 * kPi * t) * translation(0.35, 0.0, 0.0) *
                               rotation(Vec3::UnitY(), kPi / 2);
                      })});
}

void bunny_self(Scene& s, const SceneConfig& c, bool) { s.bodies.push_back({"bunny", load(c, "bunny00.off"), fixed()}); }

void herd(Scene& s, const SceneConfig& c, bool) {
  const char* files[] = {"elephant.off", "cow.off", "fandisk.off"};
  for (int b = 0; b < 3; ++b) {
    const double angle = 2 * kPi * b / 3;
    s.bodies.push_back({files[b], load(c, files[b]), by_phase(s.frames, [angle](double t) {
                          const double r = 1.5 - 1.1 * t;
                          return translation(r * std::cos(angle), r * std::sin(angle), 0.0) *
                                 rotation(Vec3::UnitZ(), angle + 0.5 * t);
                        })});
  }
}

// ---- scenes on a mesh the user brings (SceneConfig::user_mesh)

std::shared_ptr<const Mesh> user_mesh(const SceneConfig& c) {
  if (c.user_mesh.empty()) throw std::invalid_argument("this scene needs a mesh file (--mesh FILE)");
  Mesh m = read_mesh(c.user_mesh);
  normalize_dyadic(m);
  return share(std::move(m));
}

void mesh_self(Scene& s, const SceneConfig& c, bool) { s.bodies.push_back({"mesh", user_mesh(c), fixed()}); }

void mesh_sphere(Scene& s, const SceneConfig& c, bool) {
  s.bodies.push_back({"mesh", user_mesh(c), fixed()});
  s.bodies.push_back({"sphere", share(make_sphere(3, 0.5)),
                      by_phase(s.frames, [](double t) { return translation(2.0 - 4.0 * t, 0.0, 0.0); })});
}

// ------------------------------------------------------------------------------ the catalogue

enum class Source : std::uint8_t { procedural, cgal_data, user_mesh };
// How the scene moves: bodies in motion (exact: by dyadic translations only), or one mesh
// against itself, deformed over the frames or static (one frame).
enum class Kind : std::uint8_t { moving, moving_exact, self_deforming, self_static };

struct Entry {
  const char* name;
  std::uint64_t seed;
  Source source;
  Kind kind;
  void (*build)(Scene&, const SceneConfig&, bool small);
  const char* description;
};

// clang-format off
const Entry kScenes[] = {
    {"approach", 11, Source::procedural, Kind::moving, approach,
     "noisy blob (r~1) flies along -x into a sphere (r=1) while turning about z: separated, first contact, then centres 0.25 apart (deep penetration)"},
    {"graze", 12, Source::procedural, Kind::moving, graze,
     "small sphere (r=0.5) orbits a sphere (r=1) at a constant centre distance a quarter of the way from the sum of the polyhedra's inscribed radii to the sum of their vertex radii: faces and vertices brush each other, contact comes and goes from frame to frame"},
    {"box_stack", 13, Source::procedural, Kind::moving_exact, box_stack,
     "three axis-aligned subdivided boxes in resting contact (A's top and B's bottom at z=0, B's top and C's bottom at z=1, exactly coplanar); B slides along x off A's edges, C slides along y on B; dyadic translations only (exact)"},
    {"rotate_through", 14, Source::procedural, Kind::moving, rotate_through,
     "two linked tori (R=1, r=0.25, like chain links); the second turns half a revolution about the vertical axis through its centre, which lies on the first one's core circle, so the tubes pass through each other"},
    {"shell_terrain", 15, Source::procedural, Kind::moving, shell_terrain,
     "thin spherical shell (r=0.5, wall 2^-6) drops onto a noisy height field and sinks into it while drifting along x"},
    {"spindle_self", 16, Source::procedural, Kind::self_deforming, spindle_self,
     "one torus against itself while its tube radius grows from 0.75 to 1.25 (major radius 1): a ring torus, then a spindle torus whose inner part passes through itself around the axis"},
    {"blobs_self", 17, Source::procedural, Kind::self_deforming, blobs_self,
     "one mesh made of two blobs (as in a merged asset) against itself; the second component moves through the first over the frames"},
    {"dragon_bunny", 21, Source::cgal_data, Kind::moving, dragon_bunny,
     "ChineseDragon-10kv flies along -x into bunny00 while turning about y (both scaled by a power of two to an extent in [1, 2), centred)"},
    {"knot_torus", 22, Source::cgal_data, Kind::moving, knot_torus,
     "knot1 fixed; a torus ring (R=0.5, r=0.1, 8192 triangles) offset by 0.35 in x turns a full revolution about the x axis, sweeping through the knot's tube"},
    {"bunny_self", 23, Source::cgal_data, Kind::self_static, bunny_self,
     "bunny00 (a range scan) against itself, one frame"},
    {"herd", 24, Source::cgal_data, Kind::moving, herd,
     "elephant, cow and fandisk (each scaled to an extent in [1, 2)) start on a circle of radius 1.5 and converge on its centre while turning: three body pairs per frame, grazing then interpenetrating"},
    {"mesh_self", 31, Source::user_mesh, Kind::self_static, mesh_self,
     "the given mesh (scaled to an extent in [1, 2), centred) against itself, one frame"},
    {"mesh_sphere", 32, Source::user_mesh, Kind::moving, mesh_sphere,
     "a sphere (r=0.5, 1280 triangles) flies along -x through the given mesh (scaled to an extent in [1, 2), centred)"},
};
// clang-format on

const Entry* find(const std::string& name) {
  for (const Entry& e : kScenes)
    if (name == e.name) return &e;
  return nullptr;
}

bool from(const std::string& name, Source source) {
  const Entry* e = find(name);
  return e && e->source == source;
}

}  // namespace

bool needs_cgal_data(const std::string& name) { return from(name, Source::cgal_data); }
bool needs_user_mesh(const std::string& name) { return from(name, Source::user_mesh); }

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
  std::vector<std::string> v;
  for (const Entry& e : kScenes)
    if (e.source == Source::procedural || (e.source == Source::cgal_data && size == Size::Full)) v.push_back(e.name);
  return v;
}

Scene make_scene(const std::string& name, const SceneConfig& c) {
  const Entry* e = find(name);
  if (!e) throw std::invalid_argument("unknown scene '" + name + "'");
  Scene s;
  s.name = e->name;
  s.description = e->description;
  s.seed = e->seed;
  s.frames = e->kind == Kind::self_static ? 1 : c.frames;
  s.self = e->kind == Kind::self_deforming || e->kind == Kind::self_static;
  s.exact = e->kind == Kind::moving_exact;
  e->build(s, c, c.size == Size::Small);
  return s;
}

}  // namespace tritri::scenes
