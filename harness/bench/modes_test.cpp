// Tests of the timing modes of `tritri bench`: call mode goes through the one-pair entry, one
// pair per call (or a batch of one when there is none), batch mode through the batch entry; the
// mode is an axis of every result, its reference ratio and the floors' share; a floor's share
// warns only about published tests in the same mode.
// No test here asserts anything about time: speed claims come from the benchmark only.
#include "harness/bench/bench.hpp"
#include "harness/bench/report.hpp"
#include "harness/bench/test_support.hpp"
#include "algorithms/moller97/moller97.hpp"
#include "tritri/add_level.hpp"
#include "tritri/isa.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <sys/wait.h>
#include <tuple>
#include <unistd.h>

namespace tritri::bench {
namespace {

// Entry points that count how they are called: pairs through the one-pair entry, and batch calls
// by their size.
std::size_t g_one_pair_calls = 0;
std::map<std::size_t, std::size_t> g_batch_calls;  // n -> calls

Overlap counted_one(const TrianglePair& p) {
  ++g_one_pair_calls;
  return moller97::overlap<double, true>(p) ? Overlap::yes : Overlap::no;
}
void counted_batch(const TrianglePair* pairs, std::size_t n, Overlap* out) {
  ++g_batch_calls[n];
  overlap_batch<&moller97::overlap<double, true>>(pairs, n, out);
}

// 300 pairs, checked in this process (so that the counts above see the check's calls too).
Options small_run(std::vector<const Algorithm*> algorithms, std::vector<Mode> modes, const std::string& json) {
  Options o = bench::small_run(std::move(algorithms), 300, 1, json);
  o.modes = std::move(modes);
  o.isolation.enabled = false;
  return o;
}

// An algorithm on the counting entries (with its one-pair entry or without, as a C-ABI plug-in
// is), run in `mode` from zeroed counts.
void run_counting(const std::string& name, bool one_pair, Mode mode, std::string& output) {
  Algorithm a;
  a.name = name;
  a.set_batch<Level::overlap>(Scalar::double_, &counted_batch);
  if (one_pair) a.set_one_pair<Level::overlap>(&counted_one);
  g_one_pair_calls = 0;
  g_batch_calls.clear();
  std::ostringstream out;
  EXPECT_EQ(run(small_run({&a}, {mode}, ""), out), 0) << out.str();
  output = out.str();
}

std::filesystem::path scratch(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("tritri-modes-" + name + "-" + std::to_string(getpid()) + ".json");
}

TEST(BenchModes, CallModeCallsTheOnePairEntryOncePerPair) {
  std::string out;
  run_counting("one-pair-counter", true, Mode::call, out);
  // Timing makes at least one pass over the 300 pairs, each through the one-pair entry; the batch
  // entry is called only by the check (the whole pool at once), never per pair.
  EXPECT_GE(g_one_pair_calls, 300u);
  EXPECT_EQ(g_one_pair_calls % 300, 0u);
  EXPECT_EQ(g_batch_calls.count(1), 0u);
  EXPECT_NE(out.find("one-pair-counter/overlap/call"), std::string::npos) << out;
}

TEST(BenchModes, CallModeWithoutAOnePairEntryCallsTheBatchWithOnePair) {
  std::string out;
  run_counting("batch-only", false, Mode::call, out);
  EXPECT_GE(g_batch_calls[1], 300u);
  EXPECT_EQ(g_batch_calls[1] % 300, 0u);
}

TEST(BenchModes, BatchModeHandsThePoolOverInBatches) {
  std::string out;
  run_counting("batch-counter", true, Mode::batch, out);
  EXPECT_EQ(g_one_pair_calls, 0u);
  EXPECT_GE(g_batch_calls[kBatch], 1u);  // 300 pairs: one batch of 256, one of 44 per pass
  EXPECT_GE(g_batch_calls[300 - kBatch], g_batch_calls[kBatch]);
  EXPECT_EQ(g_batch_calls.count(1), 0u);
}

TEST(BenchModes, BothModesAreAnAxisOfEveryResultRatioAndFloorShare) {
  const auto path = scratch("both");
  std::ostringstream out;
  const Algorithm* moller = registry().find("moller97");
  const Algorithm* guigue = registry().find("guigue03");
  ASSERT_EQ(run(small_run({moller, guigue}, {Mode::call, Mode::batch}, path.string()), out), 0) << out.str();
  const auto doc = nlohmann::json::parse(std::ifstream(path));
  const auto& t = doc["tritri"];
  EXPECT_EQ(t["schema"], kBenchSchema);
  EXPECT_EQ(t["modes"], nlohmann::json::array({"call", "batch"}));
  EXPECT_TRUE(t["isa"].is_string() && t["isa_machine"].is_string() && t["cpu_model"].is_string()) << t.dump();
  std::set<std::pair<std::string, std::string>> seen;  // (algorithm, mode)
  for (const auto& r : t["results"]) {
    const std::string mode = r["mode"];
    EXPECT_EQ(r["name"], r["algorithm"].get<std::string>() + "/overlap/ratio:0.50/" + mode);
    EXPECT_EQ(r["level"], "overlap");
    EXPECT_TRUE(r["stage"].is_null());
    seen.insert({r["algorithm"].get<std::string>(), mode});
    if (r["algorithm"] == "moller97") {
      EXPECT_DOUBLE_EQ(r["relative_to_reference"].get<double>(), 1.0) << mode;
    }
  }
  for (const char* algo : {"floor", "null", "moller97", "guigue03"})
    for (const char* mode : {"call", "batch"}) EXPECT_TRUE(seen.count({algo, mode})) << algo << " " << mode;
  // Each floor against each test in each mode, the floor timed in that mode.
  std::set<std::tuple<std::string, std::string, std::string>> shares;
  for (const auto& s : t["harness"]["floor_share"]) {
    shares.insert({s["floor"].get<std::string>(), s["test"].get<std::string>(), s["mode"].get<std::string>()});
    EXPECT_TRUE(s["published"].get<bool>()) << s.dump();
  }
  for (const char* floor : {"floor", "null"})
    for (const char* test : {"moller97/overlap", "guigue03/overlap"})
      for (const char* mode : {"call", "batch"}) EXPECT_TRUE(shares.count({floor, test, mode})) << floor << test << mode;
  EXPECT_EQ(t["harness"]["floors"], nlohmann::json::array({"floor", "null"}));
  EXPECT_NE(out.str().find("harness: floor 'null' in call mode"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("harness: floor 'null' in batch mode"), std::string::npos) << out.str();
  std::filesystem::remove(path);
}

// The main job's default plan times the ratio pools in both modes and the rest in call mode
// (scripts/run): the filter decides what is counted, planned and written, not only what runs.
TEST(BenchModes, TheFilterChoosesModesPerWorkloadAndThePlanCountsWhatRuns) {
  const auto path = scratch("filter");
  std::ostringstream out;
  Options o = small_run({registry().find("moller97")}, {Mode::call, Mode::batch}, path.string());
  o.workloads = {"ratio:0.5", "type:point"};
  o.filter = "ratio:|/call$";
  ASSERT_EQ(run(o, out), 0) << out.str();
  const auto doc = nlohmann::json::parse(std::ifstream(path));
  std::set<std::pair<std::string, std::string>> seen;  // (pool, mode)
  std::size_t results = 0;
  for (const auto& r : doc["tritri"]["results"]) {
    seen.insert({r["workload"].get<std::string>(), r["mode"].get<std::string>()});
    ++results;
  }
  EXPECT_EQ(seen, (std::set<std::pair<std::string, std::string>>{
                      {"ratio:0.50", "call"}, {"ratio:0.50", "batch"}, {"type:point", "call"}}));
  // floor, null, moller97: both modes on the ratio pool, call mode on the other.
  EXPECT_EQ(results, 9u);
  EXPECT_NE(out.str().find("; 9 benchmarks, 1 repetitions each"), std::string::npos) << out.str();

  o.filter = "-/batch$";  // a leading '-': every name it does not match
  ASSERT_EQ(run(o, out), 0) << out.str();
  const auto calls = nlohmann::json::parse(std::ifstream(path));
  EXPECT_EQ(calls["tritri"]["results"].size(), 6u);  // floor, null, moller97 on both pools
  for (const auto& r : calls["tritri"]["results"]) EXPECT_EQ(r["mode"], "call");
  o.filter = "ratio:(";
  EXPECT_THROW(run(o, out), std::invalid_argument);
  std::filesystem::remove(path);
}

// A scene's pools ask one question each: every algorithm is timed at that level only, or, when
// it does not answer it, at the lowest level asked for that does (a relation says whether they meet).
TEST(BenchModes, EachScenePoolIsTimedAtTheLevelItsQueryAsks) {
  const auto path = scratch("scene-levels");
  std::ostringstream out;
  Options o = small_run({registry().find("moller97-segment"), registry().find("yuhe13")}, {Mode::batch}, path.string());
  o.workloads = {"scene:box_stack/bv:OBB", "scene:spindle_self/bv:OBB"};
  o.levels = {Level::overlap, Level::relation, Level::segment};
  ASSERT_EQ(run(o, out), 0) << out.str();
  std::map<std::string, std::set<std::string>> levels;  // algorithm pool -> levels timed
  const auto doc = nlohmann::json::parse(std::ifstream(path));
  for (const auto& r : doc["tritri"]["results"])
    levels[r["algorithm"].get<std::string>() + " " + r["workload"].get<std::string>()].insert(r["level"].get<std::string>());
  using Set = std::set<std::string>;
  for (const char* pool : {"scene:box_stack/bv:OBB", "scene-shuffled:box_stack/bv:OBB", "scene-any:box_stack/bv:OBB"}) {
    EXPECT_EQ(levels[std::string("moller97-segment ") + pool], Set{"overlap"}) << pool;
    EXPECT_EQ(levels[std::string("yuhe13 ") + pool], Set{"relation"}) << pool;
  }
  for (const char* pool : {"scene:spindle_self/bv:OBB", "scene-shuffled:spindle_self/bv:OBB"}) {
    EXPECT_EQ(levels[std::string("moller97-segment ") + pool], Set{"segment"}) << pool;
    EXPECT_EQ(levels[std::string("yuhe13 ") + pool], Set{"segment"}) << pool;
  }
  std::filesystem::remove(path);
}

// Summaries of hand-made entries: a floor at 1 ns against tests of known times.
struct Fixture {
  Algorithm floor, published, ours;
  PlannedPool planned;
  EntryList timed;
  Lineup lineup;

  Fixture() {
    floor.name = "null";
    published.name = "moller97";
    published.citation = "Tomas Möller. A Fast Triangle-Triangle Intersection Test.";
    ours.name = "exact";
    ours.citation = "this project (tritri): algorithms/exact/README.md";
    planned.pool.workload = "ratio";
    planned.pool.value = "0.50";
    planned.pool.pairs.resize(8);
    planned.levels = true;
    lineup.floors = {&floor};
    lineup.algorithms = {&floor, &published, &ours};
    lineup.reference = &published;
  }
  void add(const Algorithm& a, Mode mode, double ns) {
    auto e = std::make_unique<Entry>();
    e->algo = a.name;
    e->algorithm = &a;
    e->level = Level::overlap;
    e->mode = mode;
    e->pool = &planned.pool;
    e->floor = &a == &floor;
    e->ns_per_pair = {ns};
    timed.push_back(std::move(e));
  }
  Summary summary() const { return summarize(timed, {planned}, lineup, 8, {Mode::call, Mode::batch}); }
};

bool warns_about(const Summary& s, const std::string& what) {
  for (const auto& w : s.warnings)
    if (w.find(what) != std::string::npos) return true;
  return false;
}

TEST(BenchFloorShare, WarnsOnlyAboutPublishedTestsInTheSameMode) {
  Fixture f;
  f.add(f.floor, Mode::call, 2.0);   // call: 2 ns, 8% of moller97's 25 ns
  f.add(f.floor, Mode::batch, 1.0);  // batch: 1 ns, 5% of moller97's 20 ns, 50% of exact's 2 ns
  f.add(f.published, Mode::call, 25.0);
  f.add(f.published, Mode::batch, 20.0);
  f.add(f.ours, Mode::call, 30.0);
  f.add(f.ours, Mode::batch, 2.0);
  Summary s = f.summary();
  ASSERT_EQ(s.floor_shares.size(), 4u);
  for (const FloorShare& fs : s.floor_shares) {
    EXPECT_EQ(fs.published, fs.row == "moller97/overlap") << fs.row;
    // The floor in the test's own mode: never the batch floor against a call time.
    const double expected = fs.row == "moller97/overlap" ? (fs.mode == Mode::call ? 2.0 / 25 : 1.0 / 20)
                                                          : (fs.mode == Mode::call ? 2.0 / 30 : 1.0 / 2);
    EXPECT_DOUBLE_EQ(fs.share_full, expected) << fs.row << " " << to_string(fs.mode);
  }
  EXPECT_FALSE(warns_about(s, "floor 'null'")) << "exact is this project's, not a published test";

  Fixture g;  // now the floor is 12% of moller97 in call mode
  g.add(g.floor, Mode::call, 3.0);
  g.add(g.published, Mode::call, 25.0);
  g.add(g.floor, Mode::batch, 1.0);
  g.add(g.published, Mode::batch, 20.0);
  s = g.summary();
  EXPECT_TRUE(warns_about(s, "floor 'null' above 10% of 1 published test(s)' time in call mode (moller97/overlap 12.0%"))
      << (s.warnings.empty() ? "" : s.warnings.front());
  EXPECT_FALSE(warns_about(s, "in batch mode"));
}

TEST(BenchModes, ParsesTheModesByName) {
  EXPECT_EQ(parse_mode("call"), Mode::call);
  EXPECT_EQ(parse_mode("batch"), Mode::batch);
  EXPECT_EQ(parse_mode("both"), std::nullopt);  // the command's word for the two, not a mode
  EXPECT_EQ(to_string(Mode::call), "call");
  Options o = small_run({registry().find("moller97")}, {}, "");
  std::ostringstream out;
  EXPECT_THROW(run(o, out), std::invalid_argument);
}

// The command: a clear usage error for an unknown mode or ISA and for an ISA the machine lacks;
// the ISA asked for reaches the lane algorithm (exact's path counter names the one it ran on)
// and is recorded in the JSON.
std::pair<int, std::string> tritri_bench(const std::string& arguments) {
  const auto log = scratch("cli-log");
  const std::string command = std::string(TRITRI_BINARY_DIR) + "/bin/tritri bench " + arguments + " > '" +
                              log.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(log);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text};
}

TEST(BenchModesCli, UnknownModesAndIsasAreRefusedAndTheIsaIsRecorded) {
  auto [status, text] = tritri_bench("--mode sometimes --list");
  EXPECT_EQ(status, 2);
  EXPECT_NE(text.find("unknown --mode 'sometimes' (call, batch, both)"), std::string::npos) << text;
  std::tie(status, text) = tritri_bench("--isa avx1024 --list");
  EXPECT_EQ(status, 2);
  EXPECT_NE(text.find("unknown --isa 'avx1024' (scalar, sse2, avx2, avx512, neon)"), std::string::npos) << text;
  if (machine_isa() < Isa::avx512) {
    std::tie(status, text) = tritri_bench("--isa avx512 --list");
    EXPECT_EQ(status, 2);
    EXPECT_NE(text.find("runs at most " + std::string(to_string(machine_isa()))), std::string::npos) << text;
  }
  const auto json = scratch("cli-isa");
  std::tie(status, text) = tritri_bench("--quick --isa sse2 --mode both --algo exact --level overlap --workload ratio:0.5 "
                                        "--pool 512 --no-cache --json '" + json.string() + "'");
  ASSERT_EQ(status, 0) << text;
  const auto doc = nlohmann::json::parse(std::ifstream(json));
  EXPECT_EQ(doc["tritri"]["isa"], "sse2");
  EXPECT_EQ(doc["context"]["isa"], "sse2");
  EXPECT_EQ(doc["tritri"]["isa_machine"], std::string(to_string(machine_isa())));
  std::size_t exact_results = 0;
  for (const auto& r : doc["tritri"]["results"]) {
    if (r["algorithm"] != "exact") continue;
    ++exact_results;
    // Path counters are counted through the batch entry: only the batch result carries them.
    if (r["mode"] == "batch") EXPECT_EQ(r["path_counters"].value("isa:sse2", 0), 1) << r.dump();
    else EXPECT_FALSE(r.contains("path_counters")) << r.dump();
  }
  EXPECT_EQ(exact_results, 2u);  // call and batch
  std::filesystem::remove(json);
}

}  // namespace
}  // namespace tritri::bench
