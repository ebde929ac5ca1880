// Pairs on which a port's counting instantiation must answer exactly as its double one: random
// pairs in general position, pairs on a small integer grid (exact contacts, where the last bit
// decides an answer), and the built-in cases. No zero-area triangle.
#pragma once

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"
#include "tritri/counting.hpp"

#include <gtest/gtest.h>

#include <random>
#include <tuple>
#include <utility>
#include <vector>

namespace tritri::test_support {

struct CountingPairs {
  std::vector<TrianglePair> general;   // coordinates uniform in [-1, 1]
  std::vector<TrianglePair> singular;  // integer grid [-2, 2]^3, and the built-in cases
};

inline CountingPairs counting_pairs(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> real(-1, 1);
  std::uniform_int_distribution<int> grid(-2, 2);
  CountingPairs out;
  while (out.general.size() < 300 || out.singular.size() < 300) {
    const bool on_grid = out.singular.size() < out.general.size();
    TrianglePair p;
    for (auto* t : {&p.t1, &p.t2})
      for (int i = 0; i < 3; ++i)
        (*t)[i] = on_grid ? Vec3<double>(grid(rng), grid(rng), grid(rng)) : Vec3<double>(real(rng), real(rng), real(rng));
    if (!has_degenerate_triangle(p)) (on_grid ? out.singular : out.general).push_back(p);
  }
  for (const Case& c : builtin_cases())
    if (!has_degenerate_triangle(c.pair)) out.singular.push_back(c.pair);
  return out;
}

// The scalar of a PairT<T>, for generic lambdas that instantiate a port on it.
template <class P>
struct pair_scalar;
template <class T>
struct pair_scalar<PairT<T>> {
  using type = T;
};
template <class P>
using scalar_of = typename pair_scalar<std::decay_t<P>>::type;

template <class A>
bool same_answer(const A& a, const A& b) {
  return a == b;
}
inline bool same_answer(const RelationAnswer& a, const RelationAnswer& b) {
  return a.relation == b.relation && a.dimension == b.dimension;
}
// Endpoints within a few ulps: they are constructions, not decisions.
inline bool same_answer(const SegmentAnswer& a, const SegmentAnswer& b) {
  auto close = [](const Vec3<double>& x, const Vec3<double>& y) { return (x - y).norm() <= 1e-9 * (1 + x.norm()); };
  return a.kind == b.kind && close(a.p, b.p) && close(a.q, b.q);
}

// A port's counting instantiation must answer exactly as its double one, on singular pairs as
// on general ones: Counted's arithmetic, the order of Eigen's sums included, is double's.
// `answers` is a generic lambda taking a PairT<T> and returning a std::tuple of the port's
// answers (one per variant and level); it is called on each pair in double and in Counted.
template <class Answers>
void expect_counted_matches_double(unsigned seed, Answers answers) {
  const CountingPairs pairs = counting_pairs(seed);
  int disagreements = 0;
  auto check = [&](const TrianglePair& pair) {
    const auto in_double = answers(pair);
    const auto in_counted = answers(cast<Counted>(pair));
    constexpr std::size_t kNone = ~std::size_t{0};
    std::size_t differs = kNone;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((differs == kNone && !same_answer(std::get<I>(in_double), std::get<I>(in_counted)) ? void(differs = I) : void()), ...);
    }(std::make_index_sequence<std::tuple_size_v<decltype(in_double)>>{});
    if (differs == kNone) return;
    if (++disagreements <= 10) {
      Case c;
      c.name = "counted";
      c.pair = pair;
      ADD_FAILURE() << "answer " << differs << " of the tuple differs between double and Counted on\n"
                    << format_case(c, NumberStyle::hex);
    }
  };
  for (const TrianglePair& p : pairs.general) check(p);
  for (const TrianglePair& p : pairs.singular) check(p);
  ::testing::Test::RecordProperty("disagreements", disagreements);
  EXPECT_EQ(disagreements, 0);
}

}  // namespace tritri::test_support
