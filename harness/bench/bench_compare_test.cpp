// bench and compare through the real CLI: plug-ins are timed, a broken one is reported and not
// timed, and compare tells a recorded slowdown from a recorded rerun (no test here reads a clock
// to decide: speed claims come from `tritri bench` itself).
#include "harness/testing/tritri_runner.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace tritri {
namespace {

using namespace testing_support;  // run_tritri, plugin_library, scratch_file, Outcome

std::string out_file(const std::string& name) { return std::string(TRITRI_BINARY_DIR) + "/bench-compare-" + name; }

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

bool has_benchmark(const nlohmann::json& doc, const std::string& name) {
  for (const auto& b : doc["benchmarks"])
    if (b.value("run_name", "") == name) return true;
  return false;
}

TEST(BenchPlugins, TheCExampleIsTimed) {
  const auto json = out_file("mine.json");
  const Outcome r = run_tritri("bench --quick --plugin " + plugin_library("tritri_example_mine") +
                               " --algo mine --workload ratio:0.5 --json " + json);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto doc = read_json(json);
  // A C-ABI plug-in has no one-pair entry: call mode calls its batch with n = 1.
  EXPECT_TRUE(has_benchmark(doc, "mine/overlap/ratio:0.50/call")) << r.out;
  EXPECT_TRUE(has_benchmark(doc, "moller97/overlap/ratio:0.50/call"));  // the reference, same run
}

TEST(BenchPlugins, ABrokenPluginIsReportedAndNotTimedAndTheOthersAre) {
  const auto cases = scratch_file("bench-hostile.cases",
      "fine-1 0 0 0 4 0 0 0 4 0  1 1 -1 1 1 1 2 2 1  family=f\n"
      "segv 0 0 0 4 0 0 0 4 0  1 1 -1 1 1 1 13 2 1  family=f\n"
      "fine-2 0 0 0 4 0 0 0 4 0  5 5 5 6 5 5 5 6 5  family=f\n"
      "hang 0 0 0 4 0 0 0 4 0  666 1 -1 1 1 1 2 2 1  family=f\n");
  const auto json = out_file("broken.json");
  const Outcome r = run_tritri("bench --quick --plugin " + plugin_library("tritri_broken") + " --algo broken,guigue03 --workload family --cases " +
                               cases + " --timeout 0.5 --json " + json);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("not timed: broken/overlap/family:f: 1 crash(es), 1 timeout(s)"), std::string::npos) << r.out;
  const auto doc = read_json(json);
  EXPECT_FALSE(has_benchmark(doc, "broken/overlap/family:f/call"));
  EXPECT_TRUE(has_benchmark(doc, "guigue03/overlap/family:f/call"));
  ASSERT_EQ(doc["tritri"]["not_timed"].size(), 1u);
  EXPECT_EQ(doc["tritri"]["not_timed"][0]["faults"].size(), 2u);
}

// tritri bench --quick on the ratio:0.5 pool of 512 pairs, with the process plug-in `exec`
// (a command on a file of the source tree) among the algorithms `algo`.
Outcome bench_process_plugin(const std::string& exec, const std::string& algo, const std::string& json) {
  return run_tritri("bench --quick --exec 'python3 " + std::string(TRITRI_SOURCE_DIR) + "/" + exec + "' --algo " +
                    algo + " --workload ratio:0.5 --pool 512 --json " + json);
}

// The Python example greets with 'timing' (harness/run/process_plugin.hpp): it is handed the pool,
// times its own loop, and its answers there are judged; its time stands apart from Google
// Benchmark's, marked as the plug-in's.
TEST(BenchPlugins, AProcessPluginThatTimesItselfIsCheckedAndReportedApart) {
  const auto json = out_file("process.json");
  const Outcome r = bench_process_plugin("harness/examples/mine.py' --exec-name 'mine-py", "mine-py,guigue03", json);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("timed in-process by the plug-in"), std::string::npos) << r.out;
  const auto doc = read_json(json);
  EXPECT_FALSE(has_benchmark(doc, "mine-py/overlap/ratio:0.50/call"));
  EXPECT_TRUE(has_benchmark(doc, "guigue03/overlap/ratio:0.50/call"));
  ASSERT_EQ(doc["tritri"]["self_timed"].size(), 1u);
  const auto& self = doc["tritri"]["self_timed"][0];
  EXPECT_EQ(self["name"], "mine-py/overlap/ratio:0.50/call");
  EXPECT_EQ(self["timed_by"], "plug-in");
  EXPECT_EQ(self["wrong"], 0);
  EXPECT_EQ(self["ns_per_pair"].size(), 3u);  // --quick: 3 repetitions
  EXPECT_GT(self["ns_per_pair_median"].get<double>(), 0.0);
}

