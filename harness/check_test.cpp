// check counts what it should: a wrong algorithm is caught, and baselines see new and fixed
// disagreements.
#include "check.hpp"
#include "check_output.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace tritri {
namespace {

bool always_yes(const TrianglePair&) { return true; }
bool always_no(const TrianglePair&) { return false; }
RelationAnswer always_cross(const TrianglePair&) { return answer_with(Relation::cross); }

Algorithm fake(std::string name, OverlapBatch overlap, RelationBatch relation = nullptr) {
  Algorithm a;
  a.name = std::move(name);
  a.overlap = overlap;
  a.relation = relation;
  return a;
}

const std::vector<Case>& cases() {
  static const auto c = read_case_file(std::string(TRITRI_SOURCE_DIR) + "/cases/builtin.cases");
  return c;
}
const std::vector<OracleRecord>& labels() {
  static const auto l = label_cases(cases());
  return l;
}

Tally total(const CheckResult& r, const std::string& algorithm) {
  Tally t;
  for (const auto& [key, tally] : r.tallies) {
    if (key.first != algorithm) continue;
    t.cases += tally.cases;
    t.false_positives += tally.false_positives;
    t.false_negatives += tally.false_negatives;
    t.misclassified += tally.misclassified;
    t.unsupported += tally.unsupported;
  }
  return t;
}

TEST(Check, CountsFalsePositivesAndNegativesOfAWrongAlgorithm) {
  std::size_t meeting = 0;
  for (const auto& l : labels()) meeting += l.overlap;
  const Algorithm yes = fake("yes", overlap_batch<&always_yes>), no = fake("no", overlap_batch<&always_no>);
  const CheckResult r = run_check({&yes, &no}, cases(), labels());
  EXPECT_EQ(total(r, "yes").cases, cases().size());
  EXPECT_EQ(total(r, "yes").false_positives, cases().size() - meeting);
  EXPECT_EQ(total(r, "yes").false_negatives, 0u);
  EXPECT_EQ(total(r, "no").false_negatives, meeting);
  EXPECT_EQ(total(r, "no").false_positives, 0u);
  EXPECT_EQ(r.failures.size(), cases().size());  // each case is wrong for exactly one of them
}

TEST(Check, ScoresRelationsAndDerivesOverlapFromThem) {
  const Algorithm cross = fake("cross", nullptr, relation_batch<&always_cross>);
  const CheckResult r = run_check({&cross}, cases(), labels());
  std::size_t crossing = 0, meeting = 0;
  for (const auto& l : labels()) {
    crossing += l.relation == Relation::cross;
    meeting += l.overlap;
  }
  EXPECT_EQ(total(r, "cross").misclassified, cases().size() - crossing);
  EXPECT_EQ(total(r, "cross").false_positives, cases().size() - meeting);
}

TEST(Check, TalliesPerFamily) {
  const Algorithm yes = fake("yes", overlap_batch<&always_yes>);
  const CheckResult r = run_check({&yes}, cases(), labels());
  EXPECT_EQ(r.tallies.at({"yes", "parallel"}).cases, 5u);
  EXPECT_EQ(r.tallies.at({"yes", "parallel"}).false_positives, 5u);
  EXPECT_NE(std::find(r.families.begin(), r.families.end(), "coplanar-disjoint"), r.families.end());
}

TEST(Check, DegenerateInputIsNotPassedToAlgorithmsThatRefuseIt) {
  Case c = parse_case_line("needle 0 0 0 4 0 0 0 4 0  1 1 -1 1 1 0 1 1 1", "mem", 1);
  const std::vector<Case> one{c};
  const auto l = label_cases(one);
  Algorithm yes = fake("yes", overlap_batch<&always_yes>);
  CheckResult r = run_check({&yes}, one, l);
  EXPECT_EQ(total(r, "yes").unsupported, 1u);
  EXPECT_EQ(total(r, "yes").false_positives + total(r, "yes").false_negatives, 0u);
  yes.accepts_degenerate = true;
  r = run_check({&yes}, one, l);
  EXPECT_EQ(total(r, "yes").unsupported, 0u);  // it meets in a point: "yes" is right
}

TEST(Baseline, ReportsNewAndFixedDisagreementsOnlyForWhatRan) {
  const Algorithm no = fake("no", overlap_batch<&always_no>);
  const CheckResult r = run_check({&no}, cases(), labels());
  Baseline recorded = baseline_of(r, cases());
  ASSERT_FALSE(recorded.empty());
  const BaselineRow dropped = *recorded.begin();
  recorded.erase(recorded.begin());
  recorded.insert({"no", "coplanar-far", "overlap", "1", "0"});        // a failure that is gone
  recorded.insert({"other-algorithm", "coplanar-far", "overlap", "1", "0"});  // not in this run
  recorded.insert({"no", "case-not-in-this-run", "overlap", "1", "0"});
  const auto cmp = compare_with_baseline(recorded, r, cases());
  ASSERT_EQ(cmp.new_failures.size(), 1u);
  EXPECT_EQ(cmp.new_failures[0], dropped);
  ASSERT_EQ(cmp.fixed.size(), 1u);
  EXPECT_EQ(std::get<1>(cmp.fixed[0]), "coplanar-far");
}

TEST(Baseline, RoundTripsThroughItsFile) {
  const Algorithm no = fake("no", overlap_batch<&always_no>);
  const Baseline b = baseline_of(run_check({&no}, cases(), labels()), cases());
  const std::string path = std::string(TRITRI_BINARY_DIR) + "/roundtrip-baseline.tsv";
  {
    std::ofstream out(path);
    write_baseline(out, b);
  }
  EXPECT_EQ(read_baseline(path), b);
}

}  // namespace
}  // namespace tritri
