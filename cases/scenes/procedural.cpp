// procedural meshes. See procedural.hpp.
#include "cases/scenes/procedural.hpp"

#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace tritri::scenes {

namespace {

std::string describe(const char* what, std::initializer_list<double> args) {
  std::ostringstream s;
  s << what << '(';
  bool first = true;
  for (double a : args) { s << (first ? "" : ", ") << a; first = false; }
  s << ')';
  return s.str();
}

void snap_all(Mesh& m) {
  for (Vec3& p : m.vertices)
    for (int i = 0; i < 3; ++i) p[i] = snap(p[i], kSnapBits);
}

// Unit icosphere, vertices on the unit sphere.
Mesh unit_icosphere(int level) {
  Mesh m;
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  const double base[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                              {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                              {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& b : base) m.vertices.push_back(Vec3(b[0], b[1], b[2]).normalized());
  m.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      auto key = std::minmax(a, b);
      auto it = mid.find({key.first, key.second});
      if (it != mid.end()) return it->second;
      const std::uint32_t id = std::uint32_t(m.vertices.size());
      m.vertices.push_back((0.5 * (m.vertices[a] + m.vertices[b])).normalized());
      mid.emplace(std::make_pair(key.first, key.second), id);
      return id;
    };
    std::vector<std::array<std::uint32_t, 3>> next;
    next.reserve(m.faces.size() * 4);
    for (const auto& f : m.faces) {
      const std::uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      next.push_back({f[0], ab, ca});
      next.push_back({f[1], bc, ab});
      next.push_back({f[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    m.faces.swap(next);
  }
  return m;
}

// Value noise: pseudo-random values on the integer lattice, blended with a smoothstep.
std::uint64_t mix(std::uint64_t h) {
  h ^= h >> 33; h *= 0xff51afd7ed558ccdull; h ^= h >> 33; h *= 0xc4ceb9fe1a85ec53ull; h ^= h >> 33;
  return h;
}
double lattice(std::uint64_t seed, long long x, long long y, long long z) {
  std::uint64_t h = mix(seed ^ mix(std::uint64_t(x) * 0x9E3779B97F4A7C15ull ^
                                   mix(std::uint64_t(y) * 0xC2B2AE3D27D4EB4Full ^ mix(std::uint64_t(z)))));
  return double(h >> 11) * 0x1.0p-52 - 1.0;  // [-1, 1)
}
double smooth(double t) { return t * t * (3.0 - 2.0 * t); }
double value_noise(std::uint64_t seed, double x, double y, double z) {
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const long long ix = (long long)fx, iy = (long long)fy, iz = (long long)fz;
  const double tx = smooth(x - fx), ty = smooth(y - fy), tz = smooth(z - fz);
  double c[2][2][2];
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int d = 0; d < 2; ++d) c[a][b][d] = lattice(seed, ix + a, iy + b, iz + d);
  auto lerp = [](double u, double v, double t) { return u + (v - u) * t; };
  const double x00 = lerp(c[0][0][0], c[1][0][0], tx), x10 = lerp(c[0][1][0], c[1][1][0], tx);
  const double x01 = lerp(c[0][0][1], c[1][0][1], tx), x11 = lerp(c[0][1][1], c[1][1][1], tx);
  return lerp(lerp(x00, x10, ty), lerp(x01, x11, ty), tz);
}
// Three octaves, normalised to [-1, 1].
double fbm(std::uint64_t seed, double x, double y, double z) {
  double sum = 0, amp = 1, norm = 0, f = 1;
  for (int o = 0; o < 3; ++o) {
    sum += amp * value_noise(seed + std::uint64_t(o) * 0x632BE59BD9B4E019ull, x * f, y * f, z * f);
    norm += amp;
    amp *= 0.5;
    f *= 2.0;
  }
  return sum / norm;
}

}  // namespace

Mesh make_sphere(int level, double radius) {
  Mesh m = unit_icosphere(level);
  for (Vec3& p : m.vertices) p *= radius;
  snap_all(m);
  m.name = describe("sphere", {double(level), radius});
  return m;
}

Mesh make_torus(double R, double r, int nu, int nv) {
  Mesh m;
  const double two_pi = 6.283185307179586;
  for (int i = 0; i < nu; ++i) {
    const double u = two_pi * i / nu;
    for (int j = 0; j < nv; ++j) {
      const double v = two_pi * j / nv;
      const double w = R + r * std::cos(v);
      m.vertices.emplace_back(w * std::cos(u), w * std::sin(u), r * std::sin(v));
    }
  }
  auto id = [&](int i, int j) { return std::uint32_t(((i + nu) % nu) * nv + (j + nv) % nv); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  snap_all(m);
  m.name = describe("torus", {R, r, double(nu), double(nv)});
  return m;
}

Mesh make_blob(int level, double radius, double amplitude, double frequency, std::uint64_t seed) {
  Mesh m = unit_icosphere(level);
  for (Vec3& p : m.vertices) {
    const double n = fbm(seed, p.x() * frequency, p.y() * frequency, p.z() * frequency);
    p *= radius * (1.0 + amplitude * n);
  }
  snap_all(m);
  m.name = describe("blob", {double(level), radius, amplitude, frequency, double(seed)});
  return m;
}

Mesh make_terrain(int n, double size, double height, std::uint64_t seed) {
  Mesh m;
  const double step = size / n;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double x = -0.5 * size + i * step, y = -0.5 * size + j * step;
      m.vertices.emplace_back(x, y, height * fbm(seed, 3.0 * x / size, 3.0 * y / size, 0.5));
    }
  auto id = [&](int i, int j) { return std::uint32_t(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if ((i + j) % 2 == 0) {
        m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        m.faces.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        m.faces.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  snap_all(m);
  m.name = describe("terrain", {double(n), size, height, double(seed)});
  return m;
}

Mesh make_thin_shell(int level, double radius, double thickness) {
  Mesh outer = make_sphere(level, radius);
  Mesh inner = make_sphere(level, radius - thickness);
  for (auto& f : inner.faces) std::swap(f[1], f[2]);
  Mesh m = concat(outer, inner, describe("thin_shell", {double(level), radius, thickness}));
  return m;
}

Mesh make_box(const Vec3& lo, const Vec3& hi, int n) {
  Mesh m;
  m.name = describe("box", {lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z(), double(n)});
  // Grid coordinates along each axis, checked to be exact.
  double g[3][65];
  if (n < 1 || n > 64) throw std::invalid_argument("make_box: n must be in [1, 64]");
  // Exactness: n a power of two makes (hi - lo) / n exact once hi - lo is; every subtraction and
  // addition is checked with the TwoSum error term (zero iff the operation did not round).
  auto two_sum_error = [](double a, double b) {
    const double s = a + b, bb = s - a;
    return (a - (s - bb)) + (b - bb);
  };
  if ((n & (n - 1)) != 0) throw std::invalid_argument("make_box: n must be a power of two");
  for (int a = 0; a < 3; ++a) {
    if (!(hi[a] > lo[a]) || two_sum_error(hi[a], -lo[a]) != 0)
      throw std::invalid_argument("make_box: hi - lo is not exact (use dyadic bounds)");
    const double step = (hi[a] - lo[a]) / n;
    for (int i = 0; i <= n; ++i) {
      const double di = i * step;
      if (std::fma(double(i), step, -di) != 0) throw std::invalid_argument("make_box: i * step is not exact");
      if (two_sum_error(lo[a], di) != 0) throw std::invalid_argument("make_box: lo + i * step is not exact");
      g[a][i] = lo[a] + di;
    }
    if (g[a][n] != hi[a]) throw std::invalid_argument("make_box: grid does not end at hi");
  }
  std::map<std::tuple<int, int, int>, std::uint32_t> weld;  // integer grid point -> vertex
  auto vid = [&](int i, int j, int k) {
    auto key = std::make_tuple(i, j, k);
    auto it = weld.find(key);
    if (it != weld.end()) return it->second;
    const std::uint32_t id = std::uint32_t(m.vertices.size());
    m.vertices.emplace_back(g[0][i], g[1][j], g[2][k]);
    weld.emplace(key, id);
    return id;
  };
  // For each axis a and side s (0: lo, 1: hi), the face lies in coordinate a = s * n; (u, v) span
  // the other two axes in right-handed order, flipped on the lo side so normals point outward.
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    for (int s = 0; s < 2; ++s)
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          auto at = [&](int di, int dj) {
            int c[3];
            c[a] = s * n; c[u] = i + di; c[v] = j + dj;
            return vid(c[0], c[1], c[2]);
          };
          std::uint32_t p00 = at(0, 0), p10 = at(1, 0), p11 = at(1, 1), p01 = at(0, 1);
          if (s == 0) std::swap(p10, p01);
          m.faces.push_back({p00, p10, p11});
          m.faces.push_back({p00, p11, p01});
        }
  }
  return m;
}

Mesh concat(const Mesh& a, const Mesh& b, const std::string& name) {
  Mesh m = a;
  m.name = name;
  const std::uint32_t off = std::uint32_t(a.vertices.size());
  m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto f : b.faces) m.faces.push_back({f[0] + off, f[1] + off, f[2] + off});
  return m;
}

}  // namespace tritri::scenes
