// --group-by: a case is counted once in each grouping it is in, under the labels' values, and
// the tallies of a grouping add up to what the family tallies say of the same cases.
#include "harness/check/check.hpp"
#include "harness/check/grouping.hpp"
#include "tritri/add_level.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace tritri {
namespace {

bool always_yes(const TrianglePair&) { return true; }

// Two variants of one base construction and a third case without the tilt label.
std::vector<Case> labelled_cases() {
  std::istringstream in(
      "fam.cfg.0.sym-a 0 0 0 1 0 0 0 1 0  0 0 1 1 0 1 0 1 1 family=fam subsuite=symmetry tilt=2^-3\n"
      "fam.cfg.0.sym-b 0 0 0 1 0 0 0 1 0  0 0 0 1 0 0 0 1 0 family=fam subsuite=symmetry tilt=2^-3\n"
      "fam.cfg.1.scale 0 0 0 1 0 0 0 1 0  0 0 2 1 0 2 0 1 2 family=fam subsuite=scale\n");
  return read_cases(in, "groups.cases");
}

TEST(Grouping, ParsesKeysAndFixedValues) {
  const Grouping g = parse_grouping("subsuite=symmetry,@base");
  ASSERT_EQ(g.keys.size(), 2u);
  EXPECT_EQ(g.keys[0].key, "subsuite");
  EXPECT_EQ(g.keys[0].value, std::optional<std::string>("symmetry"));
  EXPECT_EQ(g.keys[1].key, "@base");
  EXPECT_FALSE(g.keys[1].value.has_value());
  EXPECT_THROW(parse_grouping("subsuite,,tilt"), std::invalid_argument);
}

TEST(Grouping, NamesTheGroupsACaseIsIn) {
  const auto c = labelled_cases();
  EXPECT_EQ(groups_of(c[0], {}), std::vector<std::string>{"fam"});
  const std::vector<Grouping> g = {parse_grouping("subsuite=symmetry,@base"), parse_grouping("subsuite,tilt")};
  EXPECT_EQ(groups_of(c[0], g), (std::vector<std::string>{"subsuite=symmetry @base=fam.cfg.0",
                                                          "subsuite=symmetry tilt=2^-3"}));
  EXPECT_TRUE(groups_of(c[2], g).empty());  // not a symmetry variant, and no tilt label
}

TEST(Grouping, CountsACaseOnceInEachOfItsGroups) {
  const auto c = labelled_cases();
  const auto oracle = label_cases(c);
  Algorithm yes;
  yes.name = "yes";
  yes.set_batch<Level::overlap>(Scalar::double_, overlap_batch<&always_yes>);
  const CheckResult by_family = run_check({&yes}, c, oracle);
  const CheckResult grouped = run_check({&yes}, c, oracle, {}, {parse_grouping("subsuite"), parse_grouping("tilt")});
  EXPECT_EQ(grouped.groups,
            (std::vector<std::string>{"subsuite=symmetry", "tilt=2^-3", "subsuite=scale"}));
  const Tally& all = by_family.tallies.at({"yes", "fam"});
  const Tally& sym = grouped.tallies.at({"yes", "subsuite=symmetry"});
  const Tally& scale = grouped.tallies.at({"yes", "subsuite=scale"});
  const Tally& tilt = grouped.tallies.at({"yes", "tilt=2^-3"});
  EXPECT_EQ(sym.cases + scale.cases, all.cases);
  EXPECT_EQ(sym.false_positives + scale.false_positives, all.false_positives);
  EXPECT_EQ(tilt.cases, 2u);
  EXPECT_EQ(tilt.false_positives, sym.false_positives);
  EXPECT_EQ(grouped.failures.size(), by_family.failures.size());  // failures are per case, not per group
}

}  // namespace
}  // namespace tritri
