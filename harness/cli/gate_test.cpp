// The gate the main job runs (scripts/run: `tritri check --baseline
// algorithms/*/expected-failures-corpus.tsv.gz`), through the real CLI: a baseline recorded as
// gzip reads back exactly; an algorithm whose answer on one case changed makes the check exit 1
// and names the case, paste-ready; a damaged baseline is an error, never an empty baseline.
#include "harness/testing/tritri_runner.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace tritri {
namespace {

using namespace testing_support;  // run_tritri, plugin_library, scratch_file, Outcome


// Disjoint boxes (both answers right), overlapping boxes of disjoint triangles (the box test's
// false positive, recorded), and "seven": disjoint, with a coordinate 7 where tritri_boxes_changed
// flips its answer.
const std::string kCases =
    "apart 0 0 0 1 0 0 0 1 0  5 5 5 6 5 5 5 6 5  family=f\n"
    "boxes-meet 0 0 0 4 0 0 0 4 0  3 3 -1 3 3 1 4 4 0  family=f\n"
    "seven 0 0 0 1 0 0 0 1 0  7 5 5 8 5 5 7 6 5  family=f\n";

std::string record_baseline(const std::string& name) {
  const auto cases = scratch_file("gate.cases", kCases);
  const std::string baseline = std::string(TRITRI_BINARY_DIR) + "/scratch-" + name;
  const Outcome r = run_tritri("check --quiet --plugin " + plugin_library("tritri_boxes") + " --algo boxes --write-baseline " +
                               baseline + " " + cases);
  EXPECT_EQ(r.status, 0) << r.out;
  return baseline;
}

TEST(Gate, AGzipBaselineIsCompressedAndMatchesTheSameAnswers) {
  const auto baseline = record_baseline("gate-same.tsv.gz");
  std::ifstream in(baseline, std::ios::binary);
  ASSERT_EQ(in.get(), 0x1f) << "written as gzip";
  ASSERT_EQ(in.get(), 0x8b);
  const auto cases = scratch_file("gate.cases", kCases);
  const Outcome r = run_tritri("check --quiet --plugin " + plugin_library("tritri_boxes") + " --algo boxes --baseline " +
                               baseline + " " + cases);
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("boxes: new: 0, fixed: 0"), std::string::npos) << r.out;
}

TEST(Gate, AChangedAnswerFailsTheGateNamingTheCase) {
  const auto baseline = record_baseline("gate-changed.tsv.gz");
  const auto cases = scratch_file("gate.cases", kCases);
  const Outcome r = run_tritri("check --quiet --plugin " + plugin_library("tritri_boxes_changed") + " --algo boxes --baseline " +
                               baseline + " " + cases);
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("boxes: new: 1, fixed: 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("boxes\tseven\toverlap\tanswered 1, oracle 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nseven 0x0p+0 "), std::string::npos) << "the case, paste-ready:\n" << r.out;
}

TEST(Gate, ADamagedBaselineIsAnErrorNamingTheFile) {
  const auto baseline = record_baseline("gate-damaged.tsv.gz");
  std::string bytes;
  {
    std::ifstream in(baseline, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  ASSERT_GT(bytes.size(), 20u);
  const auto damaged = scratch_file("gate-truncated.tsv.gz", bytes.substr(0, bytes.size() / 2));
  const auto cases = scratch_file("gate.cases", kCases);
  const Outcome r = run_tritri("check --quiet --plugin " + plugin_library("tritri_boxes") + " --algo boxes --baseline " +
                               damaged + " " + cases);
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("gate-truncated.tsv.gz"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace tritri
