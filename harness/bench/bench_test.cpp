// Tests of `tritri bench`: the pools are what they claim, the workload registry parses and
// builds what it is asked for, the counting scalar counts, and the command runs end to end and
// writes Google Benchmark's JSON with tritri's context keys and the reference's ratios.
// No test here asserts anything about time: speed claims come from the benchmark only.
#include "harness/bench/bench.hpp"
#include "harness/bench/pools.hpp"
#include "harness/bench/test_support.hpp"
#include "harness/bench/workload.hpp"
#include "harness/bench/workloads/family.hpp"
#include "harness/bench/workloads/ratio.hpp"
#include "harness/bench/workloads/type.hpp"
#include "algorithms/moller97/moller97.hpp"
#include "tritri/add_level.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace tritri::bench {
namespace {

std::set<std::string> distinct_pairs(const Pool& p) {
  std::set<std::string> s;
  for (const auto& pair : p.pairs) {
    std::string bytes;
    for (const Triangle* t : {&pair.t1, &pair.t2})
      for (const auto& v : t->v) bytes.append(reinterpret_cast<const char*>(v.data()), 3 * sizeof(double));
    s.insert(bytes);
  }
  return s;
}

TEST(BenchPools, RatioPoolsHaveExactlyTheRequestedRatioPerTheOracle) {
  const std::size_t n = 1000;
  const auto pools = ratio_pools({0.0, 0.1, 0.45, 1.0}, {n, 7});
  ASSERT_EQ(pools.size(), 4u);
  std::array<std::size_t, 5> stages{};
  for (const Pool& p : pools) {
    SCOPED_TRACE(p.name());
    ASSERT_EQ(p.size(), n);
    ASSERT_EQ(p.truth.size(), n);
    const double r = std::stod(p.value);
    std::size_t meet = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const OracleRecord record = oracle_label(p.pairs[i]);  // the oracle again, not the stored label
      EXPECT_FALSE(record.degenerate);
      EXPECT_EQ(record.overlap, p.truth[i].overlap);
      EXPECT_EQ(record.stage, p.truth[i].stage);
      meet += record.overlap;
    }
    EXPECT_EQ(meet, static_cast<std::size_t>(std::llround(r * n)));
    EXPECT_EQ(p.intersecting(), meet);
    EXPECT_EQ(distinct_pairs(p).size(), n) << "a pool repeats a pair";
    const auto mix = p.stage_mix();
    for (std::size_t k = 0; k < 5; ++k) stages[k] += mix[k];
  }
  // Mixed sizes: every exit stage of a plane-rejecting test occurs.
  EXPECT_GT(stages[static_cast<std::size_t>(Stage::plane2)], 0u);
  EXPECT_GT(stages[static_cast<std::size_t>(Stage::plane1)], 0u);
  EXPECT_GT(stages[static_cast<std::size_t>(Stage::coplanar)], 0u);
  EXPECT_GT(stages[static_cast<std::size_t>(Stage::interval)], 0u);
  EXPECT_EQ(stages[static_cast<std::size_t>(Stage::degenerate)], 0u);
}

TEST(BenchPools, TypePoolsHoldOnlyTheirIntersectionType) {
  for (Dimension d : kTypes) {
    const Pool p = type_pool(d, {300, 11});
    SCOPED_TRACE(p.name());
    ASSERT_EQ(p.size(), 300u);
    EXPECT_EQ(distinct_pairs(p).size(), p.size());
    for (const auto& pair : p.pairs) {
      const OracleRecord record = oracle_label(pair);
      EXPECT_EQ(record.dimension, d);
      EXPECT_FALSE(record.degenerate);
    }
  }
}

TEST(BenchPools, PoolsAreDeterministicForASeed) {
  const auto a = ratio_pools({0.3}, {500, 42});
  const auto b = ratio_pools({0.3}, {500, 42});
  const auto c = ratio_pools({0.3}, {500, 43});
  EXPECT_EQ(hash_pools({&a[0]}), hash_pools({&b[0]}));
  EXPECT_NE(hash_pools({&a[0]}), hash_pools({&c[0]}));
  const Pool t1 = type_pool(Dimension::point, {200, 42}), t2 = type_pool(Dimension::point, {200, 42});
  EXPECT_EQ(hash_pools({&t1}), hash_pools({&t2}));
}

