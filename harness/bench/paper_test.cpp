// Tests of the paper workload (workloads/paper.hpp): each driver's pool has the shape its paper's
// driver streams (order, count, ratio, distribution), the modifiers change the one thing they
// name, Shen's data files are read as Performance.cpp reads them, and the pools time the stages.
#include "harness/bench/workload.hpp"
#include "harness/bench/workloads/paper.hpp"
#include "harness/bench/workloads/ratio.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

namespace tritri::bench {
namespace {

WorkloadInput input_with(std::string authors_code = "") {
  WorkloadInput in;
  in.pool = {256, 7};
  in.authors_code = std::move(authors_code);
  return in;
}

Pool one_pool(const std::string& value, const WorkloadInput& input) {
  const Workload* w = find_workload("paper");
  EXPECT_NE(w, nullptr);
  WorkloadPools built = w->build({w->parse_value(value)}, input);
  EXPECT_EQ(built.pools.size(), 1u) << value;
  return built.pools.empty() ? Pool{} : built.pools.front();
}

TEST(PaperWorkload, ValuesAreCanonicalAndEachDriverTakesOnlyItsModifiers) {
  const Workload* w = find_workload("paper");
  ASSERT_NE(w, nullptr);
  EXPECT_FALSE(w->in_default_set({}));
  EXPECT_TRUE(w->times_levels_and_stages());
  EXPECT_EQ(w->parse_value("shen03-drawn/ours/r:0.5/shuffled/n:100"), "shen03-drawn/n:100/r:0.50/shuffled/ours");
  EXPECT_EQ(w->parse_value("tropp06"), "tropp06");
  EXPECT_THROW(w->parse_value("yuhe13/n:100"), std::invalid_argument);     // 40 pairs, as published
  EXPECT_THROW(w->parse_value("tropp06/r:0.5"), std::invalid_argument);    // the grid sets its ratio
  EXPECT_THROW(w->parse_value("shen03/n:0"), std::invalid_argument);
  EXPECT_THROW(w->parse_value("shen03/r:2"), std::invalid_argument);
  EXPECT_THROW(w->parse_value("moller97"), std::invalid_argument);
  EXPECT_THROW(w->parse_value("shen03/sorted"), std::invalid_argument);
}

TEST(PaperWorkload, ShenWithoutTheAuthorsCodeIsSkippedWithOneLine) {
  const Workload* w = find_workload("paper");
  const WorkloadPools built = w->build({"shen03"}, input_with());
  EXPECT_TRUE(built.pools.empty());
  ASSERT_EQ(built.context.size(), 1u);
  EXPECT_EQ(built.context[0].first, "paper shen03");
  EXPECT_NE(built.context[0].second.find("skipped: needs the authors' data files"), std::string::npos);
  EXPECT_EQ(w->cache_identity(input_with()), "");
}

// A jgt-code layout with two small data files: pair k of each file has T1 at x = k and T2 at
// x = 100 + k (the file's first triangle), so the reading order shows.
std::string fake_checkout(int pairs) {
  const auto dir = std::filesystem::temp_directory_path() / ("tritri-paper-test-" + std::to_string(::getpid()));
  const auto data = dir / "Volume_08/Number_1/Shen2003/tri_tri_test/data";
  std::filesystem::create_directories(data);
  for (const char* name : {"intersected.txt", "separated.txt"}) {
    const bool meet = std::string(name) == "intersected.txt";
    std::ofstream out(data / name);
    for (int k = 0; k < pairs; ++k) {
      const double a = 100 + k, b = k;  // the file's first triangle (v), then the second (u)
      out << a << " 0.5 0.5\n" << a + 1 << " 0.5 0.5\n" << a << " 1.5 0.5\n";
      if (meet) out << a + 0.25 << " 0.75 0\n" << a + 0.25 << " 0.75 1\n" << a + 0.5 << " 1 0.5\n";
      else out << b << " 0.5 0.5\n" << b + 1 << " 0.5 0.5\n" << b << " 1.5 0.5\n";
    }
  }
  return dir.string();
}

TEST(PaperWorkload, ShenReadsTheDataFilesAsPerformanceCppDoes) {
  const std::string root = fake_checkout(6);
  const WorkloadInput input = input_with(root);
  const Pool p = one_pool("shen03/n:10/r:0.5", input);
  ASSERT_EQ(p.size(), 10u);
  EXPECT_EQ(p.intersecting(), 5u);
  for (std::size_t i = 0; i < 10; ++i) {
    EXPECT_EQ(p.truth[i].overlap, i < 5) << i;  // intersected.txt first, in file order
    EXPECT_EQ(p.pairs[i].t2[0][0], 100.0 + static_cast<double>(i % 5)) << i;  // its second triangle is T1
  }
  EXPECT_NE(find_workload("paper")->cache_identity(input).find("intersected.txt="), std::string::npos);
  EXPECT_THROW(one_pool("shen03/n:20/r:0.5", input), std::invalid_argument);  // 10 needed, 6 in each file
  std::filesystem::remove_all(root);
}

TEST(PaperWorkload, ShenDrawnIsIntersectingFirstInFloatWithSixDecimals) {
  const Pool p = one_pool("shen03-drawn/n:200", input_with());
  ASSERT_EQ(p.size(), 200u);
  EXPECT_EQ(p.intersecting(), 20u);  // the driver's ratio, 0.1
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p.truth[i].overlap, i < 20) << i;
    for (const Triangle* t : {&p.pairs[i].t1, &p.pairs[i].t2})
      for (const auto& v : t->v)
        for (int k = 0; k < 3; ++k) {
          EXPECT_EQ(v[k], static_cast<double>(static_cast<float>(v[k]))) << i;
          EXPECT_NEAR(v[k] * 1e6, std::round(v[k] * 1e6), 0.1);
          EXPECT_TRUE(v[k] >= 0 && v[k] <= 1);
        }
  }
  const Pool shuffled = one_pool("shen03-drawn/n:200/shuffled", input_with());
  EXPECT_EQ(shuffled.intersecting(), 20u);
  std::size_t first_twenty = 0;
  for (std::size_t i = 0; i < 20; ++i) first_twenty += shuffled.truth[i].overlap ? 1 : 0;
  EXPECT_LT(first_twenty, 20u);  // no longer sorted by outcome
  const Pool ours = one_pool("shen03-drawn/n:200/ours", input_with());
  EXPECT_EQ(ours.intersecting(), 20u);
  EXPECT_TRUE(ours.truth[19].overlap && !ours.truth[20].overlap);
}

