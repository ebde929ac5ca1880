// The runner answers as the entry points do, and every built-in algorithm's one-pair entry
// answers as its batch does (the coming per-call timing relies on it).
#include "harness/run/runner.hpp"

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace tritri {
namespace {

std::vector<TrianglePair> builtin_pairs(const Algorithm& a) {
  std::vector<TrianglePair> pairs;
  for (const Case& c : read_case_file(std::string(TRITRI_SOURCE_DIR) + "/cases/builtin.cases"))
    if (a.accepts_degenerate || !has_degenerate_triangle(c.pair)) pairs.push_back(c.pair);
  return pairs;
}

bool same(Overlap a, Overlap b) { return a == b; }
bool same(const RelationAnswer& a, const RelationAnswer& b) {
  return a.relation == b.relation && a.dimension == b.dimension;
}
// Bit for bit, so that a NaN endpoint equals itself.
bool same(const SegmentAnswer& a, const SegmentAnswer& b) {
  return a.kind == b.kind && std::memcmp(a.p.data(), b.p.data(), sizeof(double) * 3) == 0 &&
         std::memcmp(a.q.data(), b.q.data(), sizeof(double) * 3) == 0;
}

TEST(Runner, AnswersEachLevelAskedAsTheBatchEntryPointDoes) {
  const Algorithm* a = registry().find("moller97-segment");
  ASSERT_NE(a, nullptr);
  const auto pairs = builtin_pairs(*a);
  const std::vector<std::string> names(pairs.size(), "unused");
  const RunAnswers got = run_algorithm(*a, names, pairs, {Level::segment});
  EXPECT_TRUE(got.faults.empty());
  EXPECT_TRUE(got.overlap.empty()) << "the overlap level was not asked for";
  ASSERT_EQ(got.segment.size(), pairs.size());
  std::vector<SegmentAnswer> direct(pairs.size());
  a->batch<Level::segment>()(pairs.data(), pairs.size(), direct.data());
  for (std::size_t i = 0; i < pairs.size(); ++i) EXPECT_TRUE(same(got.segment[i], direct[i])) << "pair " << i;
}

TEST(OnePair, EveryBuiltinAlgorithmHasOneAtEachLevelAndItAnswersAsItsBatch) {
  for (const Algorithm& a : registry().all()) {
    // A second build (NAME@v3fma) may fuse products differently where the kernel is inlined into
    // the batch loop and where it is not: its two entries need not agree bit for bit.
    if (!a.build.empty()) continue;
    // A process peer (Algorithm::process) answers through the runner, over the process protocol:
    // it has no entry points here.
    if (!a.process.empty()) continue;
    const auto pairs = builtin_pairs(a);
    for_each_level([&](auto level) {
      if (!a.answers(level())) return;
      const auto one_pair = a.one_pair<level()>();
      ASSERT_NE(one_pair, nullptr) << a.name << " has no one-pair entry at " << to_string(level());
      std::vector<AnswerOf<level()>> batch(pairs.size());
      a.batch<level()>()(pairs.data(), pairs.size(), batch.data());
      for (std::size_t i = 0; i < pairs.size(); ++i)
        EXPECT_TRUE(same(one_pair(pairs[i]), batch[i])) << a.name << " " << to_string(level()) << ", pair " << i;
    });
  }
}

TEST(OnePair, NameAtFloatHasNone) {
  const auto on_float = registry().find("moller97")->on_scalar(Scalar::float_);
  ASSERT_TRUE(on_float.has_value());
  EXPECT_NE(on_float->batch<Level::overlap>(), nullptr);
  EXPECT_EQ(on_float->one_pair<Level::overlap>(), nullptr);
}

}  // namespace
}  // namespace tritri
