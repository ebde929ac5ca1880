#include "harness/hunt/shrink.hpp"

#include "cases/generator/variants.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <climits>
#include <cstdint>
#include <limits>
#include <set>

namespace tritri::hunt {

double& coordinate(TrianglePair& pair, int index) {
  Triangle& t = index < 9 ? pair.t1 : pair.t2;
  return t[(index % 9) / 3][index % 3];
}

double coordinate(const TrianglePair& pair, int index) {
  return coordinate(const_cast<TrianglePair&>(pair), index);
}

namespace {

// |x| = m·2^e with m odd; false for 0 and non-finite x.
bool odd_form(double x, std::uint64_t& m, int& e) {
  if (x == 0 || !std::isfinite(x)) return false;
  int exponent;
  const double fraction = std::frexp(std::fabs(x), &exponent);  // in [0.5, 1)
  m = static_cast<std::uint64_t>(std::ldexp(fraction, 64 - 11));
  e = exponent - (64 - 11);
  const int zeros = std::countr_zero(m);
  m >>= zeros;
  e += zeros;
  return true;
}

// x with its significand rounded to `bits` bits (to nearest, ties to even, as the FPU does).
double with_bits(double x, int bits) {
  if (x == 0 || !std::isfinite(x)) return x;
  int exponent;
  std::frexp(x, &exponent);
  return std::ldexp(std::nearbyint(std::ldexp(x, bits - exponent)), exponent - bits);
}

template <class F>
TrianglePair each_coordinate(TrianglePair p, F f) {
  for (int i = 0; i < 18; ++i) coordinate(p, i) = f(coordinate(p, i));
  return p;
}

// Whole-pair steps: a vertex to the origin, exact scalings, snapping to a grid or to few bits.
void whole_pair_steps(const TrianglePair& p, std::vector<TrianglePair>& out) {
  for (int v = 0; v < 6; ++v) {
    const Vec3<double> origin = v < 3 ? p.t1[v] : p.t2[v - 3];
    if (origin.isZero()) continue;
    TrianglePair q = p;
    for (Triangle* t : {&q.t1, &q.t2})
      for (auto& x : t->v) x -= origin;
    out.push_back(q);
  }
  for (int k : {1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48})
    for (int sign : {-1, 1})
      if (auto q = corpus::scaled_exactly(p, sign * k)) out.push_back(*q);
  // Grids relative to the pair's largest coordinate 2^top: 2^(top - b) for b = 1, 2, ..., and the
  // integers.
  int top = INT_MIN;
  for (int i = 0; i < 18; ++i)
    if (int e; coordinate(p, i) != 0) top = std::max(top, (std::frexp(coordinate(p, i), &e), e));
  if (top == INT_MIN) return;
  std::set<int> grids = {0};
  for (int b = 1; b <= 40; ++b) grids.insert(b - top);
  for (int g : grids)
    out.push_back(each_coordinate(p, [g](double x) { return std::ldexp(std::nearbyint(std::ldexp(x, g)), -g); }));
  for (int bits = 1; bits <= 40; bits += bits < 12 ? 1 : 4)
    out.push_back(each_coordinate(p, [bits](double x) { return with_bits(x, bits); }));
}

// One coordinate at a time: zeroed, rounded to an integer, shortened, a step toward 0, or set to
// another coordinate's value (fewer distinct values).
void coordinate_steps(const TrianglePair& p, std::vector<TrianglePair>& out) {
  std::set<double> values;
  for (int i = 0; i < 18; ++i) values.insert(coordinate(p, i));
  for (int i = 0; i < 18; ++i) {
    const double x = coordinate(p, i);
    if (x == 0) continue;
    std::set<double> tries = {0.0, std::nearbyint(x), std::trunc(x), x / 2};
    for (int bits : {1, 2, 3, 4, 6, 8, 12, 16, 24, 32}) tries.insert(with_bits(x, bits));
    tries.insert(with_bits(x, std::max(1, significant_bits(x) - 1)));
    if (x == std::nearbyint(x)) tries.insert(x - std::copysign(1.0, x));
    for (double v : values)
      if (coordinate_cost(v) <= coordinate_cost(x)) tries.insert(v);
    tries.erase(x);
    for (double v : tries) {
      TrianglePair q = p;
      coordinate(q, i) = v;
      out.push_back(q);
    }
  }
}

}  // namespace

int coordinate_cost(double x) {
  std::uint64_t m;
  int e;
  if (!odd_form(x, m, e)) return x == 0 ? 0 : 2048;  // non-finite: dearer than any double
  return std::bit_width(m) + std::abs(e);
}

int significant_bits(double x) {
  std::uint64_t m;
  int e;
  return odd_form(x, m, e) ? std::bit_width(m) : 0;
}

std::size_t pair_cost(const TrianglePair& pair) {
  // In the pair's own scale: every coordinate m·2^e as the integer m·2^(e - e_min), so a pair and
  // its 2^k scaling cost the same but for the tie-breaking |e_min| / 8.
  std::uint64_t m[18];
  int e[18], lowest = 0;
  bool any = false;
  std::set<double> distinct;
  for (int i = 0; i < 18; ++i) {
    const double x = coordinate(pair, i);
    distinct.insert(x);
    if (!std::isfinite(x)) return std::numeric_limits<std::size_t>::max() / 2;
    if (!odd_form(x, m[i], e[i])) continue;
    lowest = any ? std::min(lowest, e[i]) : e[i];
    any = true;
  }
  std::size_t cost = 2 * distinct.size() + static_cast<std::size_t>(std::abs(lowest) / 8);
  for (int i = 0; i < 18; ++i)
    if (coordinate(pair, i) != 0) cost += static_cast<std::size_t>(std::bit_width(m[i]) + e[i] - lowest);
  return cost;
}

std::vector<TrianglePair> simpler_pairs(const TrianglePair& pair) {
  std::vector<TrianglePair> out;
  whole_pair_steps(pair, out);
  coordinate_steps(pair, out);
  return out;
}

Shrunk shrink(const TrianglePair& start, const StillFails& still_fails, int max_rounds,
              const std::function<bool()>& out_of_time) {
  Shrunk s;
  s.pair = start;
  std::size_t cost = pair_cost(start);
  for (int round = 0; round < max_rounds; ++round) {
    if (out_of_time && out_of_time()) {
      s.cut = true;
      break;
    }
    std::vector<TrianglePair> tries;
    for (const TrianglePair& q : simpler_pairs(s.pair))
      if (pair_cost(q) < cost && q.t1[0].allFinite() && q.t1[1].allFinite() && q.t1[2].allFinite() &&
          q.t2[0].allFinite() && q.t2[1].allFinite() && q.t2[2].allFinite())
        tries.push_back(q);
    if (tries.empty()) break;
    const std::vector<bool> fails = still_fails(tries);
    std::size_t best = tries.size();
    for (std::size_t i = 0; i < tries.size(); ++i)
      if (fails[i] && (best == tries.size() || pair_cost(tries[i]) < pair_cost(tries[best]))) best = i;
    if (best == tries.size()) break;
    s.pair = tries[best];
    s.trail.push_back(s.pair);
    cost = pair_cost(s.pair);
    ++s.steps;
  }
  return s;
}

WitnessSize witness_size(const TrianglePair& pair) {
  WitnessSize w;
  std::set<double> distinct;
  for (int i = 0; i < 18; ++i) {
    const double x = coordinate(pair, i);
    distinct.insert(x);
    w.max_significant_bits = std::max(w.max_significant_bits, significant_bits(x));
    w.max_abs = std::max(w.max_abs, std::fabs(x));
    w.integers = w.integers && x == std::nearbyint(x);
  }
  w.distinct = distinct.size();
  w.cost = pair_cost(pair);
  return w;
}

}  // namespace tritri::hunt
