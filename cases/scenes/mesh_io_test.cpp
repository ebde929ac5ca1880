// tests of the mesh reader's messages and of the procedural generators.
// Writes small bad files under a scratch directory; ends with "N passed, N failed".
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "cases/scenes/data.hpp"
#include "cases/scenes/mesh_io.hpp"
#include "cases/scenes/oracle.hpp"
#include "cases/scenes/procedural.hpp"

using namespace tritri::scenes;
namespace fs = std::filesystem;

namespace {

int passed = 0, failed = 0;
void check(bool ok, const std::string& what, const std::string& detail = "") {
  (ok ? passed : failed)++;
  std::printf("%s %s%s%s\n", ok ? "ok  " : "FAIL", what.c_str(), detail.empty() ? "" : "  -- ", detail.c_str());
}

fs::path dir;
std::string write(const std::string& name, const std::string& text) {
  const auto p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

// Reading `path` must fail with a message containing every one of `needles`.
void expect_error(const std::string& what, const std::string& path, std::vector<std::string> needles,
                  ReadOptions o = {}) {
  try {
    read_mesh(path, o);
    check(false, what, "no error");
  } catch (const MeshError& e) {
    bool ok = true;
    for (const auto& n : needles) ok = ok && std::string(e.what()).find(n) != std::string::npos;
    check(ok, what, e.what());
  }
}

const char* kTet = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

// Reading: good input, and bad input named by file, line and problem.
void check_reading() {
  // --- good input
  {
    Mesh m = read_mesh(write("tet.off", kTet));
    check(m.faces.size() == 4 && m.vertices.size() == 4, "tetrahedron OFF reads 4 triangles");
  }
  {
    const std::string quad = "OFF\n# a comment\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
    ReadReport r;
    Mesh m = read_mesh(write("quad.off", quad), {}, &r);
    check(m.faces.size() == 2 && r.fanned == 1, "a quad is fanned into two triangles");
    ReadOptions refuse;
    refuse.polygons = Polygons::Refuse;
    expect_error("a quad is refused when polygons are refused", write("quad2.off", quad),
                 {"quad2.off:8:", "face 0 has 4 corners"}, refuse);
  }
  // --- bad coordinates, with the line
  expect_error("NaN coordinate (OFF)", write("nan.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"),
               {"nan.off:4:", "vertex 1", "NaN"});
  expect_error("infinite coordinate (OFF)", write("inf.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 -inf 0\n3 0 1 2\n"),
               {"inf.off:5:", "vertex 2", "infinite"});
  expect_error("overflowing coordinate (OFF)", write("big.off", "OFF\n3 1 0\n1e999 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
               {"big.off:3:", "overflows"});
  expect_error("not a number (OFF)", write("word.off", "OFF\n3 1 0\n0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n"),
               {"word.off:4:", "'zero' is not a number"});
  expect_error("NaN coordinate (OBJ)", write("nan.obj", "# obj\nv 0 0 0\nv 1 0 0\nv 0 NaN 0\nf 1 2 3\n"),
               {"nan.obj:4:", "NaN"});
  // --- bad structure
  expect_error("index out of range (OFF)", write("idx.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
               {"idx.off:6:", "index 7"});
  expect_error("index out of range (OBJ)", write("idx.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"),
               {"idx.obj"});
  expect_error("truncated vertex list (OFF)", write("short.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n"),
               {"short.off", "2 of 4 vertices"});
  expect_error("face count mismatch (OFF)", write("fewer.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n"),
               {"fewer.off:6:", "4 corners announced, 3 given"});
  expect_error("missing file", (dir / "nothere.off").string(), {"nothere.off", "cannot open"});
  expect_error("empty file", write("empty.off", ""), {"empty.off", "empty"});
  expect_error("unknown extension", write("mesh.xyz", "1 2 3\n"), {"mesh.xyz", "unknown extension"});
  // --- degenerate faces
  const std::string rep = "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n2 0 0\n3 0 1 2\n3 0 1 1\n";
  const std::string col = "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n2 0 0\n3 0 1 2\n3 0 1 3\n";
  expect_error("repeated vertex is refused", write("rep.off", rep), {"rep.off:8:", "face 1", "repeats a vertex"});
  expect_error("collinear face is refused", write("col.off", col), {"col.off:8:", "face 1", "collinear"});
  {
    ReadOptions drop;
    drop.degenerate = Degenerate::Drop;
    ReadReport r;
    Mesh m = read_mesh(write("col2.off", col), drop, &r);
    check(m.faces.size() == 1 && r.dropped_degenerate == 1, "collinear face is dropped on request");
  }
  // --- binary STL with a NaN: no line, but the vertex is named
  {
    std::string stl(80, ' ');
    auto put_u32 = [&](std::uint32_t v) { stl.append(reinterpret_cast<const char*>(&v), 4); };
    auto put_f = [&](float v) { stl.append(reinterpret_cast<const char*>(&v), 4); };
    put_u32(1);
    for (int i = 0; i < 3; ++i) put_f(0);
    const float tri[9] = {0, 0, 0, 1, 0, 0, 0, std::nanf(""), 0};
    for (float v : tri) put_f(v);
    stl.append(2, '\0');
    expect_error("NaN in binary STL", write("nan.stl", stl), {"nan.stl", "NaN"});
  }
}

// The same sphere in three formats of CGAL's data set.
void check_real_meshes(const std::string& data) {
  try {
    const auto a = read_mesh(data + "/sphere.off"), b = read_mesh(data + "/sphere.ply"), c = read_mesh(data + "/sphere.stl");
    check(a.faces.size() == b.faces.size() && b.faces.size() == c.faces.size(),
          "sphere.off/.ply/.stl give the same triangle count",
          std::to_string(a.faces.size()) + " " + std::to_string(b.faces.size()) + " " + std::to_string(c.faces.size()));
  } catch (const std::exception& e) {
    check(false, "sphere.off/.ply/.stl readable", e.what());
  }
}

void check_procedural_meshes() {
  auto no_degenerate = [](const Mesh& m) {
    for (const auto& f : m.faces) {
      const Vec3 n = (m.vertices[f[1]] - m.vertices[f[0]]).cross(m.vertices[f[2]] - m.vertices[f[0]]);
      if (!(n.squaredNorm() > 0)) return false;
    }
    return true;
  };
  auto same = [](const Mesh& a, const Mesh& b) {
    return a.faces == b.faces && a.vertices.size() == b.vertices.size() &&
           std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vec3)) == 0;
  };
  check(make_sphere(3, 1.0).faces.size() == 1280, "sphere level 3 has 1280 triangles");
  check(same(make_blob(3, 1, 0.3, 2, 7), make_blob(3, 1, 0.3, 2, 7)), "blob is deterministic for a seed");
  check(!same(make_blob(3, 1, 0.3, 2, 7), make_blob(3, 1, 0.3, 2, 8)), "blob differs between seeds");
  check(same(make_terrain(16, 4, 0.5, 3), make_terrain(16, 4, 0.5, 3)), "terrain is deterministic for a seed");
  for (const Mesh& m : {make_sphere(3, 1.0), make_torus(1, 0.25, 48, 16), make_blob(3, 1, 0.3, 2, 7),
                        make_terrain(16, 4, 0.5, 3), make_thin_shell(3, 0.5, 0x1p-6), make_box({-1, -1, -1}, {1, 1, 0}, 8)})
    check(no_degenerate(m), "no degenerate triangle in " + m.name);
  for (const Mesh& m : {make_sphere(3, 1.0), make_torus(1, 0.25, 48, 16), make_blob(3, 1, 0.3, 2, 7)}) {
    bool dyadic = true;
    for (const auto& p : m.vertices)
      for (int i = 0; i < 3; ++i) dyadic = dyadic && std::ldexp(p[i], kSnapBits) == std::nearbyint(std::ldexp(p[i], kSnapBits));
    check(dyadic, "coordinates are multiples of 2^-20 in " + m.name);
  }
  {
    // Stacked boxes: the upper box's bottom triangles lie exactly in the lower box's top plane.
    const Mesh lower = make_box({-1, -1, -1}, {1, 1, 0}, 8), upper = make_box({-0.5, -0.5, 0}, {0.5, 0.5, 1}, 8);
    int top = 0, bottom = 0;
    for (const auto& f : lower.faces)
      top += lower.vertices[f[0]].z() == 0 && lower.vertices[f[1]].z() == 0 && lower.vertices[f[2]].z() == 0;
    for (const auto& f : upper.faces)
      bottom += upper.vertices[f[0]].z() == 0 && upper.vertices[f[1]].z() == 0 && upper.vertices[f[2]].z() == 0;
    check(top == 128 && bottom == 128, "stacked boxes share the plane z = 0 exactly",
          std::to_string(top) + " and " + std::to_string(bottom) + " triangles in it");
    bool threw = false;
    try { make_box({0, 0, 0}, {0.1, 1, 1}, 4); } catch (const std::invalid_argument&) { threw = true; }
    check(threw, "a box with inexact grid coordinates is refused");
    threw = false;
    try { make_box({0, 0, 0}, {1, 1, 1}, 3); } catch (const std::invalid_argument&) { threw = true; }
    check(threw, "a box with n not a power of two is refused");
  }
  {
    // A spindle torus intersects itself (checked with the exact self rule on a few pairs), a ring torus not.
    auto self_hits = [](const Mesh& m) {
      const auto pairs = overlapping_box_pairs(m.vertices, m.faces, m.vertices, m.faces, true);
      std::size_t n = 0;
      for (auto [a, b] : pairs) n += self_pair_intersects(m.vertices, m.faces[a], m.faces[b]);
      return n;
    };
    const auto ring = self_hits(make_torus(1, 0.5, 24, 12)), spindle = self_hits(make_torus(1, 1.25, 24, 12));
    check(ring == 0 && spindle > 0, "ring torus has no self-intersection, spindle torus has",
          std::to_string(ring) + " / " + std::to_string(spindle));
  }
}

}  // namespace

int main(int argc, char** argv) {
  dir = fs::temp_directory_path() / ("scenes_mesh_io_test-" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::string data = argc > 1 ? argv[1] : "";
  if (data.empty()) try {
      data = cgal_mesh_dir();
    } catch (const std::exception& e) {
      std::printf("SKIP the real-mesh checks: %s\n", e.what());
    }
  check_reading();
  check_real_meshes(data);
  check_procedural_meshes();
  std::printf("%d passed, %d failed\n", passed, failed);
  return failed ? 1 : 0;
}
