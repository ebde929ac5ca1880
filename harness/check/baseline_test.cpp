// Every registered algorithm, on the checked-in case files and on the quick corpus, disagrees
// with the oracle exactly as its folder's expected-failures.tsv records: a new disagreement
// fails (a regression), and so does a recorded one that no longer occurs (the baseline is stale:
// re-record it and say why). To re-record, write the quick corpus to a directory and check on
// the same inputs:
//   tritri corpus --quick --out /tmp/quick
//   tritri check --algo NAME --write-baseline algorithms/FOLDER/expected-failures.tsv
//       cases/builtin.cases cases/yuhe13.cases cases/sabharwal15.cases /tmp/quick/*.cases
// (one command; every algorithm of the folder in --algo, since they share the file).
#include "harness/check/check.hpp"
#include "harness/check/check_output.hpp"
#include "cases/generator/corpus.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace tritri {
namespace {

std::vector<std::string> checked_in_case_files() {
  const std::string cases = std::string(TRITRI_SOURCE_DIR) + "/cases/";
  return {cases + "builtin.cases", cases + "yuhe13.cases", cases + "sabharwal15.cases"};
}

const std::vector<Case>& all_cases() {
  static const std::vector<Case> cases = [] {
    std::vector<Case> all;
    for (const auto& file : checked_in_case_files())
      for (auto& c : read_case_file(file)) all.push_back(std::move(c));
    // The singular configurations, generated rather than checked in: `tritri corpus --quick`
    // with its default seed gives the same cases.
    for (auto& c : corpus::generate_corpus(corpus::quick_options())) all.push_back(std::move(c));
    return all;
  }();
  return cases;
}

const std::vector<OracleRecord>& all_labels() {
  static const std::vector<OracleRecord> labels = label_cases(all_cases());
  return labels;
}

std::string describe(const std::vector<BaselineRow>& rows) {
  std::string out;
  for (const auto& [a, c, l, ans, exp] : rows)
    out += "  " + a + "\t" + c + "\t" + l + "\t" + ans + "\t" + exp + "\n";
  return out;
}

class Baseline : public testing::TestWithParam<std::string> {};

TEST_P(Baseline, DisagreementsMatchTheRecordedOnes) {
  const Algorithm* algorithm = registry().find(GetParam());
  ASSERT_NE(algorithm, nullptr);
#if defined(__SANITIZE_ADDRESS__)
  // Which products a build (NAME@v3fma) fuses into FMAs is the optimiser's choice: the recorded
  // answers are the release build's, and the instrumented build optimises differently.
  if (!algorithm->build.empty()) GTEST_SKIP() << "the " << algorithm->build << " baseline is the release build's";
#endif
  const auto path = std::filesystem::path(TRITRI_SOURCE_DIR) / "algorithms" / algorithm->folder /
                    "expected-failures.tsv";
  ASSERT_TRUE(std::filesystem::exists(path)) << "every algorithm folder records its disagreements in " << path;
  const auto recorded = read_baseline(path.string());
  const CheckResult result = run_check({algorithm}, all_cases(), all_labels());
  const auto comparison = compare_with_baseline(recorded, result);
  EXPECT_TRUE(comparison.new_failures.empty())
      << "new disagreements with the oracle:\n" << describe(comparison.new_failures);
  EXPECT_TRUE(comparison.fixed.empty())
      << "recorded disagreements that no longer occur (re-record the baseline):\n" << describe(comparison.fixed);
}

std::vector<std::string> algorithm_names() {
  std::vector<std::string> names;
  for (const auto& a : registry().all()) names.push_back(a.name);
  return names;
}

std::string test_name(const testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(EveryAlgorithm, Baseline, testing::ValuesIn(algorithm_names()), test_name);

}  // namespace
}  // namespace tritri
