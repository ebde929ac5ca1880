// The hunt finds a planted bug, its witnesses still fail after shrinking and are small, no
// shrinking step changes the oracle's verdict, it finds nothing in the exact tests, the exact
// transformations keep the verdict, and a seed with a budget in pairs gives the same hunt twice.
#include "harness/hunt/hunt.hpp"
#include "harness/hunt/output.hpp"

#include "cases/label.hpp"
#include "cases/oracle/oracle.hpp"
#include "harness/check/check.hpp"
#include "harness/check/merge.hpp"
#include "cases/util/input_error.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <vector>

namespace tritri::hunt {
namespace {

const Algorithm& exact() { return *registry().find("exact"); }

// A planted bug: exact's verdict, except that triangles that only touch are said not to meet.
bool misses_touching(Relation r) { return r != Relation::cross && r != Relation::coplanar_overlap; }

void planted_batch(const TrianglePair* pairs, std::size_t n, Overlap* out) {
  std::vector<RelationAnswer> truth(n);
  exact().batch<Level::relation>()(pairs, n, truth.data());
  for (std::size_t i = 0; i < n; ++i) out[i] = misses_touching(truth[i].relation) ? Overlap::no : Overlap::yes;
}

const Algorithm& planted() {
  static const Algorithm* a = [] {
    Algorithm p({.name = "planted-misses-touching", .summary = "exact, but touching is no contact"});
    p.set_batch<Level::overlap>(Scalar::double_, planted_batch);
    return &add_external_algorithm(std::move(p));
  }();
  return *a;
}

HuntOptions short_hunt(std::size_t pairs) {
  HuntOptions o;
  o.pairs = pairs;
  o.batch = 2048;
  return o;
}

// A short hunt whose witnesses get a few shrinking rounds: for the tests of what does not depend on
// how far they shrink (each round runs the algorithm in an isolated child, which under the
// sanitizers is most of these tests' time).
HuntOptions short_hunt_little_shrinking(std::size_t pairs) {
  HuntOptions o = short_hunt(pairs);
  o.shrink_rounds = 4;
  return o;
}

TEST(Hunt, FindsAPlantedBugAndEveryWitnessStillFailsAfterShrinking) {
  const HuntResult r = run_hunt(planted(), short_hunt(8192));
  ASSERT_GT(r.failures, 0u);
  ASSERT_FALSE(r.groups.empty());
  EXPECT_TRUE(r.exact_oracle_disagreements.empty());
  std::vector<double> bits;
  for (const Group& g : r.groups) {
    const OracleRecord truth = oracle_label(g.witness);
    EXPECT_EQ(to_string(truth.relation), g.signature.oracle) << g.signature.key();
    EXPECT_TRUE(truth.overlap) << "the planted bug only says no wrongly: " << g.signature.key();
    EXPECT_TRUE(misses_touching(truth.relation));
    EXPECT_EQ(g.signature.answer, "0");
    EXPECT_LE(pair_cost(g.witness), pair_cost(g.found));
    bits.push_back(witness_size(g.witness).max_significant_bits);
  }
  std::sort(bits.begin(), bits.end());
  EXPECT_LE(bits[bits.size() / 2], 8) << "the median witness has at most 8 significant bits per coordinate";
}

TEST(Hunt, NoShrinkingStepChangesTheOraclesVerdict) {
  // A touching pair in general position, with coordinates far from simple.
  using V = Vec3<double>;
  const TrianglePair start = {{{V(0.1, 0.2, 0.3), V(4.7, 0.3, 0.1), V(0.2, 5.3, 0.4)}},
                              {{V(0.1, 0.2, 0.3), V(-1.3, 2.9, 7.1), V(2.2, -1.7, 6.3)}}};
  const OracleRecord before = oracle_label(start);
  ASSERT_TRUE(before.overlap);
  ASSERT_TRUE(misses_touching(before.relation));
  const StillFails still_fails = [&](const std::vector<TrianglePair>& pairs) {
    const std::vector<Truth> truth = label_pairs(pairs);
    std::vector<Overlap> said(pairs.size());
    planted_batch(pairs.data(), pairs.size(), said.data());
    std::vector<bool> fails(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i)
      fails[i] = truth[i].relation == before.relation && (said[i] == Overlap::yes) != truth[i].overlap;
    return fails;
  };
  const Shrunk s = shrink(start, still_fails, 200);
  ASSERT_GT(s.steps, 0);
  ASSERT_EQ(s.trail.size(), static_cast<std::size_t>(s.steps));
  std::size_t cost = pair_cost(start);
  for (const TrianglePair& step : s.trail) {
    const OracleRecord now = oracle_label(step);
    EXPECT_EQ(now.relation, before.relation);
    EXPECT_EQ(now.overlap, before.overlap);
    EXPECT_LT(pair_cost(step), cost);
    cost = pair_cost(step);
  }
  EXPECT_TRUE(witness_size(s.pair).small()) << pair_cost(s.pair);
}

TEST(Hunt, TheExactTestsHaveNoFailureOnAShortHunt) {
  for (const char* name : {"exact", "cgal"}) {
    const Algorithm* a = registry().find(name);
    if (!a) continue;  // cgal is built only with CGAL's library peer
    const HuntResult r = run_hunt(*a, short_hunt(4096));
    EXPECT_EQ(r.pairs, 4096u);
    EXPECT_EQ(r.failures, 0u) << name;
    EXPECT_TRUE(r.groups.empty()) << name;
    EXPECT_TRUE(r.exact_oracle_disagreements.empty()) << name;
  }
}

TEST(Hunt, ExactTransformationsKeepTheVerdict) {
  const std::vector<Candidate> batch = search_batch(7, 0, 1024, [](const std::vector<TrianglePair>& p) {
    return std::vector<bool>(p.size(), false);
  });
  ASSERT_EQ(batch.size(), 1024u);
  std::vector<TrianglePair> pairs;
  for (const Candidate& c : batch) pairs.push_back(c.pair);
  const std::vector<Truth> truth = label_pairs(pairs);
  std::size_t checked = 0;
  for (std::size_t i = 0; i < batch.size(); ++i) {
    const Transform t = batch[i].transform;
    if (t == Transform::none || t == Transform::to_float) continue;
    EXPECT_EQ(truth[i].relation, truth[batch[i].base].relation) << to_string(t);
    ++checked;
  }
  EXPECT_GT(checked, 300u);
}

TEST(Hunt, WalksEndOnBothSidesOfTheDecision) {
  exact_pairs::GenRng rng(3);
  const OverlapDecider decide = [](const std::vector<TrianglePair>& pairs) {
    std::vector<bool> out;
    for (const Truth& t : label_pairs(pairs)) out.push_back(t.overlap);
    return out;
  };
  const std::vector<TrianglePair> ends = walk_pairs(rng, 16, decide);
  ASSERT_FALSE(ends.empty());
  ASSERT_EQ(ends.size() % 2, 0u);
  const std::vector<bool> overlap = decide(ends);
  for (std::size_t i = 0; i < ends.size(); i += 2) EXPECT_NE(overlap[i], overlap[i + 1]) << "walk " << i / 2;
}

TEST(Hunt, ASeedAndABudgetInPairsGiveTheSameHunt) {
  const HuntResult a = run_hunt(planted(), short_hunt_little_shrinking(4096));
  const HuntResult b = run_hunt(planted(), short_hunt_little_shrinking(4096));
  ASSERT_EQ(a.groups.size(), b.groups.size());
  EXPECT_EQ(a.failures, b.failures);
  for (std::size_t i = 0; i < a.groups.size(); ++i) {
    EXPECT_EQ(a.groups[i].signature.key(), b.groups[i].signature.key());
    EXPECT_EQ(a.groups[i].count, b.groups[i].count);
    EXPECT_EQ(pair_cost(a.groups[i].witness), pair_cost(b.groups[i].witness));
  }
  const nlohmann::json j = hunt_json({a}, HuntRun{});
  EXPECT_EQ(j["schema"], "tritri-hunt/1");
  EXPECT_EQ(j["algorithms"][0]["groups"].size(), a.groups.size());
}

// The shrinking's budget is asked before each round, not read from a clock here: a budget spent
// from the start leaves every witness as found, and says so; an unlimited one shrinks them.
TEST(Hunt, ASpentShrinkBudgetKeepsEachWitnessAsFoundAndSaysSo) {
  HuntOptions o = short_hunt_little_shrinking(4096);
  o.shrink_seconds = 0;
  const HuntResult cut = run_hunt(planted(), o);
  const HuntResult full = run_hunt(planted(), short_hunt_little_shrinking(4096));
  ASSERT_FALSE(cut.groups.empty());
  ASSERT_EQ(cut.groups.size(), full.groups.size());
  int shrunk = 0;
  for (std::size_t i = 0; i < cut.groups.size(); ++i) {
    const Group& g = cut.groups[i];
    EXPECT_TRUE(g.shrink_cut) << g.signature.key();
    EXPECT_EQ(g.shrink_steps, 0);
    EXPECT_EQ(pair_cost(g.witness), pair_cost(g.found));
    EXPECT_FALSE(full.groups[i].shrink_cut);
    shrunk += full.groups[i].shrink_steps > 0;
  }
  EXPECT_GT(shrunk, 0);
  const nlohmann::json j = hunt_json({cut}, HuntRun{});
  EXPECT_TRUE(j["algorithms"][0]["groups"][0]["witness"]["shrink_cut"].get<bool>());
}

TEST(Hunt, ShrinkingStopsWhenToldTimeIsUp) {
  TrianglePair start;
  const double odd[18] = {3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67};
  for (int i = 0; i < 18; ++i) coordinate(start, i) = odd[i] * 1.0009765625;  // 11 significant bits each
  const StillFails always = [](const std::vector<TrianglePair>& pairs) { return std::vector<bool>(pairs.size(), true); };
  int asked = 0;
  const Shrunk one = shrink(start, always, 64, [&asked] { return ++asked > 1; });
  EXPECT_EQ(one.steps, 1);
  EXPECT_TRUE(one.cut);
  const Shrunk all = shrink(start, always, 64);
  EXPECT_FALSE(all.cut);
  EXPECT_GT(all.steps, 1);
}

// The fields a clock writes: they differ between any two runs, sharded or not.
nlohmann::json without_clock(nlohmann::json doc) {
  for (auto& a : doc["algorithms"]) {
    for (const char* k : {"seconds", "pairs_per_second", "shrink_seconds", "first_failure_seconds"}) a.erase(k);
    for (auto& g : a["groups"]) g.erase("first_seconds");
  }
  return doc;
}

nlohmann::json sharded_hunt(std::size_t k, std::size_t n, std::size_t pairs) {
  HuntOptions o = short_hunt_little_shrinking(pairs);
  o.batch = 1024;
  HuntRun run;
  run.pairs = pairs;
  run.batch = o.batch;
  if (n > 1) {
    const auto [first, end] = take_shard(o, k, n);
    run.shard = HuntRun::Shard{k, n, first, end, pairs};
  }
  return hunt_json({run_hunt(planted(), o), run_hunt(*registry().find("moller97"), o)}, run);
}

TEST(Hunt, FourShardsMergeIntoTheOneRunButForTheClock) {
  const std::size_t pairs = 5 * 1024 + 100;  // a last batch cut short, and shards of unequal size
  const nlohmann::json whole = sharded_hunt(0, 1, pairs);
  std::vector<MergePart> parts;
  for (std::size_t k = 0; k < 4; ++k) parts.push_back({"shard-" + std::to_string(k) + ".json", sharded_hunt(k, 4, pairs)});
  std::swap(parts[0], parts[3]);  // the order given does not matter
  const nlohmann::json merged = kind_of_parts(parts).merge(parts);
  ASSERT_GT(whole["algorithms"][0]["groups"].size(), 1u);
  EXPECT_EQ(without_clock(merged).dump(1), without_clock(whole).dump(1));
  // A wrong set is refused, naming the problem.
  std::vector<MergePart> three(parts.begin(), parts.begin() + 3);
  EXPECT_THROW(kind_of_parts(three).merge(three), InputError);
  std::vector<MergePart> foreign = parts;
  foreign[1].doc["seed"] = 2;
  try {
    kind_of_parts(foreign).merge(foreign);
    ADD_FAILURE() << "merged a shard of another hunt";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("another seed"), std::string::npos) << e.what();
  }
}

TEST(Hunt, CoordinateCostCountsBits) {
  EXPECT_EQ(coordinate_cost(0), 0);
  EXPECT_EQ(coordinate_cost(1), 1);
  EXPECT_EQ(coordinate_cost(8), 4);
  EXPECT_EQ(coordinate_cost(-3), 2);
  EXPECT_EQ(coordinate_cost(0.5), 2);
  EXPECT_EQ(significant_bits(0.1), 52);  // 0.1 = m·2^e with an odd m of 52 bits
  EXPECT_EQ(significant_bits(96), 2);
}

}  // namespace
}  // namespace tritri::hunt
