// compare: the U test gives the exact p-values one can work out by hand, a known injected
// slowdown is significant, an unchanged rerun is not, check results diff per family, and a file
// of a version compare does not read, or without a key it needs, is refused by file and key.
#include "harness/check/compare.hpp"

#include "cases/util/random.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <functional>
#include <fstream>
#include <sstream>

namespace tritri {
namespace {

TEST(MannWhitney, ExactPValuesOfSeparatedSamples) {
  // U = 0: only 1 of the C(6,3) = 20 interleavings is as extreme on each side
  auto t = mann_whitney({1, 2, 3}, {4, 5, 6});
  EXPECT_TRUE(t.exact);
  EXPECT_EQ(t.u, 0);
  EXPECT_DOUBLE_EQ(t.p_value, 2.0 / 20.0);
  // nine against nine, fully separated: 2 / C(18,9)
  std::vector<double> a, b;
  for (int i = 0; i < 9; ++i) {
    a.push_back(i);
    b.push_back(100 + i);
  }
  t = mann_whitney(a, b);
  EXPECT_NEAR(t.p_value, 2.0 / 48620.0, 1e-15);
  EXPECT_DOUBLE_EQ(mann_whitney(b, a).p_value, t.p_value);  // two-sided: symmetric
}

TEST(MannWhitney, InterleavedSamplesAreNotSignificant) {
  const auto t = mann_whitney({1, 3, 5, 7, 9, 11, 13, 15, 17}, {2, 4, 6, 8, 10, 12, 14, 16, 18});
  EXPECT_GT(t.p_value, 0.5);
  // U = 1 of 0..9 for 3 vs 3? {1,2,4} vs {3,5,6}: one pair (4 > 3): P(U <= 1) = 2/20
  EXPECT_DOUBLE_EQ(mann_whitney({1, 2, 4}, {3, 5, 6}).p_value, 2 * 2.0 / 20.0);
}

TEST(MannWhitney, TiesUseTheNormalApproximation) {
  const auto t = mann_whitney({1, 1, 2, 2, 3, 3, 4, 4}, {1, 2, 2, 3, 3, 4, 4, 5});
  EXPECT_FALSE(t.exact);
  EXPECT_GT(t.p_value, 0.2);
  EXPECT_LE(t.p_value, 1.0);
}

// A Google Benchmark result with 9 repetitions per benchmark, ns per item scaled by `factor`,
// each with noise of 1% (the standard deviation of a uniform spread of ±1.7%); with a "tritri"
// section when one is given, as `tritri bench` writes.
std::string bench_file(const std::string& name, double factor, unsigned seed,
                       const std::vector<std::string>& benches = {"moller97/overlap/ratio:0.5", "guigue03/overlap/ratio:0.5"},
                       const nlohmann::json& tritri = nullptr) {
  Rng rng(seed);
  auto noise = [&] { return rng.uniform(1 - 0.0173, 1 + 0.0173); };
  nlohmann::json doc;
  doc["context"] = {{"date", "x"}};
  if (!tritri.is_null()) doc["tritri"] = tritri;
  doc["benchmarks"] = nlohmann::json::array();
  for (const std::string& bench : benches)
    for (int r = 0; r < 9; ++r) {
      const double ns = (bench[0] == 'm' ? 30.0 : 25.0) * factor * noise();
      doc["benchmarks"].push_back({{"name", bench}, {"run_name", bench}, {"run_type", "iteration"},
                                   {"repetition_index", r}, {"real_time", ns * 65536}, {"time_unit", "ns"},
                                   {"items_per_second", 1e9 / ns}});
    }
  doc["benchmarks"].push_back({{"name", "moller97/overlap/ratio:0.5_median"}, {"run_name", "moller97/overlap/ratio:0.5"},
                               {"run_type", "aggregate"}, {"aggregate_name", "median"}, {"real_time", 1.0}});
  const std::string path = std::string(TRITRI_BINARY_DIR) + "/" + name;
  std::ofstream(path) << doc.dump();
  return path;
}

TEST(CompareBenchmarks, AnInjectedSlowdownIsSignificantAndARerunIsNot) {
  const auto base = bench_file("base.json", 1.0, 1);
  const auto rerun = bench_file("rerun.json", 1.0, 2);
  const auto slow = bench_file("slow.json", 1.2, 3);
  for (const auto& c : compare_benchmarks(base, slow, {})) {
    EXPECT_TRUE(c.significant) << c.name;
    EXPECT_NEAR(c.ratio, 1.2, 0.03) << c.name;
    EXPECT_EQ(c.repetitions_a, 9u);  // the aggregate row is not a repetition
  }
  for (const auto& c : compare_benchmarks(base, rerun, {})) {
    EXPECT_FALSE(c.counts) << c.name << " p=" << c.test.p_value;
    EXPECT_NEAR(c.ratio, 1.0, 0.03);
  }
  std::ostringstream out;
  EXPECT_TRUE(print_comparison(out, base, slow, {}));
  EXPECT_NE(out.str().find("slower (significant)"), std::string::npos) << out.str();
  const std::string mean_label = "geometric mean of B/A over 2 benchmarks: ";
  const auto at = out.str().find(mean_label);
  ASSERT_NE(at, std::string::npos) << out.str();
  EXPECT_NEAR(std::stod(out.str().substr(at + mean_label.size())), 1.2, 0.02);
  std::ostringstream same;
  EXPECT_FALSE(print_comparison(same, base, rerun, {}));
}

// A check result as `tritri check --json` writes it, with the keys compare reads; `edit` may
// spoil it.
std::string check_file(const std::string& name, int false_negatives,
                       const std::function<void(nlohmann::json&)>& edit = {}) {
  nlohmann::json doc = {{"schema", "tritri-check/2"}};
  doc["tallies"] = {{{"algorithm", "moller97"}, {"family", "shared-edge"}, {"cases", 10}, {"false_positives", 0},
                     {"false_negatives", false_negatives}, {"misclassified", nullptr}, {"unsupported", 0},
                     {"crashes", 0}, {"timeouts", 0}},
                    {{"algorithm", "moller97"}, {"family", "random"}, {"cases", 10}, {"false_positives", 1},
                     {"false_negatives", 0}, {"misclassified", nullptr}, {"unsupported", 0}, {"crashes", 0},
                     {"timeouts", 0}}};
  if (edit) edit(doc);
  const std::string path = std::string(TRITRI_BINARY_DIR) + "/" + name;
  std::ofstream(path) << doc.dump();
  return path;
}

// The message print_comparison throws on, or "" when it does not.
std::string refusal(const std::string& a, const std::string& b) {
  std::ostringstream out;
  try {
    print_comparison(out, a, b, {});
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(CompareBenchmarks, ASignificantButTinyDriftDoesNotCount) {
  const auto base = bench_file("drift-base.json", 1.0, 4);
  const auto drift = bench_file("drift.json", 1.008, 5);  // 0.8% slower, noise 1%: may test significant
  std::ostringstream out;
  EXPECT_FALSE(print_comparison(out, base, drift, {}));
  for (const auto& c : compare_benchmarks(base, drift, {})) EXPECT_FALSE(c.counts) << c.name;
  CompareOptions strict;
  strict.min_change = 0;
  const auto slow = bench_file("drift-slow.json", 1.2, 6);
  for (const auto& c : compare_benchmarks(base, slow, strict)) EXPECT_TRUE(c.counts) << c.name;
}

TEST(CompareChecks, ReportsTheFamiliesWhoseErrorsChanged) {
  const auto a = check_file("check-a.json", 0), b = check_file("check-b.json", 2);
  std::ostringstream out;
  EXPECT_TRUE(print_comparison(out, a, b, {}));
  EXPECT_NE(out.str().find("moller97 / shared-edge:  FN 0 -> 2 (+2)"), std::string::npos) << out.str();
  EXPECT_EQ(out.str().find("random"), std::string::npos) << out.str();
  std::ostringstream back;
  EXPECT_FALSE(print_comparison(back, b, a, {}));  // fewer errors is not worse
}

// A bench file from before the mode was an axis (its "tritri" section has no schema) timed every
// benchmark in batch mode: it is compared with the batch mode of a newer file, never with call.
TEST(CompareBenchmarks, AFileFromBeforeTheModesIsComparedWithTheBatchModeOnly) {
  const auto old = bench_file("modes-old.json", 1.0, 7, {"moller97/overlap/ratio:0.50"}, {{"schema", "tritri-bench/1"}});
  const auto now = bench_file("modes-new.json", 1.0, 8,
                              {"moller97/overlap/ratio:0.50/call", "moller97/overlap/ratio:0.50/batch"},
                              {{"schema", "tritri-bench/2"}});
  const auto rows = compare_benchmarks(old, now, {});
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].name, "moller97/overlap/ratio:0.50/batch");
  // A plain Google Benchmark file (no "tritri" section) keeps its names.
  const auto plain = bench_file("modes-plain.json", 1.0, 9, {"moller97/overlap/ratio:0.50"});
  ASSERT_EQ(compare_benchmarks(plain, old, {}).size(), 0u);
}

TEST(CompareChecks, RefusesFilesItCannotCompare) {
  const auto a = check_file("refuse-check.json", 0);
  const auto bench = bench_file("refuse-bench.json", 1.0, 1);
  std::ostringstream out;
  EXPECT_THROW(print_comparison(out, a, bench, {}), std::runtime_error);
  const std::string junk = std::string(TRITRI_BINARY_DIR) + "/refuse-junk.json";
  std::ofstream(junk) << "{not json";
  EXPECT_THROW(print_comparison(out, junk, a, {}), std::runtime_error);
}

TEST(CompareChecks, NamesTheFileAndKeyOfAMissingCount) {
  const auto good = check_file("key-good.json", 0);
  const auto renamed = check_file("key-renamed.json", 0, [](nlohmann::json& doc) {
    doc["tallies"][1]["fn"] = doc["tallies"][1]["false_negatives"];
    doc["tallies"][1].erase("false_negatives");
  });
  EXPECT_EQ(refusal(good, renamed), renamed + ": missing required key tallies[1].false_negatives");
  const auto no_tallies = check_file("key-no-tallies.json", 0, [](nlohmann::json& doc) { doc.erase("tallies"); });
  EXPECT_EQ(refusal(no_tallies, good), no_tallies + ": missing required key tallies");
}

TEST(CompareChecks, RefusesASchemaVersionItDoesNotRead) {
  const auto good = check_file("version-good.json", 0);
  const auto newer = check_file("version-4.json", 0, [](nlohmann::json& doc) { doc["schema"] = "tritri-check/4"; });
  EXPECT_EQ(refusal(good, newer), newer + ": schema is \"tritri-check/4\"; tritri compare reads tritri-check/2 or tritri-check/3");
}

TEST(CompareBenchmarks, ChecksTheTritriSectionsVersionAndEachBenchmarksTime) {
  const auto plain = bench_file("plain.json", 1.0, 7);  // Google Benchmark's JSON alone: no version to check
  EXPECT_EQ(refusal(plain, plain), "");
  const auto tagged = [&](const std::string& name, const nlohmann::json& tritri) {
    std::ifstream in(plain);
    nlohmann::json doc = nlohmann::json::parse(in);
    doc["tritri"] = tritri;
    const std::string path = std::string(TRITRI_BINARY_DIR) + "/" + name;
    std::ofstream(path) << doc.dump();
    return path;
  };
  EXPECT_EQ(refusal(tagged("bench-v1.json", {{"schema", "tritri-bench/1"}}), plain), "");
  const auto old = tagged("bench-unversioned.json", {{"reference", "moller97"}});
  EXPECT_EQ(refusal(old, plain), old + ": missing required key tritri.schema");
  EXPECT_EQ(refusal(tagged("bench-v2.json", {{"schema", "tritri-bench/2"}}), plain), "");
  const auto v3 = tagged("bench-v3.json", {{"schema", "tritri-bench/3"}});
  EXPECT_EQ(refusal(plain, v3),
            v3 + ": tritri.schema is \"tritri-bench/3\"; tritri compare reads tritri-bench/1 or tritri-bench/2");
  std::ifstream in(plain);
  nlohmann::json doc = nlohmann::json::parse(in);
  doc["benchmarks"][2].erase("real_time");
  doc["benchmarks"][2].erase("items_per_second");
  const std::string no_time = std::string(TRITRI_BINARY_DIR) + "/bench-no-time.json";
  std::ofstream(no_time) << doc.dump();
  EXPECT_EQ(refusal(plain, no_time), no_time + ": missing required key benchmarks[2].real_time");
}

}  // namespace
}  // namespace tritri
