#include "cases/generator/variants.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

namespace tritri::corpus {
namespace {

using V3 = Vec3<double>;

constexpr std::array<std::array<int, 3>, 6> kOrders = {
    {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};

std::string order_name(const std::array<int, 3>& o) {
  return {char('0' + o[0]), char('0' + o[1]), char('0' + o[2])};
}

Triangle reordered(const Triangle& t, const std::array<int, 3>& o) { return Triangle{{t[o[0]], t[o[1]], t[o[2]]}}; }

// A copy of `base` renamed and relabelled as one variant.
Case variant_of(const Case& base, const std::string& suffix, const char* variant, const std::string& transform,
                bool exact) {
  Case c;
  c.name = base.name + "." + suffix;
  c.pair = base.pair;
  for (const auto& [k, v] : base.labels)
    if (exact || k != "expect") c.labels.emplace_back(k, v);
  c.set_label("subsuite", variant);
  c.set_label("transform", transform);
  return c;
}

std::string exponent_text(int k) { return "2^" + std::to_string(k); }

template <class F>
bool map_coordinates(TrianglePair& pair, F f) {
  for (Triangle* t : {&pair.t1, &pair.t2})
    for (auto& v : t->v)
      for (int i = 0; i < 3; ++i)
        if (!f(v[i], i)) return false;
  return true;
}

V3 random_direction(Rng& rng) {
  for (;;) {
    const double x = 2 * rng.unit() - 1, y = 2 * rng.unit() - 1, z = 2 * rng.unit() - 1;
    const V3 d(x, y, z);
    const double n = d.norm();
    if (n > 0.1 && n <= 1) return d / n;
  }
}

double pair_size(const TrianglePair& p) {
  V3 lo = p.t1[0], hi = p.t1[0];
  for (const Triangle* t : {&p.t1, &p.t2})
    for (const auto& v : t->v) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  return (hi - lo).maxCoeff();
}

}  // namespace

std::optional<TrianglePair> scaled_exactly(TrianglePair p, int k) {
  const bool exact = map_coordinates(p, [k](double& x, int) {
    const double y = std::ldexp(x, k);
    if (x != 0 && (!std::isnormal(y) || std::ldexp(y, -k) != x)) return false;
    x = y;
    return true;
  });
  return exact ? std::optional(p) : std::nullopt;
}

std::optional<TrianglePair> translated_exactly(TrianglePair p, const Vec3<double>& offset) {
  const bool exact = map_coordinates(p, [&](double& x, int i) {
    // Knuth's TwoSum: the error term is exactly what the sum lost.
    const double t = offset[i], y = x + t, bb = y - x;
    if ((x - (y - bb)) + (t - bb) != 0) return false;
    x = y;
    return true;
  });
  return exact ? std::optional(p) : std::nullopt;
}

void add_symmetry_variants(const Case& base, int count, Rng& rng, std::vector<Case>& out) {
  std::vector<int> chosen(72);
  for (int i = 0; i < 72; ++i) chosen[i] = i;
  // A partial shuffle of all but the identity picks the sample.
  for (int i = 1; i < count && i < 72; ++i) std::swap(chosen[i], chosen[rng.between(i, 71)]);
  chosen.resize(std::min(count, 72));
  std::sort(chosen.begin(), chosen.end());
  for (int index : chosen) {
    const auto& o1 = kOrders[index / 12];
    const auto& o2 = kOrders[index / 2 % 6];
    const bool swap = index % 2 == 1;
    const std::string name = "sym-" + order_name(o1) + "-" + order_name(o2) + (swap ? "-ba" : "-ab");
    Case c = variant_of(base, name, "symmetry", name, true);
    const Triangle a = reordered(base.pair.t1, o1), b = reordered(base.pair.t2, o2);
    c.pair = swap ? TrianglePair{b, a} : TrianglePair{a, b};
    out.push_back(std::move(c));
  }
}

void add_scale_variants(const Case& base, int count, Rng& rng, std::vector<Case>& out) {
  for (int attempt = 0, made = 0; made < count && attempt < 8 * count; ++attempt) {
    const int k = rng.nonzero_between(-40, 40);
    const std::optional<TrianglePair> p = scaled_exactly(base.pair, k);
    const std::string name = "scale-" + exponent_text(k);
    if (!p || std::any_of(out.begin(), out.end(), [&](const Case& c) { return c.name == base.name + "." + name; }))
      continue;
    Case c = variant_of(base, name, "scale", exponent_text(k), true);
    c.pair = *p;
    out.push_back(std::move(c));
    ++made;
  }
}

void add_translate_variants(const Case& base, int count, Rng& rng, std::vector<Case>& out) {
  for (int attempt = 0, made = 0; made < count && attempt < 8 * count; ++attempt) {
    const int k = rng.nonzero_between(-40, 40);
    int s[3];
    do
      for (int& si : s) si = rng.between(-1, 1);
    while (s[0] == 0 && s[1] == 0 && s[2] == 0);
    const double step = std::ldexp(1.0, k);
    const std::optional<TrianglePair> p = translated_exactly(base.pair, V3(s[0] * step, s[1] * step, s[2] * step));
    if (!p) continue;
    const std::string transform = exponent_text(k) + "*(" + std::to_string(s[0]) + "," + std::to_string(s[1]) +
                                  "," + std::to_string(s[2]) + ")";
    Case c = variant_of(base, "translate-" + std::to_string(made), "translate", transform, true);
    c.pair = *p;
    out.push_back(std::move(c));
    ++made;
  }
}

void add_rotate_variants(const Case& base, int count, Rng& rng, std::vector<Case>& out) {
  for (int i = 0; i < count; ++i) {
    // A uniform random unit quaternion: a uniform point of the 4-ball, normalised.
    double q[4], n2;
    do {
      n2 = 0;
      for (double& x : q) x = 2 * rng.unit() - 1, n2 += x * x;
    } while (n2 < 0.01 || n2 > 1);
    const Eigen::Quaterniond rotation(q[0], q[1], q[2], q[3]);
    const Eigen::Matrix3d m = rotation.normalized().toRotationMatrix();
    Case c = variant_of(base, "rotate-" + std::to_string(i), "rotate", "random", false);
    for (Triangle* t : {&c.pair.t1, &c.pair.t2})
      for (auto& v : t->v) v = m * v;
    out.push_back(std::move(c));
  }
}

void add_perturb_variants(const Case& base, Rng& rng, std::vector<Case>& out) {
  const V3 direction = random_direction(rng);
  const double size = pair_size(base.pair);
  for (int e = -16; e <= -2; e += 2)
    for (int sign : {1, -1}) {
      char text[32];
      std::snprintf(text, sizeof text, "%s1e%d", sign > 0 ? "+" : "-", e);
      Case c = variant_of(base, std::string("perturb") + (sign > 0 ? "-p" : "-m") + "1e" + std::to_string(e),
                          "perturb", text, false);
      c.pair.t2[0] += (sign * std::pow(10.0, e) * size) * direction;
      out.push_back(std::move(c));
    }
}

}  // namespace tritri::corpus
