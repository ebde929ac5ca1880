#include "harness/bench/workloads/ratio.hpp"

#include "cases/generator/shapes.hpp"
#include "harness/bench/workload.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace tritri::bench {
namespace {

// The ratio workloads' candidate kinds and their shares.
TrianglePair ratio_candidate(Rng& r, bool disjoint_full) {
  const double u = r.unit();
  if (!disjoint_full) {
    if (u < 0.55) return shapes::scatter_pair(r);
    if (u < 0.95) return shapes::near_pair(r);
    return shapes::coplanar_pair(r);
  }
  // Once enough disjoint pairs are in hand, draw only the kinds that often meet, in the same
  // proportions to each other as before.
  return u < 0.40 / 0.45 ? shapes::near_pair(r) : shapes::coplanar_pair(r);
}

double parse_ratio(const std::string& value) {
  char* end = nullptr;
  const double r = std::strtod(value.c_str(), &end);
  if (value.empty() || *end || !(r >= 0 && r <= 1))
    throw std::invalid_argument("ratio '" + value + "' is not a number in [0, 1]");
  return r;
}

class RatioWorkload : public Workload {
 public:
  RatioWorkload() : Workload("ratio", "ratio[:R]") {}
  std::vector<std::string> default_values() const override { return texts_of(default_ratios(), ratio_text); }
  std::string parse_value(const std::string& value) const override { return ratio_text(parse_ratio(value)); }
  WorkloadPools build(const std::vector<std::string>& values, const WorkloadInput& input) const override {
    std::vector<double> ratios;
    for (const auto& v : values) ratios.push_back(parse_ratio(v));
    std::sort(ratios.begin(), ratios.end());
    return {ratio_pools(ratios, input.pool), {}};
  }
};

}  // namespace

std::unique_ptr<Workload> make_ratio_workload() { return std::make_unique<RatioWorkload>(); }

std::vector<double> default_ratios() {
  std::vector<double> r;
  for (int i = 0; i <= 10; ++i) r.push_back(i / 10.0);
  return r;
}

std::string ratio_text(double r) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", r);
  return buf;
}

std::size_t intersecting_of(double r, std::size_t n) {
  return static_cast<std::size_t>(std::llround(r * static_cast<double>(n)));
}

RatioCandidates ratio_candidates(std::size_t need_yes, std::size_t need_no, std::uint64_t seed,
                                 const std::string& what) {
  Rng rng(sub_seed(seed, "ratio"));
  std::unordered_set<std::uint64_t> seen;
  RatioCandidates c;
  for (int round = 0; c.yes.size() < need_yes || c.no.size() < need_no; ++round) {
    if (round > 200) throw std::runtime_error("ratio pools: the generator yields too few pairs");
    const bool disjoint_full = c.no.size() >= need_no;
    const std::size_t missing = std::max(need_yes - std::min(need_yes, c.yes.size()),
                                         need_no - std::min(need_no, c.no.size()));
    const std::size_t count = std::max<std::size_t>(2048, disjoint_full ? 2 * missing : missing + missing / 4);
    for (auto& x : draw(count, rng, [&](Rng& r) { return ratio_candidate(r, disjoint_full); }, seen, what)) {
      auto& cls = x.truth.overlap ? c.yes : c.no;
      if (cls.size() < (x.truth.overlap ? need_yes : need_no)) cls.push_back(x);
    }
  }
  return c;
}

Pool ratio_pool(const RatioCandidates& candidates, double r, std::size_t n, std::string workload, std::string value,
                std::uint64_t seed) {
  const std::size_t k = intersecting_of(r, n);
  if (candidates.yes.size() < k || candidates.no.size() < n - k)
    throw std::logic_error("ratio_pool: too few candidates for " + workload + ":" + value);
  std::vector<Candidate> chosen(candidates.yes.begin(), candidates.yes.begin() + static_cast<std::ptrdiff_t>(k));
  chosen.insert(chosen.end(), candidates.no.begin(), candidates.no.begin() + static_cast<std::ptrdiff_t>(n - k));
  return make_pool(std::move(workload), std::move(value), seed, std::move(chosen));
}

std::vector<Pool> ratio_pools(const std::vector<double>& ratios, const PoolOptions& options) {
  const std::size_t n = options.size;
  std::size_t need_yes = 0, need_no = 0;
  for (double r : ratios) {
    if (!(r >= 0.0 && r <= 1.0)) throw std::invalid_argument("ratio " + std::to_string(r) + " is not in [0, 1]");
    need_yes = std::max(need_yes, intersecting_of(r, n));
    need_no = std::max(need_no, n - intersecting_of(r, n));
  }
  // One candidate set for every ratio: the classes' mixtures are the same in every pool.
  const RatioCandidates candidates = ratio_candidates(need_yes, need_no, options.seed, "ratio pools");
  std::vector<Pool> pools;
  for (double r : ratios) {
    const std::string value = ratio_text(r);
    pools.push_back(ratio_pool(candidates, r, n, "ratio", value, sub_seed(options.seed, "ratio:" + value)));
  }
  return pools;
}

}  // namespace tritri::bench
