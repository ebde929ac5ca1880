// The tritri commands run as documented: their columns, their errors, their exit statuses.
#include "harness/testing/tritri_runner.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace {

using tritri::testing_support::Outcome;
Outcome tritri(const std::string& arguments) { return tritri::testing_support::run_tritri(arguments); }

const std::string kBuiltin = std::string(TRITRI_SOURCE_DIR) + "/cases/builtin.cases";

std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

std::size_t count_lines(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

TEST(Cli, EveryCommandHasHelp) {
  for (const char* command : {"list", "label", "answer", "check", "show"}) {
    const Outcome r = tritri(std::string(command) + " --help");
    EXPECT_EQ(r.status, 0) << command;
    EXPECT_NE(r.out.find(std::string("usage: tritri ") + command), std::string::npos) << r.out;
  }
  EXPECT_EQ(tritri("--help").status, 0);
  EXPECT_EQ(tritri("").status, 2);
}

TEST(Cli, ListShowsLevelsSemanticsToleranceAndCitation) {
  const Outcome r = tritri("list --tsv");
  ASSERT_EQ(r.status, 0);
  EXPECT_EQ(first_line(r.out), "name\tlevels\tboundary\ttolerance\tdegenerate\tsummary\tcitation\tfolder");
  EXPECT_NE(r.out.find("moller97\toverlap\tclosed\t1e-06 absolute"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Möller"), std::string::npos);
}

TEST(Cli, LabelHasTheDocumentedColumnsAndARowPerCase) {
  const Outcome r = tritri("label " + kBuiltin);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(first_line(r.out), "name\toverlap\trelation\tdim\tcoplanar\tseparation\tstage");
  EXPECT_EQ(count_lines(r.out), 44u);
  EXPECT_NE(r.out.find("parallel-stacked\t0\tparallel\tnone\t0\t1\tplane2\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("cross-pierce\t1\tcross\tsegment\t0\t0\tinterval\n"), std::string::npos) << r.out;
}

TEST(Cli, AnswerHasTheDocumentedColumns) {
  Outcome r = tritri("answer --algo moller97-segment " + kBuiltin);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(first_line(r.out), "name\toverlap\trelation\tsegment");
  EXPECT_NE(r.out.find("cross-pierce\t1\t-\t"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("disjoint-above\t0\t-\tempty\n"), std::string::npos) << r.out;
  r = tritri("answer --algo moller97 " + kBuiltin);
  EXPECT_NE(r.out.find("cross-pierce\t1\t-\t-\n"), std::string::npos) << r.out;
}

TEST(Cli, CheckPrintsTheTableAndWritesJson) {
  const std::string json = std::string(TRITRI_BINARY_DIR) + "/cli-check.json";
  const Outcome r = tritri("check --algo moller97 --json " + json + " " + kBuiltin);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(first_line(r.out).substr(0, 9), "algorithm");
  for (const char* column : {"family", "cases", "FP", "FN", "relation", "unsupported"})
    EXPECT_NE(first_line(r.out).find(column), std::string::npos) << column;
  EXPECT_NE(r.out.find("(all)"), std::string::npos);
  FILE* f = std::fopen(json.c_str(), "r");
  ASSERT_NE(f, nullptr);
  std::fclose(f);
}

TEST(Cli, CheckFailsOnANewDisagreementWithTheBaseline) {
  // An empty baseline for an algorithm that is wrong on nothing passes; a baseline that records
  // a disagreement which does not occur lists it as fixed but still passes.
  const std::string baseline = std::string(TRITRI_BINARY_DIR) + "/cli-baseline.tsv";
  Outcome r = tritri("check --algo moller97 --write-baseline " + baseline + " " + kBuiltin);
  ASSERT_EQ(r.status, 0);
  {
    FILE* f = std::fopen(baseline.c_str(), "a");
    std::fputs("moller97\tcross-pierce\toverlap\t0\t1\n", f);
    std::fclose(f);
  }
  r = tritri("check --algo moller97 --baseline " + baseline + " " + kBuiltin);
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("fixed (in the baseline, no longer occurring): 1"), std::string::npos) << r.out;
}

// NAME@float names a port's float instantiation wherever an algorithm is named; bench --float sets
// each port's beside it (and null@float, the rounding alone), leaving out those without one.
TEST(Cli, FloatInstantiationsAreNamedAndTimedBesideTheDoubleOnes) {
  Outcome r = tritri("answer --algo moller97@float " + kBuiltin);
  EXPECT_EQ(r.status, 0) << r.out;
  r = tritri("answer --algo cgal@float " + kBuiltin);
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("cgal@float: none of the chosen algorithms has a float instantiation"), std::string::npos) << r.out;
  r = tritri("bench --float --no-cache --algo moller97,cgal --mode batch --level overlap --workload ratio:0.5 --pool 512 "
             "--repetitions 1 --min-time 0.001 --no-ops --json -");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("no float instantiation, left out: cgal"), std::string::npos) << r.out;
  for (const char* row : {"\nmoller97/overlap/batch", "\nmoller97@float/overlap/batch", "\nnull@float/overlap/batch"})
    EXPECT_NE(r.out.find(row), std::string::npos) << row << "\n" << r.out;
  EXPECT_EQ(r.out.find("\ncgal/overlap/batch"), std::string::npos) << r.out;
}

TEST(Cli, ShowGivesOneCaseWithEveryAnswer) {
  const Outcome r = tritri("show cross-pierce " + kBuiltin);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("relation cross"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("moller97"), std::string::npos);
  EXPECT_NE(r.out.find("0x"), std::string::npos);  // hex coordinates, paste-ready
}

TEST(Cli, ErrorsAreClearAndExitTwo) {
  Outcome r = tritri("check --algo nosuch " + kBuiltin);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("unknown algorithm 'nosuch'"), std::string::npos) << r.out;
  r = tritri("label /nonexistent.cases");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("/nonexistent.cases"), std::string::npos) << r.out;
  r = tritri("check --bogus " + kBuiltin);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("unknown option '--bogus'"), std::string::npos);
  r = tritri("frobnicate");
  EXPECT_EQ(r.status, 2);
  r = tritri("show no-such-case " + kBuiltin);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("no case named"), std::string::npos);
  r = tritri("check --json /nonexistent-dir/x.json " + kBuiltin);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("/nonexistent-dir/x.json"), std::string::npos) << r.out;
}

