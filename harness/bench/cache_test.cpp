// Tests of what `tritri bench` keeps between runs: the labelled pools (pool_cache.hpp) and the
// checks (check_cache.hpp) are reused only under the same key, and a corrupt or stale entry is
// detected, reported and rebuilt, never trusted. Also: check and bench record the same corpus.
#include "harness/bench/check_cache.hpp"
#include "harness/bench/pool_cache.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace tritri::bench {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("tritri-cache-test-" + std::to_string(getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

WorkloadInput small_input(std::uint64_t seed) { return WorkloadInput{{300, seed}, true, {}, {}}; }

Planned cached(const fs::path& dir, std::uint64_t seed, std::string& log) {
  std::ostringstream out;
  const auto selected = select_workloads({"ratio:0.5"}, {});
  Planned p = build_pools_cached(selected, small_input(seed), {true, dir.string()}, out);
  log = out.str();
  return p;
}

fs::path only_file(const fs::path& dir, const std::string& prefix) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().starts_with(prefix)) return e.path();
  return {};
}

TEST(PoolCache, ASecondBuildReadsTheSamePoolsFromTheCache) {
  const fs::path dir = scratch("reuse");
  std::string log;
  const Planned first = cached(dir, 5, log);
  EXPECT_NE(log.find("kept in the cache"), std::string::npos) << log;
  const Planned second = cached(dir, 5, log);
  EXPECT_NE(log.find("read from the cache"), std::string::npos) << log;
  ASSERT_EQ(first.pools.size(), second.pools.size());
  EXPECT_EQ(hash_pools({&first.pools[0].pool}), hash_pools({&second.pools[0].pool}));
  EXPECT_EQ(first.pools[0].pool.truth.size(), second.pools[0].pool.truth.size());
  EXPECT_EQ(first.cache_key, second.cache_key);
  const Planned other = cached(dir, 6, log);  // another seed: another entry, built afresh
  EXPECT_NE(log.find("kept in the cache"), std::string::npos) << log;
  EXPECT_NE(hash_pools({&other.pools[0].pool}), hash_pools({&first.pools[0].pool}));
}

TEST(PoolCache, ACorruptEntryIsRebuiltNotTrusted) {
  const fs::path dir = scratch("corrupt");
  std::string log;
  const Planned first = cached(dir, 5, log);
  const fs::path entry = only_file(dir, "pools-");
  ASSERT_FALSE(entry.empty());
  {
    std::fstream f(entry, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(fs::file_size(entry) / 2));
    f.put('\x5a');
  }
  const Planned again = cached(dir, 5, log);
  EXPECT_NE(log.find("checksum mismatch"), std::string::npos) << log;
  EXPECT_EQ(hash_pools({&first.pools[0].pool}), hash_pools({&again.pools[0].pool}));
  fs::resize_file(entry, fs::file_size(entry) - 100);
  cached(dir, 5, log);
  EXPECT_NE(log.find("not used"), std::string::npos) << log;
}

TEST(PoolCache, AnEntryMadeForOtherSettingsIsStale) {
  const fs::path dir = scratch("stale");
  std::string log;
  cached(dir, 5, log);
  const fs::path five = only_file(dir, "pools-");
  cached(dir, 6, log);
  fs::path six;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path() != five && e.path().filename().string().starts_with("pools-")) six = e.path();
  ASSERT_FALSE(six.empty());
  fs::copy_file(five, six, fs::copy_options::overwrite_existing);  // seed 5's pools under seed 6's name
  cached(dir, 6, log);
  EXPECT_NE(log.find("stale"), std::string::npos) << log;
}

