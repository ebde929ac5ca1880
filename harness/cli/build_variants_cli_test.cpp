// The v3fma build (NAME@v3fma, algorithms/api/builds.hpp) as a user meets it: NAME@v3fma beside each
// port in list, check, bench and diff; none for the library peers; one line saying why when it
// is not loaded. The tests that need the module loaded skip on a CPU that cannot run it.
#include "harness/testing/tritri_runner.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>
#include <map>
#include <string>

namespace {

using tritri::testing_support::Outcome;
Outcome tritri(const std::string& arguments) { return tritri::testing_support::run_tritri(arguments); }

const std::string kBuiltin = std::string(TRITRI_SOURCE_DIR) + "/cases/builtin.cases";
constexpr const char* kNotLoaded = "is not loaded";

std::size_t occurrences(const std::string& text, const std::string& word) {
  std::size_t n = 0;
  for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

// `tritri list --tsv`, or a skip when this CPU (or build) has no v3fma module to load.
#define LIST_OR_SKIP(listing)                                                                   \
  const Outcome listing = tritri("list --tsv");                                                 \
  ASSERT_EQ(listing.status, 0) << listing.out;                                                  \
  if (listing.out.find(kNotLoaded) != std::string::npos || listing.out.find("@v3fma") == std::string::npos) \
    GTEST_SKIP() << "no v3fma build here: " << listing.out.substr(0, listing.out.find('\n'))

TEST(BuildVariants, EveryPortHasAV3fmaBuildInItsFolderAndNoPeerHasOne) {
  LIST_OR_SKIP(r);
  for (const char* row : {"\nmoller97@v3fma\t", "\nguigue03-segment@v3fma\t", "\nyuhe13@v3fma\t", "\nexact@v3fma\t"})
    EXPECT_NE(r.out.find(row), std::string::npos) << row;
  EXPECT_NE(r.out.find("\tmoller97\n"), std::string::npos);
  for (const char* peer : {"fcl@v3fma", "cgal@v3fma", "open3d@v3fma", "ode@v3fma", "bullet-gimpact@v3fma"})
    EXPECT_EQ(r.out.find(peer), std::string::npos) << peer;
}

TEST(BuildVariants, TurnedOffTheyAreAbsentAndTritriSaysWhyOnce) {
#if !defined(TRITRI_V3FMA_BUILT)
  GTEST_SKIP() << "this build has no v3fma module to turn off (configured with TRITRI_V3FMA=OFF)";
#endif
  ::setenv("TRITRI_V3FMA", "off", 1);
  const Outcome r = tritri("list --tsv");
  ::unsetenv("TRITRI_V3FMA");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(r.out.find("@v3fma\t"), std::string::npos);
  EXPECT_EQ(occurrences(r.out, kNotLoaded), 1u) << r.out;
  EXPECT_NE(r.out.find("TRITRI_V3FMA=off"), std::string::npos) << r.out;
}

TEST(BuildVariants, CheckAndBenchTakeTheirNames) {
  LIST_OR_SKIP(listing);
  Outcome r = tritri("check --algo moller97@v3fma " + kBuiltin);
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("moller97@v3fma  (all)"), std::string::npos) << r.out;
  r = tritri("bench --quick --list --no-cache --pool 1024 --algo moller97,moller97@v3fma --workload ratio:0.5");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("\nmoller97@v3fma/overlap/ratio:0.50/call\n"), std::string::npos) << r.out;  // the default mode
  const std::string json = std::string(TRITRI_BINARY_DIR) + "/scratch-v3fma-bench.json";
  r = tritri("bench --quick --no-cache --no-ops --pool 1024 --repetitions 1 --algo moller97,moller97@v3fma "
             "--workload ratio:0.5 --json " + json);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto doc = nlohmann::json::parse(std::ifstream(json));
  bool timed = false;
  for (const auto& result : doc["tritri"]["results"])
    timed = timed || (result["algorithm"] == "moller97@v3fma" && result["ns_per_pair_median"].get<double>() > 0);
  EXPECT_TRUE(timed) << doc["tritri"]["results"].dump();
}

// diff --oracle against check: for each family, the errors diff finds on each side of the cases
// where the two builds differ account exactly for the difference of their false positives (and
// negatives) in check's tallies. Two paths through the harness, one answer.
TEST(BuildVariants, DiffWithTheOracleAgreesWithCheck) {
  LIST_OR_SKIP(listing);
  const std::string dir = std::string(TRITRI_BINARY_DIR) + "/scratch-v3fma-corpus";
  ASSERT_EQ(tritri("corpus --quick --out " + dir).status, 0);
  const std::string files = dir + "/*.cases";
  const std::string diff_json = dir + "-diff.json", check_json = dir + "-check.json";
  Outcome r = tritri("diff --oracle --pair moller97=moller97@v3fma --json " + diff_json + " " + files);
  ASSERT_LE(r.status, 1) << r.out;
  r = tritri("check --quiet --algo moller97,moller97@v3fma --json " + check_json + " " + files);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto diff = nlohmann::json::parse(std::ifstream(diff_json))["pairs"][0];
  const auto check = nlohmann::json::parse(std::ifstream(check_json));
  std::map<std::string, long> fp_change, fn_change;  // per family: moller97@v3fma's minus moller97's
  for (const auto& t : check["tallies"]) {
    const long sign = t["algorithm"] == "moller97" ? -1 : 1;
    fp_change[t["family"]] += sign * t["false_positives"].get<long>();
    fn_change[t["family"]] += sign * t["false_negatives"].get<long>();
  }
  EXPECT_TRUE(diff["oracle"].get<bool>());
  std::size_t judged = 0;
  for (const auto& f : diff["families"]) {
    const long a_fp = f["a_fp"], a_fn = f["a_fn"], b_fp = f["b_fp"], b_fn = f["b_fn"];
    // Möller answers yes or no: where the builds differ, exactly one of them is wrong.
    EXPECT_EQ(a_fp + a_fn + b_fp + b_fn, f["overlap_differ"].get<long>()) << f.dump();
    EXPECT_EQ(b_fp - a_fp, fp_change[f["family"]]) << f.dump();
    EXPECT_EQ(b_fn - a_fn, fn_change[f["family"]]) << f.dump();
    judged += f["overlap_differ"].get<std::size_t>();
  }
  EXPECT_EQ(judged, diff["overlap_differ"].get<std::size_t>());
}

}  // namespace