TEST(BenchPools, FamilyPoolsGroupCasesByFamily) {
  const auto cases = read_case_file(std::string(TRITRI_SOURCE_DIR) + "/cases/builtin.cases");
  const auto pools = family_pools(cases, {65536, 1});
  std::size_t total = 0;
  for (const auto& p : pools) {
    EXPECT_EQ(p.workload, "family");
    total += p.size();
  }
  EXPECT_GT(total, 0u);
  EXPECT_LE(total, cases.size());
}

TEST(CountingScalar, CountsATinyKnownComputation) {
  op_counts() = {};
  const Counted a = 1.5, b = 2.0;
  const Counted c = (a + b) * (a - b) / b;  // 2 add, 1 mul, 1 div
  EXPECT_TRUE(c < Counted(0));              // 1 cmp
  EXPECT_DOUBLE_EQ(c.value(), -0.875);
  EXPECT_EQ(op_counts(), (OpCounts{2, 1, 1, 1, 0}));

  op_counts() = {};
  const Vec3<Counted> u(Counted(1), Counted(2), Counted(3)), v(Counted(4), Counted(5), Counted(6));
  const Counted d = u.dot(v);  // 3 mul, 2 add
  EXPECT_EQ(d.value(), 32.0);
  EXPECT_EQ(op_counts(), (OpCounts{2, 3, 0, 0, 0}));

  op_counts() = {};
  const Vec3<Counted> w = u.cross(v);  // 6 mul, 3 add (subtractions)
  EXPECT_EQ(w[0].value(), -3.0);
  EXPECT_EQ(w[1].value(), 6.0);
  EXPECT_EQ(w[2].value(), -3.0);
  EXPECT_EQ(op_counts(), (OpCounts{3, 6, 0, 0, 0}));

  op_counts() = {};
  using std::abs;
  using std::sqrt;
  const Counted s = sqrt(abs(Counted(-16.0)));  // abs is free, 1 sqrt
  EXPECT_EQ(s.value(), 4.0);
  Counted x = 1.0;
  x += 2;
  x -= 0.5;
  x *= 4;
  x /= 5;
  EXPECT_EQ(x.value(), 2.0);
  EXPECT_TRUE(x == Counted(2.0) && x != Counted(3.0) && x <= 2 && x >= 2 && !(x > 2));
  EXPECT_EQ(op_counts(), (OpCounts{2, 1, 1, 5, 1}));
}

TEST(CountingScalar, MollerCountedAnswersAgreeWithDouble) {
  const Algorithm* a = registry().find("moller97");
  ASSERT_NE(a, nullptr);
  ASSERT_TRUE(a->has_batch(Level::overlap, Scalar::counted));
  const Pool p = ratio_pools({0.5}, {400, 3})[0];
  std::vector<Overlap> plain(p.size()), counted(p.size());
  a->batch<Level::overlap>()(p.pairs.data(), p.size(), plain.data());
  a->batch<Level::overlap>(Scalar::counted)(p.pairs.data(), p.size(), counted.data());
  EXPECT_EQ(plain, counted);
  const auto ops = count_operations(*a, Level::overlap, p);
  ASSERT_TRUE(ops.has_value());
  // At least the first plane and its three distances for every pair: 6 mul + 3 add for the
  // normal, 3 dot products of 3 mul + 2 add, and one offset dot product.
  EXPECT_GE(ops->mul, p.size() * (6 + 4 * 3));
  EXPECT_GT(ops->cmp, 0u);
  EXPECT_EQ(count_operations(*a, Level::relation, p), std::nullopt);
}

TEST(BenchScore, CountsWrongAndUnsupportedAnswers) {
  Pool p;
  p.truth = {{true, false, Relation::cross, Dimension::segment, Stage::interval},
             {false, false, Relation::disjoint, Dimension::none, Stage::plane2},
             {true, false, Relation::touch_point, Dimension::point, Stage::interval}};
  const auto o = score_overlap(p, {Overlap::yes, Overlap::yes, Overlap::unsupported});
  EXPECT_EQ(o.wrong, 1u);
  EXPECT_EQ(o.unsupported, 1u);
  const auto r = score_relation(p, {answer_with(Relation::cross), {Relation::unknown, Dimension::none},
                                    answer_with(Relation::touch_segment)});
  EXPECT_EQ(r.wrong, 1u);
  EXPECT_EQ(r.unsupported, 0u);
  SegmentAnswer empty;
  empty.kind = SegmentKind::empty;
  const auto s = score_segment(p, {empty, empty, SegmentAnswer{}});
  EXPECT_EQ(s.wrong, 1u);
  EXPECT_EQ(s.unsupported, 1u);
}

