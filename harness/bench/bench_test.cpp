// Tests of `tritri bench`: the pools are what they claim, the counting scalar counts, and the
// command runs end to end and writes Google Benchmark's JSON with tritri's context keys.
// No test here asserts anything about time: speed claims come from the benchmark only.
#include "harness/bench/bench.hpp"
#include "harness/bench/pools.hpp"
#include "algorithms/moller97/moller97.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

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
  const auto path = std::filesystem::temp_directory_path() / "tritri-bench-stage-test.json";
  o.json_path = path.string();
  std::ostringstream out;
  ASSERT_EQ(run(o, out), 0) << out.str();
  std::ifstream in(path);
  const auto doc = nlohmann::json::parse(in);
  std::set<std::string> names;
  for (const auto& b : doc["benchmarks"]) names.insert(b["name"].get<std::string>());
  EXPECT_TRUE(names.count("stagetest/stage:mirror/ratio:0.50")) << out.str();
  EXPECT_TRUE(names.count("stagetest/stage:read/ratio:0.50"));
  EXPECT_FALSE(names.count("stagetest/overlap/ratio:0.50"));  // the stage pool is for the stages only
  std::filesystem::remove(path);
}

TEST(BenchCli, QuickRunsEndToEndAndWritesJsonWithTheContextKeys) {
  const auto dir = std::filesystem::temp_directory_path() / "tritri-bench-cli-test";
  std::filesystem::create_directories(dir);
  const auto json = dir / "quick.json", log = dir / "quick.log";
  const std::string command = std::string(TRITRI_BINARY_DIR) + "/bin/tritri bench --quick --json '" + json.string() +
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
  for (const char* name : {"moller97/overlap/ratio:0.00", "moller97/overlap/ratio:0.50", "moller97/overlap/ratio:1.00",
                           "moller97/overlap/type:disjoint", "moller97/overlap/type:point",
                           "moller97/overlap/type:segment", "moller97/overlap/type:area",
                           "moller97-segment/segment/ratio:0.50"})
    EXPECT_TRUE(names.count(name)) << name;
  // Every registered algorithm on every level it answers.
  for (const auto& a : registry().all())
    for (Level level : {Level::overlap, Level::relation, Level::segment})
      if (a.answers(level))
        EXPECT_TRUE(names.count(a.name + "/" + std::string(to_string(level)) + "/ratio:0.50")) << a.name;

  ASSERT_TRUE(doc.contains("tritri"));
  std::map<std::string, int> pools_of;
  for (const auto& p : doc["tritri"]["pools"]) {
    const std::string name = p["name"];
    ++pools_of[name.substr(0, name.find(':'))];
  }
  EXPECT_EQ(pools_of["ratio"], 11);
  EXPECT_EQ(pools_of["type"], 4);
  EXPECT_GE(pools_of["family"], 1);  // the corpus generator's families
  bool moller_ops = false;
  for (const auto& r : doc["tritri"]["results"])
    if (r["name"] == "moller97/overlap/ratio:0.50") {
      moller_ops = r.contains("ops_per_pair");
      EXPECT_DOUBLE_EQ(r["relative_to_moller97"].get<double>(), 1.0);
    }
  EXPECT_TRUE(moller_ops);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tritri::bench