TEST(Cli, MalformedInputNamesFileAndLine) {
  const std::string path = std::string(TRITRI_BINARY_DIR) + "/cli-bad.cases";
  FILE* f = std::fopen(path.c_str(), "w");
  std::fputs("# ok\ngood 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 1\nbad 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 nan\n", f);
  std::fclose(f);
  const Outcome r = tritri("check " + path);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find(path + ":3: coordinate 18 (T2.c.z) 'nan' is NaN"), std::string::npos) << r.out;
}

// A list option takes several values after one flag where the command has no FILE operands
// (kListsHelp): the family pools come from both files (axis-aligned is only in yuhe13.cases).
TEST(Cli, BenchTakesSeveralCaseFilesAfterOneCases) {
  const std::string yuhe = std::string(TRITRI_SOURCE_DIR) + "/cases/yuhe13.cases";
  const Outcome r = tritri("bench --quick --list --no-cache --pool 64 --algo moller97 --level overlap --workload family "
                           "--cases " + kBuiltin + " " + yuhe + " --json -");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("moller97/overlap/family:axis-aligned/call\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("moller97/overlap/family:edge-on-face/call\n"), std::string::npos) << r.out;
}

TEST(Cli, EveryCommandWithAListSaysHowListsAreGiven) {
  for (const char* command : {"list", "answer", "check", "show", "corpus", "bench", "diff"})
    EXPECT_NE(tritri(std::string(command) + " --help").out.find("several values after\none flag"), std::string::npos)
        << command;
}

}  // namespace