// A protocol-1 plug-in (no greeting) is checked on every pool and reported, not timed.
TEST(BenchPlugins, AProcessPluginThatDoesNotTimeItselfIsCheckedButNotTimed) {
  const auto json = out_file("process-1.json");
  const Outcome r = bench_process_plugin("harness/run/test_plugins/unreliable.py", "exec", json);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("not timed: exec/overlap/ratio:0.50: a process plug-in that does not time itself"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("256 wrong, 0 unsupported of 512 pairs"), std::string::npos) << r.out;  // 1 to everything
  EXPECT_TRUE(read_json(json)["tritri"]["self_timed"].empty());
}

// bench writes what compare reads, and compare, through the CLI, calls a known slowdown
// significant and a rerun not. No clock decides the outcome: one real bench gives the file's
// shape, and the plug-in's repetitions are then set to known times (fixed, x1.6 slower, and a
// rerun within 0.3% in another order); every other row is the same in all three files. Whether
// the significance test itself is right is compare_test.cpp's (harness/check).
TEST(BenchAndCompare, ARecordedSlowdownIsSignificantAndARecordedRerunIsNot) {
  const auto recorded = out_file("recorded.json");
  const Outcome r = run_tritri("bench --plugin " + plugin_library("tritri_boxes") + " --algo boxes --level overlap "
                               "--workload ratio:0.5 --pool 2048 --repetitions 9 --min-time 0.001 --no-ops --json " +
                               recorded);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto with_times = [&](const std::string& name, double factor, bool reorder) {
    nlohmann::json doc = read_json(recorded);
    int set = 0;
    for (auto& b : doc["benchmarks"]) {
      if (b.value("run_type", "") != "iteration" || b.value("run_name", "").rfind("boxes/", 0) != 0) continue;
      const int k = b.value("repetition_index", 0);
      const double ns = 100.0 * factor * (1.0 + 0.01 * (reorder ? (k * 4) % 9 : k)) * (reorder ? 1.003 : 1.0);
      b["real_time"] = ns * 2048;
      b["cpu_time"] = ns * 2048;
      b["time_unit"] = "ns";
      b["items_per_second"] = 1e9 / ns;
      ++set;
    }
    EXPECT_EQ(set, 9) << "the recorded bench has 9 repetitions of the plug-in in one mode";
    const auto path = out_file(name);
    std::ofstream(path) << doc.dump();
    return path;
  };
  const auto base = with_times("base.json", 1.0, false);
  const auto slow = with_times("slow.json", 1.6, false);
  const auto rerun = with_times("rerun.json", 1.0, true);
  auto row_of = [](const std::string& out, const std::string& name) {
    const auto at = out.find(name + "/overlap/ratio:0.50");
    return at == std::string::npos ? std::string() : out.substr(at, out.find('\n', at) - at);
  };
  Outcome c = run_tritri("compare --min-change 0.05 " + base + " " + slow);
  EXPECT_EQ(c.status, 1) << c.out;
  EXPECT_NE(row_of(c.out, "boxes").find("slower (significant)"), std::string::npos) << c.out;
  c = run_tritri("compare --min-change 0.05 " + base + " " + rerun);
  EXPECT_EQ(c.status, 0) << c.out;
  const std::string boxes = row_of(c.out, "boxes");
  ASSERT_FALSE(boxes.empty()) << c.out;
  EXPECT_EQ(boxes.find("(significant)"), std::string::npos) << c.out;
}

}  // namespace
}  // namespace tritri
