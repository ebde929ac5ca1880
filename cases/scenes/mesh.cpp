// helpers of mesh.hpp.
#include "cases/scenes/mesh.hpp"

#include <cmath>

namespace tritri::scenes {

Bounds bounds_of(const Mesh& m) {
  Bounds b;
  for (const Vec3& p : m.vertices) b.add(p);
  return b;
}

std::vector<Vec3> transformed(const Mesh& m, const Rigid& tf) {
  std::vector<Vec3> out;
  out.reserve(m.vertices.size());
  for (const Vec3& p : m.vertices) out.push_back(tf * p);
  return out;
}

double snap(double x, int k) {
  return std::ldexp(std::nearbyint(std::ldexp(x, k)), -k);
}

void normalize_dyadic(Mesh& m) {
  if (m.vertices.empty()) return;
  const Bounds b = bounds_of(m);
  const Vec3 centre = 0.5 * (b.lo + b.hi);
  const Vec3 c{snap(centre.x(), 20), snap(centre.y(), 20), snap(centre.z(), 20)};
  const double ext = b.extent().maxCoeff();
  int e = 0;
  std::frexp(ext, &e);                     // ext = f * 2^e, f in [0.5, 1)
  const int shift = 1 - e;                 // ext * 2^shift in [1, 2)
  for (Vec3& p : m.vertices) {
    p -= c;                                // rounding here is the input's, see header
    for (int i = 0; i < 3; ++i) p[i] = std::ldexp(p[i], shift);
  }
}

}  // namespace tritri::scenes
