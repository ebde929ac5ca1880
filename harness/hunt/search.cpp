#include "harness/hunt/search.hpp"

#include "cases/generator/corpus.hpp"
#include "cases/generator/exact_pairs.hpp"
#include "cases/generator/shapes.hpp"
#include "cases/generator/variants.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace tritri::hunt {

std::string_view to_string(Transform t) {
  constexpr std::array<std::string_view, static_cast<std::size_t>(Transform::kCount)> names = {
      "none", "swap", "vertex_order", "axis_permutation", "scale", "translation", "float"};
  return names[static_cast<std::size_t>(t)];
}

std::string_view to_string(Source s) {
  constexpr std::array<std::string_view, static_cast<std::size_t>(Source::kCount)> names = {
      "corpus", "shapes", "grid", "dyadic", "perturbed", "walk"};
  return names[static_cast<std::size_t>(s)];
}

namespace {

using exact_pairs::GenRng;
using V = Vec3<double>;

// The six vertex orders of a triangle, the identity first.
constexpr int kOrders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

Triangle reordered(const Triangle& t, int order) {
  return {{t[kOrders[order][0]], t[kOrders[order][1]], t[kOrders[order][2]]}};
}

// A signed axis permutation that is not the identity: the same geometry, mirrored or turned.
TrianglePair axis_permuted(TrianglePair p, Rng& rng) {
  const int order = static_cast<int>(rng.integer(0, 5));
  const int signs = static_cast<int>(rng.integer(order == 0 ? 1 : 0, 7));
  for (Triangle* t : {&p.t1, &p.t2})
    for (auto& v : t->v) {
      const V was = v;
      for (int axis = 0; axis < 3; ++axis) v[axis] = (signs >> axis & 1 ? -1.0 : 1.0) * was[kOrders[order][axis]];
    }
  return p;
}

}  // namespace

std::optional<TrianglePair> transformed(const TrianglePair& pair, Transform t, Rng& rng) {
  switch (t) {
    case Transform::none: return pair;
    case Transform::swap: return swapped(pair);
    case Transform::vertex_order: {
      const int a = static_cast<int>(rng.integer(0, 5));
      const int b = static_cast<int>(rng.integer(a == 0 ? 1 : 0, 5));
      return TrianglePair{reordered(pair.t1, a), reordered(pair.t2, b)};
    }
    case Transform::axis_permutation: return axis_permuted(pair, rng);
    case Transform::scale: {
      const int k = rng.nonzero_between(-40, 40);
      return corpus::scaled_exactly(pair, k);
    }
    case Transform::translation: {
      const double step = std::ldexp(1.0, rng.between(-10, 30));
      V offset;
      do {
        for (int axis = 0; axis < 3; ++axis) offset[axis] = step * rng.between(-1, 1);
      } while (offset.isZero());
      return corpus::translated_exactly(pair, offset);
    }
    case Transform::to_float: return cast<double>(cast<float>(pair));
    case Transform::kCount: break;
  }
  return std::nullopt;
}