TEST(CheckCache, KeepsCleanChecksUnderTheSameKeyOnly) {
  const fs::path dir = scratch("checks");
  const PoolCacheOptions where{true, dir.string()};
  Options options;
  std::ostringstream log;
  {
    CheckCache c(where, "pools key\n", options, log);
    EXPECT_EQ(c.find("a/overlap/ratio:0.50"), nullptr);
    c.put("a/overlap/ratio:0.50", {{3, 1}, OpCounts{1, 2, 3, 4, 5}});
    c.put("b/relation/ratio:0.50", {{0, 0}, std::nullopt});
    c.save(log);
  }
  {
    CheckCache c(where, "pools key\n", options, log);
    const CachedCheck* a = c.find("a/overlap/ratio:0.50");
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(a->score.wrong, 3u);
    EXPECT_EQ(a->score.unsupported, 1u);
    ASSERT_TRUE(a->ops.has_value());
    EXPECT_EQ(*a->ops, (OpCounts{1, 2, 3, 4, 5}));
    const CachedCheck* b = c.find("b/relation/ratio:0.50");
    ASSERT_NE(b, nullptr);
    EXPECT_FALSE(b->ops.has_value());
  }
  options.count_operations = false;  // another setting that shapes a check: nothing reused
  std::ostringstream stale;
  CheckCache c(where, "pools key\n", options, stale);
  EXPECT_EQ(c.find("a/overlap/ratio:0.50"), nullptr);
  EXPECT_NE(stale.str().find("stale"), std::string::npos) << stale.str();
  CheckCache off({true, dir.string()}, "", Options{}, log);  // pools not cached: no check cache
  EXPECT_EQ(off.find("a/overlap/ratio:0.50"), nullptr);
}

TEST(CheckCache, ACorruptFileIsIgnoredAndReported) {
  const fs::path dir = scratch("checks-corrupt");
  const PoolCacheOptions where{true, dir.string()};
  std::ostringstream log;
  CheckCache c(where, "k\n", Options{}, log);
  c.put("a/overlap/ratio:0.50", {{3, 1}, std::nullopt});
  c.save(log);
  const fs::path file = only_file(dir, "checks-");
  std::string text;
  {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    text = s.str();
  }
  text.replace(text.find("\t3\t"), 3, "\t0\t");  // a forged score
  std::ofstream(file) << text;
  std::ostringstream again;
  CheckCache d(where, "k\n", Options{}, again);
  EXPECT_EQ(d.find("a/overlap/ratio:0.50"), nullptr);
  EXPECT_NE(again.str().find("checksum mismatch"), std::string::npos) << again.str();
}

std::string run(const std::string& command) {
  const fs::path log = scratch("cli-log") / "out.txt";
  const int status = std::system((command + " > '" + log.string() + "' 2>&1").c_str());
  std::ifstream in(log);
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_EQ(status, 0) << command << "\n" << s.str();
  return s.str();
}

TEST(BenchCache, ASecondRunReusesPoolsAndChecksAndRecordsTheCorpusAsCheckDoes) {
  const fs::path dir = scratch("cli");
  const std::string tritri = std::string(TRITRI_BINARY_DIR) + "/bin/tritri";
  const std::string cases = std::string(TRITRI_SOURCE_DIR) + "/cases/builtin.cases";
  const std::string bench = tritri + " bench --quick --algo moller97 --workload ratio:0.5 --workload family --cases '" +
                            cases + "' --cache '" + dir.string() + "' --json '" + (dir / "bench.json").string() + "'";
  const std::string first = run(bench);
  EXPECT_NE(first.find("pools: kept in the cache"), std::string::npos) << first;
  const std::string second = run(bench);
  EXPECT_NE(second.find("pools: read from the cache"), std::string::npos) << second;
  EXPECT_NE(second.find("read from the cache, " + (dir / "checks-").string()), std::string::npos) << second;
  run(tritri + " check --quiet --algo moller97 --json '" + (dir / "check.json").string() + "' '" + cases + "'");
  const auto bench_doc = nlohmann::json::parse(std::ifstream(dir / "bench.json"));
  const auto check_doc = nlohmann::json::parse(std::ifstream(dir / "check.json"));
  ASSERT_TRUE(bench_doc["tritri"].contains("corpus"));
  EXPECT_EQ(bench_doc["tritri"]["corpus"]["hash"], check_doc["corpus"]["hash"]);
  EXPECT_EQ(bench_doc["tritri"]["corpus"]["files"][0]["path"], cases);
}

}  // namespace
}  // namespace tritri::bench
