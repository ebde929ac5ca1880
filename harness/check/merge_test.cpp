// Campaigns in parts: the segment errors' summary and the check JSON merge exactly, whatever the
// split; a wrong set of shards is refused by name; the exact-first judge scores as the oracle.
#include "harness/check/check_output.hpp"
#include "harness/check/merge.hpp"
#include "harness/check/stream.hpp"
#include "cases/util/random.hpp"
#include "cases/util/stats.hpp"
#include "tritri/add_level.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sstream>

namespace tritri {
namespace {

const std::string kBuiltin = std::string(TRITRI_SOURCE_DIR) + "/cases/builtin.cases";

bool always_yes(const TrianglePair&) { return true; }
RelationAnswer always_cross(const TrianglePair&) { return answer_with(Relation::cross); }
SegmentAnswer always_point(const TrianglePair& p) { return {SegmentKind::point, p.t1[0], p.t1[0]}; }

Algorithm fake(std::string name) {
  Algorithm a;
  a.name = std::move(name);
  a.set_batch<Level::overlap>(Scalar::double_, overlap_batch<&always_yes>);
  a.set_batch<Level::relation>(Scalar::double_, relation_batch<&always_cross>);
  a.set_batch<Level::segment>(Scalar::double_, segment_batch<&always_point>);
  return a;
}

std::vector<double> some_errors(std::size_t n) {
  Rng rng(7);
  std::vector<double> e;
  for (std::size_t i = 0; i < n; ++i) e.push_back(std::ldexp(rng.unit(), -static_cast<int>(rng.next() % 60)));
  return e;
}

TEST(ErrorSummary, IsExactUpToItsSampleAndTheSameWhateverTheSplit) {
  for (std::size_t n : {std::size_t(7), ErrorSummary::kExactErrors, std::size_t(5000)}) {
    const auto errors = some_errors(n);
    ErrorSummary whole, parts[3];
    for (std::size_t i = 0; i < n; ++i) {
      whole.add(errors[i]);
      parts[(i * 7) % 3].add(errors[i]);
    }
    ErrorSummary joined;
    for (int k : {2, 0, 1}) joined.add(parts[k]);
    EXPECT_EQ(joined.to_json(), whole.to_json()) << n;
    EXPECT_EQ(joined.max(), *std::max_element(errors.begin(), errors.end()));
    const double exact = median(errors);
    if (n <= ErrorSummary::kExactErrors) EXPECT_EQ(joined.median(), exact);
    else EXPECT_NEAR(joined.median(), exact, exact / ErrorSummary::kBinsPerOctave);
    const auto back = ErrorSummary::from_json(whole.to_json(), whole.count(), whole.max());
    EXPECT_EQ(back.to_json(), whole.to_json());
  }
}

TEST(ShardRange, TilesTheInputInOrder) {
  for (std::size_t total : {0, 1, 5, 43, 1000003})
    for (std::size_t n : {1, 2, 4, 7}) {
      std::size_t end = 0;
      for (std::size_t k = 0; k < n; ++k) {
        const CaseRange r = shard_range(k, n, total);
        EXPECT_EQ(r.first, end);
        EXPECT_LE(r.end - r.first, total / n + 1);
        end = r.end;
      }
      EXPECT_EQ(end, total);
    }
}

struct Campaign {
  Algorithm a = fake("a");
  StreamOptions options;
  CheckJsonContext context;
  Campaign() {
    options.chunk = 5;  // several chunks per shard
    context.inputs = {kBuiltin};
    context.corpus = identify_corpus({kBuiltin});
    context.failure_cap = 3;
  }
  nlohmann::json run(std::optional<ShardInfo> shard) {
    StreamOptions o = options;
    CheckJsonContext c = context;
    if (shard) o.range = {shard->first, shard->end};
    c.shard = shard;
    return check_json(check_files({&a}, {kBuiltin}, o), c);
  }
  std::vector<MergePart> shards(std::size_t n) {
    const std::size_t total = count_cases({kBuiltin});
    std::vector<MergePart> parts;
    for (std::size_t k = 0; k < n; ++k) {
      const CaseRange r = shard_range(k, n, total);
      parts.push_back({"part" + std::to_string(k) + ".json", run(ShardInfo{k, n, r.first, r.end, total})});
    }
    return parts;
  }
};

std::string dumped(const nlohmann::json& doc) {
  std::ostringstream out;
  dump_check_json(out, doc);
  return out.str();
}

TEST(Merge, ShardsJoinIntoTheOneRunByteForByte) {
  Campaign campaign;
  const std::string whole = dumped(campaign.run(std::nullopt));
  for (std::size_t n : {2, 3, 7}) {
    auto parts = campaign.shards(n);
    std::swap(parts.front(), parts.back());  // the order given does not matter
    EXPECT_EQ(&kind_of_parts(parts), &merge_kinds()[0]);
    EXPECT_EQ(dumped(merge_check(parts)), whole) << n << " shards";
  }
}

std::string refusal(std::vector<MergePart> parts) {
  try {
    merge_check(parts);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(merged)";
}

TEST(Merge, RefusesAWrongSetOfShardsNamingTheProblem) {
  Campaign campaign;
  const auto parts = campaign.shards(3);
  EXPECT_EQ(refusal({parts[0], parts[2]}), "shard 1/3 is missing (2 of 3 shards given)");
  EXPECT_EQ(refusal({parts[0], parts[1], parts[1], parts[2]}), "shard 1/3 is given twice: part1.json and part1.json");
  auto overlapping = parts;
  overlapping[1].doc["shard"]["first_case"] = overlapping[1].doc["shard"]["first_case"].get<std::size_t>() - 1;
  EXPECT_NE(refusal(overlapping).find("part1.json: shard 1/3 covers cases ["), std::string::npos);
  EXPECT_NE(refusal(overlapping).find("the shards overlap or leave a gap"), std::string::npos);
  auto foreign = parts;
  foreign[2].doc["corpus"]["hash"] = "0123456789abcdef";
  EXPECT_NE(refusal(foreign).find("part2.json: another corpus.hash than part0.json"), std::string::npos);
  auto other_judge = parts;
  other_judge[1].doc["judge"]["kind"] = "oracle";
  EXPECT_NE(refusal(other_judge).find("another judge.kind"), std::string::npos);
  auto whole = parts;
  whole[0].doc.erase("shard");
  EXPECT_NE(refusal(whole).find("part0.json: not a shard"), std::string::npos);
  auto old = parts;
  old[0].doc["schema"] = "tritri-check/2";
  EXPECT_EQ(refusal(old), "part0.json: schema \"tritri-check/2\"; tritri merge reads tritri-check/3");
}

TEST(Judge, ExactFirstScoresAsTheOracleAndSaysWhoDecided) {
  Campaign campaign;
  campaign.context.failure_cap.reset();
  campaign.options.judge.geometry = true;
  campaign.options.judge.sample_one_in = 4;
  auto exact_first = campaign.run(std::nullopt);
  campaign.options.judge.kind = JudgeKind::oracle;
  auto oracle = campaign.run(std::nullopt);
  EXPECT_EQ(exact_first["tallies"], oracle["tallies"]);
  EXPECT_EQ(exact_first["failures"], oracle["failures"]);
  const auto& j = exact_first["judge"];
  EXPECT_EQ(j["kind"], "exact-first");
  EXPECT_GT(j["exact"].get<std::size_t>(), 0u);
  EXPECT_GT(j["cross_checked"].get<std::size_t>(), 0u);  // one in 4 of the cases exact decided
  EXPECT_EQ(j["exact"].get<std::size_t>() + j["oracle"].get<std::size_t>(), exact_first["case_count"].get<std::size_t>());
  EXPECT_EQ(oracle["judge"]["oracle"], oracle["case_count"]);
}

}  // namespace
}  // namespace tritri
