#include "harness/bench/report.hpp"

#include "cases/util/stats.hpp"

#include <algorithm>
#include <cmath>

namespace tritri::bench {
namespace {

// Per algorithm/level: how many wrong and unsupported answers were timed, and where the most.
void warn_wrong_answers(const EntryList& timed, std::vector<std::string>& warnings) {
  struct Bad {
    std::size_t pools = 0, wrong = 0, unsupported = 0;
    std::string worst;
    double worst_share = -1;
  };
  std::vector<std::pair<std::string, Bad>> bad;
  for (const auto& e : timed) {
    if (e->floor || e->stage || (!e->score.wrong && !e->score.unsupported)) continue;
    auto it = std::find_if(bad.begin(), bad.end(), [&](const auto& b) { return b.first == e->row(); });
    if (it == bad.end()) it = bad.insert(bad.end(), {e->row(), {}});
    Bad& b = it->second;
    ++b.pools;
    b.wrong += e->score.wrong;
    b.unsupported += e->score.unsupported;
    const double share = static_cast<double>(e->score.wrong + e->score.unsupported) / static_cast<double>(e->pool->size());
    if (share > b.worst_share) b.worst_share = share, b.worst = e->pool->name();
  }
  for (const auto& [row, b] : bad)
    warnings.push_back("wrong answers timed: " + row + ": " + std::to_string(b.wrong) + " wrong, " +
                       std::to_string(b.unsupported) + " unsupported, on " + std::to_string(b.pools) +
                       " pools; worst " + b.worst + " (" + fixed(100 * b.worst_share, 2) + "% of its pairs)");
}

FloorShare floor_share(const Algorithm* f, const EntryList& timed, const std::vector<PlannedPool>& pools,
                       std::size_t pool_size) {
  FloorShare fs;
  fs.name = f->name;
  for (const auto& planned : pools) {
    const Pool& p = planned.pool;
    double floor_t = NAN, fastest = INFINITY;
    std::string fastest_name;
    for (const auto& e : timed) {
      if (e->pool != &p || e->ns_per_pair.empty() || e->stage) continue;
      const double t = median(e->ns_per_pair);
      if (e->algorithm == f) floor_t = t;
      else if (!e->floor && t < fastest) fastest = t, fastest_name = e->row();
    }
    if (!std::isfinite(floor_t) || !std::isfinite(fastest)) continue;
    const std::string where = p.name() + " (" + f->name + " " + fixed(floor_t, 2) + " ns, fastest " + fastest_name +
                              " " + fixed(fastest, 2) + " ns)";
    if (!(floor_t / fastest <= fs.share)) fs.share = floor_t / fastest, fs.where = where;
    if (p.size() >= pool_size && !(floor_t / fastest <= fs.share_full))
      fs.share_full = floor_t / fastest, fs.where_full = where;
  }
  return fs;
}

void measure_spreads(const EntryList& timed, Summary& s) {
  for (const auto& e : timed) {
    const double x = spread(e->ns_per_pair);
    if (!std::isfinite(x)) continue;
    s.spreads.push_back(x);
    if (!(x <= s.worst_spread)) s.worst_spread = x, s.spread_where = e->name();
  }
  std::size_t unstable = 0;
  for (double x : s.spreads) unstable += x > 0.05;
  if (unstable)
    s.warnings.push_back("unstable: " + std::to_string(unstable) + " of " + std::to_string(s.spreads.size()) +
                         " benchmarks spread more than 5% over their repetitions (worst " + s.spread_where + ", " +
                         fixed(100 * s.worst_spread, 1) +
                         "%): quiet the machine, raise --min-time or --repetitions; the medians are more robust");
}

void warn_small_pools(const std::vector<PlannedPool>& pools, std::size_t pool_size, std::vector<std::string>& warnings) {
  std::size_t small = 0;
  std::string example;
  for (const auto& planned : pools)
    if (planned.pool.size() < pool_size)
      ++small, example = planned.pool.name() + " has " + std::to_string(planned.pool.size()) + " pairs";
  if (small)
    warnings.push_back("small pools: " + std::to_string(small) + " pools are smaller than " + std::to_string(pool_size) +
                       " pairs (e.g. " + example + "): the branch predictor may learn them; compare their times with care");
}

}  // namespace

double Summary::relative(const Entry& e) const {
  const auto r = reference_ns.find(e.pool);
  if (e.ns_per_pair.empty() || r == reference_ns.end() || !std::isfinite(r->second)) return NAN;
  return median(e.ns_per_pair) / r->second;
}

Summary summarize(const EntryList& timed, const std::vector<PlannedPool>& pools, const Lineup& lineup,
                  std::size_t pool_size) {
  Summary s;
  s.reference = lineup.reference->name;
  s.reference_row = lineup.reference_row();
  for (const auto& e : timed)
    if (e->row() == s.reference_row && !e->ns_per_pair.empty()) s.reference_ns[e->pool] = median(e->ns_per_pair);
  warn_wrong_answers(timed, s.warnings);
  for (const Algorithm* f : lineup.floors) s.floor_shares.push_back(floor_share(f, timed, pools, pool_size));
  measure_spreads(timed, s);
  warn_small_pools(pools, pool_size, s.warnings);
  std::size_t without = 0;
  for (const auto& planned : pools) without += planned.levels && !s.reference_ns.count(&planned.pool);
  if (without && !timed.empty())
    s.warnings.push_back("no reference: " + s.reference_row + " was not timed on " + std::to_string(without) +
                         " pools (--level, --filter or a fault): no relative times there");
  return s;
}

}  // namespace tritri::bench
