// Plug-ins through the real CLI: a broken one is contained case by case, the tutorial's
// examples run, process plug-ins survive their own deaths.
#include "cases/util/text.hpp"
#include "harness/testing/tritri_runner.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string_view>

namespace tritri {
namespace {

using namespace testing_support;  // run_tritri, plugin_library, scratch_file, Outcome

const std::string kSource = TRITRI_SOURCE_DIR;
const std::string kBuiltin = kSource + "/cases/builtin.cases";

// A table row of `tritri check`: the words of the line that starts with algorithm and family.
std::vector<std::string_view> row(const std::string& out, const std::string& algorithm, const std::string& family) {
  for (std::string_view line : split_fields(out, '\n')) {
    const auto words = split_words(line);
    if (words.size() > 1 && words[0] == algorithm && words[1] == family) return words;
  }
  return {};
}

// An example plug-in (`how` loads it), checked on the built-in cases: all 43 answered, none wrong.
void expect_right_on_builtin(const std::string& how, const std::string& algorithm) {
  const Outcome r = run_tritri("check " + how + " --algo " + algorithm + " " + kBuiltin);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto all = row(r.out, algorithm, "(all)");
  ASSERT_EQ(all.size(), 9u) << r.out;
  EXPECT_EQ(all[2], "43");
  EXPECT_EQ(all[3], "0");
  EXPECT_EQ(all[4], "0");
}

const std::string kHostile =
    "fine-1 0 0 0 4 0 0 0 4 0  1 1 -1 1 1 1 2 2 1  family=f\n"
    "segv 0 0 0 4 0 0 0 4 0  1 1 -1 1 1 1 13 2 1  family=f\n"
    "fine-2 0 0 0 4 0 0 0 4 0  5 5 5 6 5 5 5 6 5  family=f\n"
    "hang 0 0 0 4 0 0 0 4 0  666 1 -1 1 1 1 2 2 1  family=f\n"
    "abort 0 0 0 4 0 0 0 4 0  99 1 -1 1 1 1 2 2 1  family=f\n"
    "fine-3 0 0 0 4 0 0 0 4 0  1 1 0 2 1 0 1 2 0  family=f\n";

TEST(BrokenPlugin, CheckContainsItsCrashesAndHangsAndKeepsEverythingElse) {
  const auto cases = scratch_file("hostile.cases", kHostile);
  const Outcome r = run_tritri("check --plugin " + plugin_library("tritri_broken") + " --algo broken,moller97 --timeout 0.5 " + cases);
  ASSERT_EQ(r.status, 0) << r.out;
  // columns: algorithm family cases FP FN relation unsupported crash timeout
  const auto broken = row(r.out, "broken", "f");
  ASSERT_EQ(broken.size(), 9u) << r.out;
  EXPECT_EQ(broken[2], "6");
  EXPECT_EQ(broken[7], "2");  // segv and abort
  EXPECT_EQ(broken[8], "1");  // hang
  const auto moller = row(r.out, "moller97", "f");
  ASSERT_EQ(moller.size(), 9u) << r.out;
  EXPECT_EQ(moller[7], "0");
  EXPECT_EQ(moller[8], "0");
  // each fault named with its case, paste-ready
  EXPECT_NE(r.out.find("# broken: crash (SIGSEGV) on this case"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("# broken: crash (SIGABRT) on this case"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("# broken: timeout (no progress for 0.5 s) on this case"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nsegv 0x0p+0 "), std::string::npos) << r.out;
}

TEST(BrokenPlugin, AnswerAndShowSayWhatHappened) {
  const auto cases = scratch_file("hostile.cases", kHostile);
  Outcome r = run_tritri("answer --plugin " + plugin_library("tritri_broken") + " --algo broken --timeout 0.5 " + cases);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("segv\tcrash\tcrash\tcrash\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("hang\ttimeout\t"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fine-2\t0\t-\t-\n"), std::string::npos) << r.out;
  r = run_tritri("show segv " + cases + " --plugin " + plugin_library("tritri_broken") + " --algo broken,moller97");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("crash (SIGSEGV)"), std::string::npos) << r.out;
}

TEST(BrokenPlugin, ANewCrashFailsTheBaseline) {
  const auto cases = scratch_file("hostile.cases", kHostile);
  const auto baseline = scratch_file("empty-baseline.tsv", "algorithm\tcase\tlevel\tanswer\toracle\n");
  const Outcome r = run_tritri("check --quiet --plugin " + plugin_library("tritri_broken") + " --algo broken --timeout 0.5 --baseline " +
                               baseline + " " + cases);
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("broken\tsegv\toverlap\tanswered crash"), std::string::npos) << r.out;
}

TEST(ExamplePlugins, TheCExampleIsRightOnTheBuiltinCases) {
  expect_right_on_builtin("--plugin " + plugin_library("tritri_example_mine"), "mine");
}

TEST(ExamplePlugins, ThePythonExampleIsRightOnTheBuiltinCases) {
  expect_right_on_builtin("--exec 'python3 " + kSource + "/harness/examples/mine.py' --exec-name mine-py", "mine-py");
}

TEST(ProcessPlugin, SurvivesItsOwnDeathsAndHangs) {
  const auto cases = scratch_file("process.cases",
      "ok-1 0 0 0 4 0 0 0 4 0  1 1 -1 1 1 1 2 2 1  family=p\n"
      "boom 0 0 0 4 0 0 0 4 0  1 1 -1 1 1 1 2 2 1  family=p\n"
      "ok-2 0 0 0 4 0 0 0 4 0  5 5 5 6 5 5 5 6 5  family=p\n"
      "slow 0 0 0 4 0 0 0 4 0  1 1 -1 1 1 1 2 2 1  family=p\n"
      "ok-3 0 0 0 4 0 0 0 4 0  1 1 -1 1 1 1 2 2 1  family=p\n");
  const Outcome r = run_tritri("check --exec 'python3 " + kSource + "/harness/run/test_plugins/unreliable.py' --algo exec --timeout 1 " + cases);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto p = row(r.out, "exec", "p");
  ASSERT_EQ(p.size(), 9u) << r.out;
  EXPECT_EQ(p[3], "1");  // ok-2 is disjoint; it says 1 to everything
  EXPECT_EQ(p[7], "1");  // boom
  EXPECT_EQ(p[8], "1");  // slow
  EXPECT_NE(r.out.find("# exec: crash (the process ended (exit status 3))"), std::string::npos) << r.out;
}

TEST(ProcessPlugin, AProtocolErrorStopsTheRunAndQuotesTheAnswer) {
  const auto cases = scratch_file("garbled.cases", "garbled 0 0 0 4 0 0 0 4 0  1 1 -1 1 1 1 2 2 1\n");
  const Outcome r = run_tritri("check --exec 'python3 " + kSource + "/harness/run/test_plugins/unreliable.py' --algo exec " + cases);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("answered 'what is a triangle' to case 'garbled'"), std::string::npos) << r.out;
}

TEST(ProcessPlugin, ACommandThatCannotRunIsAClearError) {
  const Outcome r = run_tritri("check --exec '/nonexistent/plugin' " + kBuiltin);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("did not answer a probe case"), std::string::npos) << r.out;
}

// A build that hangs on every case is stopped after --max-faults timeouts, told so in one line
// naming the first faulting cases and how many were not run; answer, check and diff exit 1, and
// check's JSON says the run is incomplete.
TEST(FaultLimit, AHangingBuildStopsAfterMaxFaultsInAnswerCheckAndDiff) {
  std::string text;
  for (int i = 0; i < 40; ++i)
    text += "hang-" + std::to_string(i) + " 0 0 0 4 0 0 0 4 0  666 1 -1 1 1 1 2 2 1  family=f\n";
  const auto cases = scratch_file("fault-limit.cases", text);
  const std::string broken = "--plugin " + plugin_library("tritri_broken") + " --timeout 0.2 --max-faults 3 ";
  Outcome r = run_tritri("answer " + broken + "--algo broken " + cases);
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("tritri: broken stopped after 3 crashes or timeouts (--max-faults): 37 of 40 cases not run; "
                       "the first: hang-0 (no progress for 0.2 s) hang-1"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("hang-39\tnot-run\tnot-run\tnot-run"), std::string::npos) << r.out;
  const auto json = scratch_file("fault-limit.json", "");
  r = run_tritri("check " + broken + "--algo broken --quiet --json " + json + " " + cases);
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("37 of 40 cases not run"), std::string::npos) << r.out;
  std::ifstream in(json);
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(written.find("\"complete\": false"), std::string::npos) << written.substr(0, 400);
  r = run_tritri("diff " + broken + "--pair broken=moller97 " + cases);
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("37 of 40 cases not run"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace tritri