// A stage hook as an algorithm folder would register it.
TrianglePair mirrored(const TrianglePair& p) {
  TrianglePair q = p;
  for (Triangle* t : {&q.t1, &q.t2})
    for (auto& v : t->v) v = -v;
  return q;
}
double first_coordinate(const TrianglePair& p) { return p.t1[0][0] + p.t2[2][2]; }

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

WorkloadInput input_of(std::size_t size, std::uint64_t seed) {
  WorkloadInput input;
  input.pool = {size, seed};
  return input;
}

std::vector<std::string> values_of(const std::string& spec) { return select_workloads({spec}, {}).at(0).values; }

TEST(BenchWorkloads, AnUnknownWorkloadIsAClearErrorListingTheKnownOnes) {
  for (const char* kind : {"ratio", "type", "family", "stage", "size"}) EXPECT_NE(find_workload(kind), nullptr) << kind;
  const std::string e = error_of([] { select_workloads({"sizes:4096"}, {}); });
  EXPECT_NE(e.find("unknown workload 'sizes:4096'"), std::string::npos) << e;
  for (const char* usage : {"ratio[:R]", "type[:T]", "family[:F]", "stage", "size[:N]"})
    EXPECT_NE(e.find(usage), std::string::npos) << e;
}

TEST(BenchWorkloads, ValuesAreCanonicalAndBadOnesAreRefused) {
  EXPECT_EQ(values_of("ratio:0.5"), std::vector<std::string>{"0.50"});
  EXPECT_EQ(values_of("ratio").size(), 11u);
  EXPECT_EQ(values_of("type:point"), std::vector<std::string>{"point"});
  EXPECT_EQ(values_of("type").size(), 4u);
  EXPECT_EQ(values_of("size"), (std::vector<std::string>{"4096", "16384", "65536", "262144", "1048576"}));
  EXPECT_EQ(values_of("size:4096"), std::vector<std::string>{"4096"});
  EXPECT_EQ(select_workloads({"ratio:0.5", "ratio:0.50", "ratio:0.1"}, {}).at(0).values,
            (std::vector<std::string>{"0.50", "0.10"}));
  for (const char* bad : {"ratio:1.5", "ratio:x", "ratio:", "type:volume", "size:0", "size:-3", "size:4k",
                          "stage:transform", "family:"})
    EXPECT_FALSE(error_of([&] { select_workloads({bad}, {}); }).empty()) << bad;
}

TEST(BenchWorkloads, SizeBuildsTheHalfIntersectingRatioPoolOfThatSize) {
  const Planned planned = build_pools(select_workloads({"size:4096"}, {}), input_of(512, 5));
  ASSERT_EQ(planned.pools.size(), 1u);
  const Pool& p = planned.pools[0].pool;
  EXPECT_EQ(p.name(), "size:4096");
  EXPECT_EQ(p.size(), 4096u);  // --pool (512 here) does not apply to it
  EXPECT_EQ(p.intersecting(), 2048u);
  EXPECT_EQ(distinct_pairs(p).size(), p.size());
  for (std::size_t i = 0; i < p.size(); i += 16) EXPECT_EQ(oracle_label(p.pairs[i]).overlap, p.truth[i].overlap);
  EXPECT_TRUE(planned.pools[0].levels);
  EXPECT_FALSE(planned.pools[0].stages);
}

TEST(BenchWorkloads, SmallerSizesAreDrawnFromTheSameCandidatesAsLargerOnes) {
  const Planned planned = build_pools(select_workloads({"size:1000", "size:300"}, {}), input_of(64, 5));
  ASSERT_EQ(planned.pools.size(), 2u);
  const Pool& small = planned.pools[0].pool;
  const Pool& large = planned.pools[1].pool;
  EXPECT_EQ(small.name(), "size:300");
  EXPECT_EQ(large.name(), "size:1000");
  const auto in_large = distinct_pairs(large);
  for (const auto& bytes : distinct_pairs(small)) EXPECT_TRUE(in_large.count(bytes));
}

