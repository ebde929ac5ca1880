// Unit tests of the batch's route choice (detail/route_choice.hpp; algorithms/exact/README.md,
// "The batch's route: lanes or one pair at a time"): the chooser fed made-up costs, so that its
// decisions are known, and the batch driven through each route, whose answers must be the
// one-pair path's whatever the chooser decides.
#include "algorithms/exact/exact.hpp"
#include "cases/generator/exact_pairs.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

using namespace tritri;
using namespace exact_pairs;
namespace ex = tritri::exact;
using ex::detail::BatchRoute;
using ex::detail::RouteChooser;

namespace {

// Runs `pairs` pairs through `c` in chunks of `chunk`, each route costing its ticks per pair;
// `share`: the lanes' share of pairs reaching the scalar pass. Returns the pairs each route ran.
struct Ran {
  std::uint64_t lanes = 0, one_pair = 0;
};
Ran feed(RouteChooser& c, std::uint64_t pairs, std::uint64_t chunk, double lanes_cost, double one_pair_cost,
         double share) {
  Ran ran;
  for (std::uint64_t done = 0; done < pairs; done += chunk) {
    const BatchRoute r = c.next();
    const double cost = r == BatchRoute::lanes ? lanes_cost : one_pair_cost;
    const auto scalar = static_cast<std::uint64_t>(share * static_cast<double>(chunk));
    c.record(r, chunk, static_cast<std::uint64_t>(cost * static_cast<double>(chunk)), r == BatchRoute::lanes ? scalar : 0);
    (r == BatchRoute::lanes ? ran.lanes : ran.one_pair) += chunk;
  }
  return ran;
}

}  // namespace

// Lanes far ahead and few pairs to the scalar pass (a ratio pool): the one-pair route is never
// tried, however long the run. Fails with the gate left out (the try would run).
TEST(RouteChoice, LanesAheadWithFewScalarPairsNeverTryTheOnePairRoute) {
  RouteChooser c;
  const Ran ran = feed(c, 1u << 24, 256, 50.0, 100.0, 0.02);
  EXPECT_EQ(ran.one_pair, 0u);
  EXPECT_EQ(c.current(), BatchRoute::lanes);
}

// Many pairs to the scalar pass and the one-pair route cheaper (slivers on a core that slows down
// for wide instructions): the first try takes over, and afterwards the lanes are tried only on
// short stretches, each loss doubling the gap, so they run a small share of the pairs. Fails
// with the comparison reversed or without the doubling.
TEST(RouteChoice, ACheaperOnePairRouteTakesOverAndTheLanesAreTriedRarely) {
  RouteChooser c;
  const std::uint64_t total = 1u << 25;
  const Ran ran = feed(c, total, 256, 400.0, 300.0, 0.4);
  EXPECT_EQ(c.current(), BatchRoute::one_pair);
  // before the first try (kMinGap) and one try per gap after it: a few percent at most
  EXPECT_LT(ran.lanes, total / 50) << ran.lanes;
  EXPECT_GT(ran.one_pair, total - total / 50);
}

// Many pairs to the scalar pass but the lanes cheaper (a core that keeps its clock): the one-pair
// route is tried, loses, and its tries become rarer. Fails if a losing try switched the route.
TEST(RouteChoice, ALosingTryKeepsTheRouteAndComesLess) {
  RouteChooser c;
  const std::uint64_t total = 1u << 25;
  const Ran ran = feed(c, total, 256, 300.0, 400.0, 0.4);
  EXPECT_EQ(c.current(), BatchRoute::lanes);
  EXPECT_GT(ran.one_pair, 0u);
  // one try of kTryOnePair per kMaxGap once the gap has grown: 16,384 in 278,528, 5.9 %
  const double most = static_cast<double>(RouteChooser::kTryOnePair) /
                      static_cast<double>(RouteChooser::kMaxGap + RouteChooser::kTryOnePair);
  EXPECT_LT(static_cast<double>(ran.one_pair), 1.05 * most * static_cast<double>(total)) << ran.one_pair;
}

// The pairs change: after a long run where the one-pair route won, and right after one of its
// lanes tries (so that the next try is a whole gap away), pairs on which the lanes are far ahead
// (the one-pair route's cost per pair moves) bring the lanes back within the drift's 1,024 pairs
// and a lanes try, not after the gap. Fails without the drift test.
TEST(RouteChoice, OtherPairsAreMeasuredAfresh) {
  RouteChooser c;
  feed(c, 1u << 25, 256, 400.0, 300.0, 0.4);
  ASSERT_EQ(c.current(), BatchRoute::one_pair);
  while (c.next() == c.current()) feed(c, 256, 256, 400.0, 300.0, 0.4);  // to the next try
  while (c.next() != c.current()) feed(c, 256, 256, 400.0, 300.0, 0.4);  // through it
  ASSERT_EQ(c.current(), BatchRoute::one_pair);
  feed(c, 1024 + RouteChooser::kTryLanes + 512, 256, 50.0, 100.0, 0.02);
  EXPECT_EQ(c.current(), BatchRoute::lanes);
}