namespace {

TrianglePair corpus_pair(Rng& rng) {
  const auto& families = corpus::families();
  const corpus::Family& family = families[static_cast<std::size_t>(rng.integer(0, static_cast<std::int64_t>(families.size()) - 1))];
  const auto configs = static_cast<std::int64_t>(family.configs.size());
  const corpus::Config& config = family.configs[static_cast<std::size_t>(rng.integer(0, configs - 1))];
  return corpus::build_construction(family, config, rng).pair;
}

TrianglePair shapes_pair(Rng& rng) {
  switch (rng.integer(0, 2)) {
    case 0: return shapes::scatter_pair(rng);
    case 1: return shapes::near_pair(rng);
    default: return shapes::coplanar_pair(rng);
  }
}

// Small integers over 2^e, some coordinates then moved a float ulp: contact stays representable
// on a grid finer than the integers, and every coordinate is a float.
TrianglePair dyadic_pair(GenRng& rng) {
  TrianglePair p = exact_pairs::small_int_pair(rng, rng.between(2, 8));
  const int e = rng.between(1, 6);
  for (Triangle* t : {&p.t1, &p.t2})
    for (auto& v : t->v)
      for (int axis = 0; axis < 3; ++axis) {
        double& x = v[axis];
        x = std::ldexp(x, -e);
        if (rng.integer(0, 3) == 0) x = std::nextafter(static_cast<float>(x), rng.coin() ? 1.0f : -1.0f);
      }
  return p;
}

TrianglePair drawn_pair(GenRng& rng, Source source) {
  switch (source) {
    case Source::corpus: return corpus_pair(rng);
    case Source::shapes: return shapes_pair(rng);
    case Source::grid: return exact_pairs::small_int_pair(rng, rng.between(1, 6));
    case Source::dyadic: return dyadic_pair(rng);
    default: return exact_pairs::perturbed(rng.coin() ? corpus_pair(rng) : exact_pairs::small_int_pair(rng, 4), rng);
  }
}

Source drawn_source(Rng& rng) {
  const auto u = rng.integer(0, 99);
  if (u < 40) return Source::corpus;
  if (u < 50) return Source::shapes;
  if (u < 70) return Source::grid;
  return u < 85 ? Source::dyadic : Source::perturbed;
}


// ---- walks

struct Walk {
  TrianglePair start;
  V direction;
  int moving = 3;     // 0..2: that vertex of T2 moves; 3: all of T2
  double sign = 1.0;  // the side the decision flips on
  bool decision = false;  // at the start, and at every step of bits `lo`
  std::uint64_t lo = 0, hi = 0;  // bit patterns of the step (non-negative doubles order as their bits)
  bool flips = false;
};

TrianglePair walked(const Walk& w, double step) {
  TrianglePair p = w.start;
  for (int k = 0; k < 3; ++k)
    if (w.moving == 3 || w.moving == k) p.t2[k] += step * w.direction;
  return p;
}

double step_of(const Walk& w, std::uint64_t bits) { return w.sign * std::bit_cast<double>(bits); }

Walk drawn_walk(GenRng& rng) {
  Walk w;
  w.start = rng.coin() ? corpus_pair(rng) : exact_pairs::small_int_pair(rng, 4);
  w.moving = rng.between(0, 3);
  if (rng.coin()) {
    w.direction = (w.start.t1[1] - w.start.t1[0]).cross(w.start.t1[2] - w.start.t1[0]);
  } else {
    do w.direction = shapes::integer_vector(rng, 3);
    while (w.direction.isZero());
  }
  if (w.direction.isZero() || !w.direction.allFinite()) w.direction = V(0, 0, 1);
  return w;
}

// The steps tried for a flip of the decision, smallest first, on both sides.
constexpr double kProbes[] = {0x1p-40, 0x1p-24, 0x1p-12, 0x1p-6, 0x1p-2, 1.0, 4.0};

void find_flips(std::vector<Walk>& walks, const OverlapDecider& decide) {
  std::vector<TrianglePair> pairs;
  for (const Walk& w : walks) pairs.push_back(w.start);
  const std::vector<bool> at_start = decide(pairs);
  pairs.clear();
  for (const Walk& w : walks)
    for (double probe : kProbes)
      for (double sign : {1.0, -1.0}) pairs.push_back(walked(w, sign * probe));
  const std::vector<bool> probed = decide(pairs);
  std::size_t k = 0;
  for (std::size_t i = 0; i < walks.size(); ++i) {
    Walk& w = walks[i];
    w.decision = at_start[i];
    for (double probe : kProbes)
      for (double sign : {1.0, -1.0}) {
        if (!w.flips && probed[k] != w.decision) {
          w.flips = true;
          w.sign = sign;
          w.hi = std::bit_cast<std::uint64_t>(probe);
        }
        ++k;
      }
  }
}

}  // namespace

std::vector<TrianglePair> walk_pairs(GenRng& rng, std::size_t count, const OverlapDecider& decide) {
  std::vector<Walk> walks;
  for (std::size_t i = 0; i < count; ++i) walks.push_back(drawn_walk(rng));
  if (walks.empty()) return {};
  find_flips(walks, decide);
  for (;;) {  // at most 64 rounds: each halves every open interval of bit patterns
    std::vector<std::size_t> open;
    std::vector<TrianglePair> mids;
    for (std::size_t i = 0; i < walks.size(); ++i)
      if (walks[i].flips && walks[i].hi - walks[i].lo > 1) {
        open.push_back(i);
        mids.push_back(walked(walks[i], step_of(walks[i], walks[i].lo + (walks[i].hi - walks[i].lo) / 2)));
      }
    if (open.empty()) break;
    const std::vector<bool> decided = decide(mids);
    for (std::size_t j = 0; j < open.size(); ++j) {
      Walk& w = walks[open[j]];
      const std::uint64_t mid = w.lo + (w.hi - w.lo) / 2;
      (decided[j] == w.decision ? w.lo : w.hi) = mid;
    }
  }
  std::vector<TrianglePair> out;
  for (const Walk& w : walks)
    if (w.flips) {
      out.push_back(walked(w, step_of(w, w.lo)));
      out.push_back(walked(w, step_of(w, w.hi)));
    }
  return out;
}

std::vector<Candidate> search_batch(std::uint64_t seed, std::uint64_t index, std::size_t size,
                                    const OverlapDecider& decide) {
  GenRng rng(stream_seed(seed, "hunt", index));
  std::vector<Candidate> out;
  out.reserve(size);
  if (size < 2) throw std::invalid_argument("hunt: a search batch holds at least 2 candidates");
  const std::size_t bases = (size + 1) / 2, walks = std::min<std::size_t>(bases / 16, 64);
  for (const TrianglePair& p : walk_pairs(rng, walks, decide)) out.push_back({p, 0, Transform::none, Source::walk});
  while (out.size() < bases) {
    const Source source = drawn_source(rng);
    out.push_back({drawn_pair(rng, source), 0, Transform::none, source});
  }
  for (std::size_t b = 0, n = out.size(); b < n; ++b) out[b].base = static_cast<std::uint32_t>(b);
  for (std::size_t b = 0; out.size() < size; b = (b + 1) % bases) {
    const auto t = static_cast<Transform>(rng.integer(1, static_cast<int>(Transform::kCount) - 1));
    if (auto p = transformed(out[b].pair, t, rng)) out.push_back({*p, out[b].base, t, out[b].source});
  }
  return out;
}

}  // namespace tritri::hunt