TEST(BenchWorkloads, StageIsTimedOnTheRatioPoolOfTheSameName) {
  Planned planned = build_pools(select_workloads({"ratio:0.3", "stage", "ratio:0.5"}, {}), input_of(256, 9));
  ASSERT_EQ(planned.pools.size(), 2u);
  EXPECT_EQ(planned.pools[0].pool.name(), "ratio:0.30");
  EXPECT_TRUE(planned.pools[0].levels);
  EXPECT_FALSE(planned.pools[0].stages);
  EXPECT_EQ(planned.pools[1].pool.name(), "ratio:0.50");
  EXPECT_TRUE(planned.pools[1].levels);
  EXPECT_TRUE(planned.pools[1].stages);
  planned = build_pools(select_workloads({"stage"}, {}), input_of(256, 9));
  ASSERT_EQ(planned.pools.size(), 1u);
  EXPECT_EQ(planned.pools[0].pool.name(), "ratio:0.50");
  EXPECT_FALSE(planned.pools[0].levels);  // built for the stages only
  EXPECT_TRUE(planned.pools[0].stages);
}

TEST(BenchWorkloads, TheDefaultSetLeavesOutSizeAndHasStageOnlyWithStages) {
  auto kinds = [](const std::vector<const Algorithm*>& algorithms) {
    std::vector<std::string> k;
    for (const Selected& s : select_workloads({}, algorithms)) k.push_back(s.workload->kind());
    return k;
  };
  Algorithm plain;
  plain.name = "plain";
  Algorithm staged = plain;
  staged.stages = {{"read", stage_run<&first_coordinate>, nullptr}};
  EXPECT_EQ(kinds({&plain}), (std::vector<std::string>{"ratio", "type", "family"}));
  EXPECT_EQ(kinds({&plain, &staged}), (std::vector<std::string>{"ratio", "type", "family", "stage"}));
}

// A small real run on ratio:0.50, timing moller97 and guigue03.
Options tiny_run(const std::filesystem::path& json) {
  return small_run({registry().find("moller97"), registry().find("guigue03")}, 512, 2, json.string());
}

TEST(BenchReference, TimesAreRelativeToTheNamedAlgorithmUnderOneKey) {
  const auto path = std::filesystem::temp_directory_path() / ("tritri-bench-reference-test-" + std::to_string(getpid()) + ".json");
  Options o = tiny_run(path);
  o.reference = "guigue03";
  std::ostringstream out;
  ASSERT_EQ(run(o, out), 0) << out.str();
  EXPECT_NE(out.str().find("relative to guigue03/overlap"), std::string::npos) << out.str();
  std::ifstream in(path);
  const auto doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc["tritri"]["reference"], "guigue03");
  EXPECT_EQ(doc["tritri"]["reference_level"], "overlap");
  EXPECT_EQ(doc["context"]["reference"], "guigue03");
  std::map<std::string, double> median, relative;
  for (const auto& r : doc["tritri"]["results"]) {
    EXPECT_FALSE(r.contains("relative_to_moller97"));
    ASSERT_TRUE(r.contains("relative_to_reference")) << r.dump();
    median[r["name"]] = r["ns_per_pair_median"];
    relative[r["name"]] = r["relative_to_reference"];
  }
  EXPECT_DOUBLE_EQ(relative.at("guigue03/overlap/ratio:0.50/call"), 1.0);
  EXPECT_DOUBLE_EQ(relative.at("moller97/overlap/ratio:0.50/call"),
                   median.at("moller97/overlap/ratio:0.50/call") / median.at("guigue03/overlap/ratio:0.50/call"));
  std::filesystem::remove(path);
}

TEST(BenchReference, AnUnknownReferenceIsAUsageError) {
  Options o = tiny_run("");
  o.reference = "nosuch";
  std::ostringstream out;
  const std::string e = error_of([&] { run(o, out); });
  EXPECT_NE(e.find("unknown reference algorithm 'nosuch'"), std::string::npos) << e;
  EXPECT_NE(e.find("moller97"), std::string::npos) << e;  // the known ones are listed
  const std::string command = std::string(TRITRI_BINARY_DIR) + "/bin/tritri bench --reference nosuch --list > /dev/null 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
}