// Other pairs on which the current route costs what it did (one pair at a time about as dear),
// but the lanes now cost less: no drift to see, so the lanes come back at the next try, within
// the longest gap and a try's length. Fails with a longer kMaxGap than the feed (the try would
// not come) or without the gap's cap.
TEST(RouteChoice, TheOtherRouteIsRetriedWithinTheLongestGap) {
  RouteChooser c;
  feed(c, 1u << 25, 256, 400.0, 300.0, 0.4);
  ASSERT_EQ(c.current(), BatchRoute::one_pair);
  feed(c, RouteChooser::kMaxGap + RouteChooser::kTryLanes + 256, 256, 200.0, 300.0, 0.1);
  EXPECT_EQ(c.current(), BatchRoute::lanes);
}

// A batch cut into large chunks (4,096 pairs, more than half of a lanes try): the try is still
// timed (on its last chunk) and can win. Fails if a try timed on its second half alone saw none.
TEST(RouteChoice, LargeChunksStillTimeTheirTries) {
  RouteChooser c;
  feed(c, 1u << 22, 4096, 400.0, 300.0, 0.4);
  ASSERT_EQ(c.current(), BatchRoute::one_pair);
  feed(c, 1u << 22, 4096, 200.0, 300.0, 0.4);
  EXPECT_EQ(c.current(), BatchRoute::lanes);
}

// The batch on each route, through a chooser pinned to it, and on whatever the thread's chooser
// picks: every answer the one-pair path's, at both levels and on every ISA; the one-pair route
// counted as `direct` and never as pending or scalar, the lanes' as before. Pieces of 100 pairs
// (timed chunks) and of 7 (below kMinPairs: run on the current route untimed). Fails if a route's
// chunk wrote answers at the wrong offset or skipped its tail.
TEST(RouteChoice, EveryRouteGivesTheOnePairAnswers) {
  GenRng r(47);
  std::vector<TrianglePair> pairs;
  for (int i = 0; i < 5000; ++i) pairs.push_back(i % 3 ? random_pair(r) : small_int_pair(r, 6));
  std::vector<Overlap> want_o;
  std::vector<RelationAnswer> want_r;
  for (const TrianglePair& p : pairs) want_o.push_back(ex::overlap(p)), want_r.push_back(ex::relation(p));
  for (ex::Isa isa : kIsas) {
    if (!ex::supported(isa) || isa == ex::Isa::scalar) continue;
    SCOPED_TRACE(ex::to_string(isa));
    for (BatchRoute route : {BatchRoute::lanes, BatchRoute::one_pair}) {
      SCOPED_TRACE(route == BatchRoute::lanes ? "lanes" : "one pair");
      RouteChooser c = RouteChooser::pinned(route);
      std::vector<Overlap> ov(pairs.size(), Overlap::unsupported);
      std::vector<RelationAnswer> rel(pairs.size(), RelationAnswer{Relation::unknown, Dimension::unknown});
      ex::reset_stats();
      for (std::size_t at = 0; at < pairs.size(); at += 107) {
        const std::size_t n = std::min<std::size_t>(107, pairs.size() - at), first = std::min<std::size_t>(n, 100);
        ex::detail::batch<false>(isa, pairs.data() + at, first, ov.data() + at, &c);
        ex::detail::batch<false>(isa, pairs.data() + at + first, n - first, ov.data() + at + first, &c);
      }
      const ex::Stats st = ex::stats();
      ex::detail::batch<true>(isa, pairs.data(), pairs.size(), rel.data(), &c);
      for (std::size_t k = 0; k < pairs.size(); ++k) {
        ASSERT_EQ(ov[k], want_o[k]) << k;
        ASSERT_EQ(rel[k].relation, want_r[k].relation) << k;
        ASSERT_EQ(rel[k].dimension, want_r[k].dimension) << k;
      }
      EXPECT_EQ(st.pairs, pairs.size());
      EXPECT_EQ(st.direct, route == BatchRoute::one_pair ? pairs.size() : 0u);
      if (route == BatchRoute::one_pair) EXPECT_EQ(st.pending, 0u);
      else EXPECT_GT(st.pending, 0u);
      EXPECT_EQ(st.filter + st.shared + st.grid + st.filtered + st.declined, st.direct + st.scalar);
    }
  }
  // the public entries, on whatever route the thread's chooser takes: the same answers
  std::vector<Overlap> ov(pairs.size());
  std::vector<RelationAnswer> rel(pairs.size());
  ex::overlap_batch(pairs.data(), pairs.size(), ov.data());
  ex::relation_batch(pairs.data(), pairs.size(), rel.data());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    ASSERT_EQ(ov[k], want_o[k]) << k;
    ASSERT_EQ(rel[k].relation, want_r[k].relation) << k;
  }
}
