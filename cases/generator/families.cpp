#include "cases/generator/construction.hpp"
#include "cases/generator/families_parts.hpp"

#include <algorithm>
#include <cmath>

namespace tritri::corpus {

const std::vector<Family>& families() {
  static const std::vector<Family> all = [] {
    // The relations a family produces beyond its configs' expectations (also_produces): those of
    // its configs that only the oracle can judge.
    const std::vector<Relation> none, disjoint = {Relation::disjoint},
                                disjoint_or_cross = {Relation::disjoint, Relation::cross};
    // The families, in the order of cases/README.md: name, summary, their configs (the rows of
    // the construction files' tables that name them, added below), also_produces, and whether
    // they are exact as built.
    std::vector<Family> out = {
        {"shared-vertex", "one common vertex", {}, none, true},
        {"vertex-on-edge", "a vertex of T2 strictly inside an edge of T1", {}, none, true},
        {"vertex-on-face", "a vertex of T2 strictly inside T1", {}, none, true},
        {"shared-edge", "a common edge", {}, none, true},
        {"collinear-edges", "an edge of each on one line", {}, none, true},
        {"edge-crossing", "an edge of each crossing at one point, planes not parallel", {}, none, true},
        {"edge-on-face", "an edge of T2 in T1's plane", {}, none, true},
        {"coplanar-containment", "T2 inside T1 in one plane, touching its boundary or not", {}, none, true},
        {"coplanar-overlap", "coplanar overlaps whose intersection has 3 to 6 corners", {}, none, true},
        {"coplanar-disjoint", "one plane, apart by gaps from 8 down to one ulp", {}, none, true},
        {"parallel", "distinct parallel planes, offsets from 8 down to one ulp", {}, none, true},
        {"near-coplanar", "T2 tilted off T1's plane by slopes 2^-3 to 2^-50", {}, none, true},
        {"axis-aligned", "T1 in a plane x, y or z = c; T2 crossing, touching or random", {}, disjoint, true},
        {"slivers", "needles and caps with aspect ratios up to 1e8", {}, none, true},
        {"tiny-vs-huge", "T2 smaller than T1 by 2^-10 to 2^-40", {}, none, true},
        {"random", "vertices uniform in the unit cube", {}, disjoint_or_cross, false},
    };
    for (const auto& table : {contact_configs(), plane_configs(), stress_configs()})
      for (const FamilyConfig& row : table)
        for (Family& f : out)
          if (std::string_view(f.name) == row.family) f.configs.push_back(row.config);
    return out;
  }();
  return all;
}

const Family* find_family(std::string_view name) {
  for (const auto& f : families())
    if (name == f.name) return &f;
  return nullptr;
}

std::vector<Relation> relations_meant(const Family& family) {
  std::vector<Relation> out = family.also_produces;
  for (const auto& c : family.configs)
    if (c.expect) out.push_back(*c.expect);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

namespace {

void permute_axes(Rng& rng, Frame& f) {
  int order[3] = {0, 1, 2};
  for (int i = 2; i > 0; --i) std::swap(order[i], order[rng.between(0, i)]);
  Frame p = f;
  for (int i = 0; i < 3; ++i) {
    const double s = rng.sign();
    for (int j = 0; j < 3; ++j) p.m[i][j] = s * f.m[order[i]][j];
    p.t[i] = s * f.t[order[i]];
  }
  f = p;
}

double det3(const double (&m)[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// a + b, or nothing if it rounds (Knuth's TwoSum: the error term is exactly the rounding).
bool add_exact(double a, double b, double& sum) {
  sum = a + b;
  const double bb = sum - a;
  return (a - (sum - bb)) + (b - bb) == 0.0;
}

bool mul_exact(double a, double b, double& product) {
  product = a * b;
  return std::fma(a, b, -product) == 0.0;
}

}  // namespace

Frame random_frame(Rng& rng, FrameKind kind) {
  Frame f{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}};
  if (kind == FrameKind::none) return f;
  if (kind == FrameKind::general) {
    do
      for (auto& row : f.m)
        for (double& x : row) x = rng.between(-2, 2);
    while (det3(f.m) == 0);
  } else if (kind == FrameKind::planar) {
    do {
      f.m[0][0] = rng.between(-2, 2), f.m[0][1] = rng.between(-2, 2);
      f.m[1][0] = rng.between(-2, 2), f.m[1][1] = rng.between(-2, 2);
    } while (f.m[0][0] * f.m[1][1] - f.m[0][1] * f.m[1][0] == 0);
  }
  // Translations are often zero along an axis, so that ulp-sized features survive the frame.
  for (int i = 0; i < 3; ++i)
    if (kind != FrameKind::planar || i < 2) f.t[i] = rng.between(0, 1) ? rng.between(-32, 32) : 0;
  permute_axes(rng, f);
  return f;
}

std::optional<TrianglePair> apply_exactly(const Frame& f, const TrianglePair& pair) {
  TrianglePair out = pair;
  for (Triangle* t : {&out.t1, &out.t2})
    for (auto& v : t->v) {
      V3 w;
      for (int i = 0; i < 3; ++i) {
        double acc = f.t[i];
        for (int j = 0; j < 3; ++j) {
          double p;
          if (!mul_exact(f.m[i][j], v[j], p) || !add_exact(acc, p, acc)) return std::nullopt;
        }
        w[i] = acc;
      }
      v = w;
    }
  return out;
}

}  // namespace tritri::corpus