TEST(BenchRun, StageHooksAreTimedAndWritten) {
  Algorithm a;
  a.name = "stagetest";
  a.set_batch<Level::overlap>(Scalar::double_, overlap_batch<&moller97::overlap<double, true>>);
  a.stages = {{"mirror", stage_run<&mirrored>, nullptr},
              {"read", stage_run<&first_coordinate>, stage_prepare<&mirrored>}};
  Options o = quick_options();
  o.algorithms = {&a};
  o.workloads = {"stage"};
  o.pool_size = 512;
  o.repetitions = 2;
  o.min_time = 0.001;
  o.count_operations = false;
  const auto path = std::filesystem::temp_directory_path() / ("tritri-bench-stage-test-" + std::to_string(getpid()) + ".json");
  o.json_path = path.string();
  std::ostringstream out;
  ASSERT_EQ(run(o, out), 0) << out.str();
  std::ifstream in(path);
  const auto doc = nlohmann::json::parse(in);
  std::set<std::string> names;
  for (const auto& b : doc["benchmarks"]) names.insert(b["name"].get<std::string>());
  // Stages are batch functions: timed in batch mode even when only call mode is asked for.
  EXPECT_TRUE(names.count("stagetest/stage:mirror/ratio:0.50/batch")) << out.str();
  EXPECT_TRUE(names.count("stagetest/stage:read/ratio:0.50/batch"));
  EXPECT_FALSE(names.count("stagetest/overlap/ratio:0.50/call"));  // the stage pool is for the stages only
  for (const auto& r : doc["tritri"]["results"]) {
    if (r["algorithm"] != "stagetest") continue;
    EXPECT_TRUE(r["level"].is_null()) << r.dump();  // "level" means a level; the stage has its own field
    EXPECT_TRUE(r["stage"] == "mirror" || r["stage"] == "read") << r.dump();
    EXPECT_EQ(r["mode"], "batch");
  }
  std::filesystem::remove(path);
}

// A test with path counters gets them recorded per pool, from one pass over exactly that pool.
std::uint64_t g_pairs_seen = 0, g_resets = 0;
void count_reset() {
  g_pairs_seen = 0;
  ++g_resets;
}
CounterList count_read() { return {{"pairs", g_pairs_seen}, {"resets", g_resets}}; }
void counting_overlap(const TrianglePair* pairs, std::size_t n, Overlap* out) {
  g_pairs_seen += n;
  overlap_batch<&moller97::overlap<double, true>>(pairs, n, out);
}

TEST(BenchRun, PathCountersAreRecordedPerPoolFromOnePass) {
  Algorithm a;
  a.name = "countertest";
  a.set_batch<Level::overlap>(Scalar::double_, &counting_overlap);
  a.counters = {&count_reset, &count_read};
  Options o = quick_options();
  o.algorithms = {&a};
  o.workloads = {"ratio:0.5", "type:point"};
  o.modes = {Mode::call, Mode::batch};
  o.pool_size = 300;
  o.repetitions = 1;
  o.min_time = 0.001;
  o.count_operations = false;
  o.isolation.enabled = false;
  const auto path = std::filesystem::temp_directory_path() / ("tritri-bench-counters-" + std::to_string(getpid()) + ".json");
  o.json_path = path.string();
  std::ostringstream out;
  ASSERT_EQ(run(o, out), 0) << out.str();
  const auto doc = nlohmann::json::parse(std::ifstream(path));
  std::size_t seen = 0;
  for (const auto& r : doc["tritri"]["results"]) {
    if (r["algorithm"] != "countertest") continue;
    // Counted through the batch entry: they describe the batch mode's path, and only it has them.
    if (r["mode"] == "call") {
      EXPECT_FALSE(r.contains("path_counters")) << r["name"];
      continue;
    }
    ASSERT_TRUE(r.contains("path_counters")) << r["name"];
    EXPECT_EQ(r["path_counters"]["pairs"], r["pool_size"]) << r["name"];
    ++seen;
  }
  EXPECT_EQ(seen, 2u);
  EXPECT_EQ(g_resets, 2u);
  std::filesystem::remove(path);
}

// The default set of workloads (what `tritri bench` and `--quick` run when none is named).
TEST(BenchCli, TheDefaultWorkloadsAreTheRatiosTheTypesAndTheFamilies) {
  std::map<std::string, std::size_t> values_of;
  for (const Selected& s : select_workloads({}, {})) values_of[s.workload->kind()] = s.values.size();
  EXPECT_EQ(values_of["ratio"], 11u);
  EXPECT_EQ(values_of["type"], 4u);
  EXPECT_GE(values_of["family"], 1u);  // the corpus generator's families
}

