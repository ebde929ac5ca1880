// The size workload: the ratio:0.50 pool at several sizes, to show what a small pool does to the
// ranking. A pool of a few thousand pairs fits in the cache and is replayed often enough for
// the branch predictor to learn its answers, so a branchy test looks much faster on it than on a
// pool of a million pairs, which it has to decide pair by pair from main memory.
//
//   size:N    N pairs, half of them intersecting, drawn as the ratio pools are (the same
//             candidates: each size's pairs are the first of the next size's, reshuffled).
//             Default set: 4096, 16384, 65536, 262144, 1048576. Not in the default run: labelling
//             the million-pair pool takes a while. --pool does not apply.
#include "harness/bench/workload.hpp"
#include "harness/bench/workloads/ratio.hpp"
#include "cases/util/text.hpp"

#include <algorithm>
#include <stdexcept>

namespace tritri::bench {
namespace {

std::size_t parse_size(const std::string& value) {
  const std::size_t n = positive_count(value, 9);
  if (n == 0) throw std::invalid_argument("size '" + value + "' is not a number of pairs from 1 to 999999999");
  return n;
}

class SizeWorkload : public Workload {
 public:
  SizeWorkload() : Workload("size", "size[:N]") {}
  std::vector<std::string> default_values() const override {
    return {"4096", "16384", "65536", "262144", "1048576"};
  }
  std::string parse_value(const std::string& value) const override { return std::to_string(parse_size(value)); }
  bool in_default_set(const std::vector<const Algorithm*>&) const override { return false; }

  WorkloadPools build(const std::vector<std::string>& values, const WorkloadInput& input) const override {
    std::vector<std::size_t> sizes;
    for (const auto& v : values) sizes.push_back(parse_size(v));
    std::sort(sizes.begin(), sizes.end());
    const double ratio = 0.5;
    std::size_t need_yes = 0, need_no = 0;
    for (std::size_t n : sizes) {
      need_yes = std::max(need_yes, intersecting_of(ratio, n));
      need_no = std::max(need_no, n - intersecting_of(ratio, n));
    }
    const RatioCandidates candidates = ratio_candidates(need_yes, need_no, input.pool.seed, "size pools");
    WorkloadPools built;
    for (std::size_t n : sizes) {
      const std::string value = std::to_string(n);
      built.pools.push_back(ratio_pool(candidates, ratio, n, "size", value, sub_seed(input.pool.seed, "size:" + value)));
    }
    return built;
  }
};

}  // namespace

std::unique_ptr<Workload> make_size_workload() { return std::make_unique<SizeWorkload>(); }

}  // namespace tritri::bench
