#include "harness/bench/workloads/family.hpp"

#include "harness/bench/workload.hpp"
#include "cases/generator/corpus.hpp"

#include <algorithm>
#include <stdexcept>

namespace tritri::bench {
namespace {

class FamilyWorkload : public Workload {
 public:
  FamilyWorkload() : Workload("family", "family[:F]") {}
  // Every family of the cases: known only once they are read or generated.
  std::vector<std::string> default_values() const override { return {"*"}; }
  std::string parse_value(const std::string& value) const override {
    if (value.empty() || value == "*") throw std::invalid_argument("family: wants a family's name, e.g. family:shared-vertex");
    return value;
  }

  WorkloadPools build(const std::vector<std::string>& values, const WorkloadInput& input) const override {
    const bool every = std::find(values.begin(), values.end(), "*") != values.end();
    WorkloadPools built;
    std::vector<Case> cases;
    if (input.corpus.files.empty()) {
      auto options = input.quick ? corpus::quick_options(input.pool.seed) : corpus::default_options(input.pool.seed);
      if (!every) options.families = values;
      cases = corpus::generate_corpus(options);
      built.context.emplace_back("family_source", generator_source(input));
    } else {
      cases = input.read_cases();
      std::string files;
      for (const CorpusFile& f : input.corpus.files) files += (files.empty() ? "" : " ") + f.path;
      built.context.emplace_back("family_source", files);
    }
    for (auto& p : family_pools(cases, input.pool))
      if (every || std::find(values.begin(), values.end(), p.value) != values.end()) built.pools.push_back(std::move(p));
    return built;
  }
};

}  // namespace

std::string generator_source(const WorkloadInput& input) {
  return std::string("tritri corpus") + (input.quick ? " --quick" : "") + " --seed " + std::to_string(input.pool.seed) +
         " (cases/generator)";
}

std::unique_ptr<Workload> make_family_workload() { return std::make_unique<FamilyWorkload>(); }

std::vector<Pool> family_pools(const std::vector<Case>& cases, const PoolOptions& options) {
  std::vector<std::string> order;
  std::vector<std::vector<TrianglePair>> members;
  std::vector<std::unordered_set<std::uint64_t>> seen;
  for (const auto& c : cases) {
    const std::string f = c.family();
    auto it = std::find(order.begin(), order.end(), f);
    if (it == order.end()) {
      order.push_back(f);
      members.emplace_back();
      seen.emplace_back();
      it = order.end() - 1;
    }
    const auto k = static_cast<std::size_t>(it - order.begin());
    if (seen[k].insert(pair_hash(c.pair)).second) members[k].push_back(c.pair);
  }
  std::vector<Pool> pools;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const auto truth = label_pairs(members[k]);
    std::vector<Candidate> kept;
    for (std::size_t i = 0; i < truth.size(); ++i)
      if (truth[i].relation != Relation::degenerate) kept.push_back({members[k][i], truth[i]});
    // A family larger than the pool size is sampled down to it, with the seed.
    const std::uint64_t seed = sub_seed(options.seed, "family:" + order[k]);
    Pool p = make_pool("family", order[k], seed, std::move(kept));
    if (p.size() > options.size) {
      p.pairs.resize(options.size);
      p.truth.resize(options.size);
    }
    if (!p.pairs.empty()) pools.push_back(std::move(p));
  }
  return pools;
}

}  // namespace tritri::bench
