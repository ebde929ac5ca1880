// check counts what it should: a wrong algorithm is caught, and baselines see new and fixed
// disagreements.
#include "harness/check/check.hpp"
#include "harness/check/check_output.hpp"
#include "harness/check/judge.hpp"
#include "tritri/add_level.hpp"

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
  if (overlap) a.set_batch<Level::overlap>(Scalar::double_, overlap);
  if (relation) a.set_batch<Level::relation>(Scalar::double_, relation);
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
  EXPECT_NE(std::find(r.groups.begin(), r.groups.end(), "coplanar-disjoint"), r.groups.end());
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
  Baseline recorded = baseline_of(r);
  ASSERT_FALSE(recorded.empty());
  const BaselineRow dropped = *recorded.begin();
  recorded.erase(recorded.begin());
  recorded.insert({"no", "coplanar-far", "overlap", "1", "0"});        // a failure that is gone
  recorded.insert({"other-algorithm", "coplanar-far", "overlap", "1", "0"});  // not in this run
  recorded.insert({"no", "case-not-in-this-run", "overlap", "1", "0"});
  const auto cmp = compare_with_baseline(recorded, r);
  ASSERT_EQ(cmp.new_failures.size(), 1u);
  EXPECT_EQ(cmp.new_failures[0], dropped);
  ASSERT_EQ(cmp.fixed.size(), 1u);
  EXPECT_EQ(std::get<1>(cmp.fixed[0]), "coplanar-far");
}

TEST(Baseline, RoundTripsThroughItsFile) {
  const Algorithm no = fake("no", overlap_batch<&always_no>);
  const Baseline b = baseline_of(run_check({&no}, cases(), labels()));
  const std::string path = std::string(TRITRI_BINARY_DIR) + "/roundtrip-baseline.tsv";
  {
    std::ofstream out(path);
    write_baseline(out, b);
  }
  EXPECT_EQ(read_baseline(path), b);
}

}  // namespace
}  // namespace tritri

// ---- relation confusion and segment error (issue 5) ----
namespace tritri {
namespace {

RelationAnswer dimension_area(const TrianglePair&) { return {Relation::unknown, Dimension::area}; }

// The exact intersection of cross-pierce, one end moved by 0.5 along the segment's line.
SegmentAnswer pierce_segment_off(const TrianglePair&) {
  SegmentAnswer s;
  s.kind = SegmentKind::segment;
  s.p = {1, 0, 0};
  s.q = {1, 1.5, 0};  // exact: (1,0,0)–(1,1,0)
  return s;
}

TEST(CheckScoring, ConfusionCountsEveryCaseOnceInItsCell) {
  Algorithm cross = fake("cross", nullptr, relation_batch<&always_cross>);
  CheckResult r;
  r.algorithms = {&cross};
  score(cross, cases(), labels(), answer_cases(cross, cases()), r);
  std::size_t cells = 0, diagonal = 0, scored = 0;
  for (const auto& [key, tally] : r.tallies) {
    scored += tally.cases - tally.unsupported;
    for (const auto& [cell, count] : tally.confusion) {
      EXPECT_EQ(cell.first, "cross");
      cells += count;
      if (cell.second == "cross") diagonal += count;
    }
  }
  EXPECT_EQ(cells, scored);
  EXPECT_EQ(diagonal, 5u);  // the built-in cross cases
  EXPECT_EQ(total(r, "cross").misclassified, scored - diagonal);
}

TEST(CheckScoring, DegenerateAnswersAreJudgedByTheirDimension) {
  // An exact algorithm answers a zero-area pair as the oracle labels it: {degenerate, dimension}.
  Truth truth;
  truth.overlap = true;
  truth.degenerate = true;
  truth.relation = Relation::degenerate;
  truth.dimension = Dimension::point;
  EXPECT_EQ(judge_relation({Relation::degenerate, Dimension::point}, truth).verdict, Verdict::right);
  EXPECT_EQ(judge_relation({Relation::degenerate, Dimension::segment}, truth).verdict, Verdict::wrong);
  EXPECT_EQ(judge_relation({Relation::degenerate, Dimension::none}, truth).verdict, Verdict::wrong);
  EXPECT_EQ(implied_overlap(RelationAnswer{Relation::degenerate, Dimension::point}), Overlap::yes);
  EXPECT_EQ(implied_overlap(RelationAnswer{Relation::degenerate, Dimension::none}), Overlap::no);
}

TEST(CheckScoring, DimensionOnlyAnswersAreConfusedByDimension) {
  Algorithm area = fake("area", nullptr, relation_batch<&dimension_area>);
  CheckResult r;
  r.algorithms = {&area};
  score(area, cases(), labels(), answer_cases(area, cases()), r);
  const Tally& t = r.tallies.at({"area", "parallel"});
  EXPECT_EQ(t.confusion.at({"dim:area", "dim:none"}), 5u);
}

TEST(CheckScoring, SegmentErrorIsRelativeHausdorffAndKindsAreCompared) {
  Algorithm seg;
  seg.name = "seg";
  seg.set_batch<Level::segment>(Scalar::double_, segment_batch<&pierce_segment_off>);
  std::vector<Case> one;
  for (const Case& c : cases())
    if (c.name == "cross-pierce" || c.name == "disjoint-above") one.push_back(c);
  ASSERT_EQ(one.size(), 2u);
  const auto oracle = label_cases(one);
  CheckResult r;
  r.algorithms = {&seg};
  score(seg, one, oracle, answer_cases(seg, one), r);
  const SegmentTally& s = r.tallies.at({"seg", "general"}).segment;
  EXPECT_EQ(s.answered, 2u);
  EXPECT_EQ(s.kind_mismatches, 1u);  // a segment where the oracle has nothing
  ASSERT_EQ(s.errors.count(), 1u);
  const double exact_pierce_error = 0.5 / pair_size(one[1].pair);  // one[1] is cross-pierce
  EXPECT_NEAR(s.errors.sample()[0], exact_pierce_error, 1e-15);
  // Overlap is derived from the segment answer when it is the only level.
  EXPECT_EQ(r.tallies.at({"seg", "general"}).false_positives, 1u);
}

TEST(CheckScoring, HausdorffBetweenSegmentsAndPoints) {
  const Vec3<double> o(0, 0, 0), x(1, 0, 0), y(0, 1, 0);
  EXPECT_EQ(hausdorff_distance(o, x, o, x), 0.0);
  EXPECT_EQ(hausdorff_distance(x, o, o, x), 0.0);          // orientation does not matter
  EXPECT_DOUBLE_EQ(hausdorff_distance(o, o, o, x), 1.0);   // a point against a segment
  EXPECT_DOUBLE_EQ(hausdorff_distance(o, x, y, y), std::sqrt(2.0));
}

TEST(CheckScoring, JsonHasSchemaThreeWithConfusionAndSegment) {
  Algorithm cross = fake("cross", nullptr, relation_batch<&always_cross>);
  const CheckResult r = run_check({&cross}, cases(), labels());
  std::ostringstream out;
  write_check_json(out, r, {.inputs = {"builtin"}});
  EXPECT_NE(out.str().find("\"tritri-check/3\""), std::string::npos);
  EXPECT_NE(out.str().find("\"confusion\""), std::string::npos);
  EXPECT_NE(out.str().find("\"segment\": null"), std::string::npos);
}

}  // namespace
}  // namespace tritri