// Every registered algorithm end to end, on the three ratio pools of the timing modes' targets and
// the four type pools (the default set's other pools take the same path: the test above lists them).
TEST(BenchCli, QuickRunsEndToEndAndWritesJsonWithTheContextKeys) {
  const auto dir = std::filesystem::temp_directory_path() / ("tritri-bench-cli-test-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const auto json = dir / "quick.json", log = dir / "quick.log";
  const std::string command = std::string(TRITRI_BINARY_DIR) + "/bin/tritri bench --quick --workload ratio:0 " +
                              "--workload ratio:0.5 --workload ratio:1 --workload type --json '" + json.string() +
                              "' > '" + log.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream log_in(log);
  const std::string output((std::istreambuf_iterator<char>(log_in)), std::istreambuf_iterator<char>());
  ASSERT_EQ(status, 0) << output;
  EXPECT_NE(output.find("ns per pair"), std::string::npos) << output;
  EXPECT_NE(output.find("harness: floor"), std::string::npos) << output;

  std::ifstream in(json);
  const auto doc = nlohmann::json::parse(in);  // throws (and fails the test) on invalid JSON
  ASSERT_TRUE(doc.contains("context"));
  const auto& context = doc["context"];
  for (const char* key : {"git_sha", "git_dirty", "compiler", "compiler_flags", "cgal_version", "fcl_version",
                          "eigen_version", "corpus_hash", "seed", "pool_size", "date", "host_name", "num_cpus"})
    EXPECT_TRUE(context.contains(key)) << key;
  EXPECT_EQ(context["pool_size"], "4096");
  EXPECT_NE(context["compiler_flags"].get<std::string>().find("-ffp-contract=off"), std::string::npos);

  std::set<std::string> names;
  for (const auto& b : doc["benchmarks"]) {
    names.insert(b["run_name"].get<std::string>());
    if (b["run_type"] == "iteration") {
      EXPECT_TRUE(b.contains("items_per_second"));
      EXPECT_TRUE(b.contains("wrong"));
      EXPECT_TRUE(b.contains("per_pair"));
    }
  }
  for (const char* name : {"moller97/overlap/ratio:0.00/call", "moller97/overlap/ratio:0.50/call",
                           "moller97/overlap/ratio:1.00/call", "moller97/overlap/type:disjoint/call",
                           "moller97/overlap/type:point/call", "moller97/overlap/type:segment/call",
                           "moller97/overlap/type:area/call", "moller97-segment/segment/ratio:0.50/call"})
    EXPECT_TRUE(names.count(name)) << name;
  // Every registered algorithm of the default selection (build variants run when named) on every
  // level it answers: timed, or reported as not timed with the faults (crash, hang) that kept it
  // out, paste-ready (named without a mode: it is checked, not timed); and no build variant.
  std::set<std::string> not_timed;
  for (const auto& e : doc["tritri"]["not_timed"]) {
    EXPECT_FALSE(e["faults"].empty()) << e["name"];
    not_timed.insert(e["name"].get<std::string>());
  }
  // A process peer (algorithms/README.md) times itself: its results stand apart, under self_timed.
  for (const auto& e : doc["tritri"]["self_timed"]) {
    EXPECT_EQ(e["timed_by"], "plug-in") << e["name"];
    names.insert(e["name"].get<std::string>());
  }
  for (const auto& a : registry().all())
    for (Level level : {Level::overlap, Level::relation, Level::segment})
      if (a.answers(level)) {
        const std::string name = a.name + "/" + std::string(to_string(level)) + "/ratio:0.50";
        const bool timed = names.count(name + "/call") > 0;
        if (a.build.empty()) EXPECT_TRUE(timed || not_timed.count(name)) << name;
        else EXPECT_FALSE(timed || not_timed.count(name)) << name;
      }

  ASSERT_TRUE(doc.contains("tritri"));
  std::map<std::string, int> pools_of;
  for (const auto& p : doc["tritri"]["pools"]) {
    const std::string name = p["name"];
    ++pools_of[name.substr(0, name.find(':'))];
  }
  EXPECT_EQ(pools_of["ratio"], 3);
  EXPECT_EQ(pools_of["type"], 4);
  EXPECT_EQ(pools_of.size(), 2u);
  bool moller_ops = false;
  for (const auto& r : doc["tritri"]["results"])
    if (r["name"] == "moller97/overlap/ratio:0.50/call") {
      moller_ops = r.contains("ops_per_pair");
      EXPECT_DOUBLE_EQ(r["relative_to_reference"].get<double>(), 1.0);
    }
  EXPECT_TRUE(moller_ops);
  EXPECT_EQ(doc["tritri"]["reference"], "moller97");
  EXPECT_EQ(context["reference"], "moller97");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tritri::bench