TEST(PaperWorkload, TroppHoldsEachBForTenThousandAsAndShiftsItsEdgesByAsVertex) {
  const Pool p = one_pool("tropp06/n:10002", input_with());
  ASSERT_EQ(p.size(), 10002u);
  for (std::size_t k : {std::size_t{0}, std::size_t{1}, std::size_t{9999}, std::size_t{10000}, std::size_t{10001}}) {
    EXPECT_EQ(p.pairs[k].t1[0], p.pairs[k % 10000].t1[0]) << k;  // A_i, i = k mod 10,000
    EXPECT_EQ(p.pairs[k].t2[0], p.pairs[k < 10000 ? 0 : 10000].t2[0]) << k;  // B_j held
  }
  EXPECT_NE(p.pairs[0].t2[0], p.pairs[10000].t2[0]);
  // A in the unit cube; B's other vertices reach outside it (Q_j0 + Q_j1 − P_j0).
  bool outside = false;
  for (const auto& pair : p.pairs) {
    for (const auto& v : pair.t1.v)
      for (int k = 0; k < 3; ++k) EXPECT_TRUE(v[k] >= 0 && v[k] < 1);
    for (const auto& v : pair.t2.v)
      for (int k = 0; k < 3; ++k) outside = outside || v[k] < 0 || v[k] >= 1;
  }
  EXPECT_TRUE(outside);
  // /ours keeps the driver's sequence of answers with other pairs
  const Pool ours = one_pool("tropp06/n:10002/ours", input_with());
  ASSERT_EQ(ours.size(), p.size());
  for (std::size_t k = 0; k < p.size(); ++k) ASSERT_EQ(ours.truth[k].overlap, p.truth[k].overlap) << k;
  EXPECT_NE(ours.pairs[0].t1[0], p.pairs[0].t1[0]);
}

TEST(PaperWorkload, YuHeIsFortyPairsOfTheRebuiltSuite) {
  const Pool p = one_pool("yuhe13", input_with());
  ASSERT_EQ(p.size(), 40u);
  std::set<std::vector<double>> distinct;
  for (const auto& pair : p.pairs) {
    std::vector<double> bytes;
    for (const Triangle* t : {&pair.t1, &pair.t2})
      for (const auto& v : t->v) bytes.insert(bytes.end(), {v[0], v[1], v[2]});
    distinct.insert(bytes);
    EXPECT_EQ(pair.t1[1][0], 8.0);  // the paper's fixed A: A1 = (8, 0, 0)
  }
  EXPECT_GE(distinct.size(), 39u);  // the rebuilt suite repeats at most one configuration
}

TEST(PaperWorkload, ItsPoolsTimeTheLevelsAndTheStages) {
  const Planned planned = build_pools(select_workloads({"paper:yuhe13", "paper:yuhe13/shuffled"}, {}), input_with());
  ASSERT_EQ(planned.pools.size(), 2u);
  for (const PlannedPool& p : planned.pools) {
    EXPECT_TRUE(p.levels);
    EXPECT_TRUE(p.stages);
    EXPECT_EQ(p.pool.workload, "paper");
  }
  EXPECT_EQ(planned.pools[1].pool.value, "yuhe13/shuffled");
}

}  // namespace
}  // namespace tritri::bench
