#include "harness/bench/report.hpp"

#include "cases/util/stats.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace tritri::bench {
namespace {

// Per algorithm/level: how many wrong and unsupported answers were timed, and where the most
// (each pool once: its modes share one check).
void warn_wrong_answers(const EntryList& timed, Mode first_mode, std::vector<std::string>& warnings) {
  struct Bad {
    std::size_t pools = 0, wrong = 0, unsupported = 0;
    std::string worst;
    double worst_share = -1;
  };
  std::vector<std::pair<std::string, Bad>> bad;
  for (const auto& e : timed) {
    if (e->floor || e->stage || e->mode != first_mode || (!e->score.wrong && !e->score.unsupported)) continue;
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

// The share of each floor in each non-floor level entry's time, in the entry's mode, per pool.
void measure_floor_shares(const EntryList& timed, const Lineup& lineup, std::size_t pool_size, Summary& s) {
  std::map<std::tuple<const Pool*, const Algorithm*, Mode>, double> floor_ns;
  for (const auto& e : timed)
    if (e->floor && !e->ns_per_pair.empty()) floor_ns[{e->pool, e->algorithm, *e->mode}] = median(e->ns_per_pair);
  for (const Algorithm* f : lineup.floors) {
    for (const auto& e : timed) {
      if (e->floor || e->stage || e->ns_per_pair.empty()) continue;
      const auto it = floor_ns.find({e->pool, f, *e->mode});
      if (it == floor_ns.end()) continue;
      auto fs = std::find_if(s.floor_shares.begin(), s.floor_shares.end(), [&](const FloorShare& x) {
        return x.floor == f->name && x.row == e->row() && x.mode == *e->mode;
      });
      if (fs == s.floor_shares.end())
        fs = s.floor_shares.insert(s.floor_shares.end(),
                                   {f->name, e->row(), *e->mode, is_published(*e->algorithm, lineup)});
      const double t = median(e->ns_per_pair), share = it->second / t;
      const std::string where = e->pool->name() + " (" + f->name + " " + fixed(it->second, 2) + " ns, " + e->row() +
                                " " + fixed(t, 2) + " ns, " + std::string(to_string(*e->mode)) + ")";
      if (!(share <= fs->share)) fs->share = share, fs->where = where;
      if (e->pool->size() >= pool_size && !(share <= fs->share_full)) fs->share_full = share, fs->where_full = where;
    }
  }
}

// One warning per floor and mode, naming the published tests it exceeds the limit of.
void warn_floor_shares(const Summary& s, std::vector<std::string>& warnings) {
  std::map<std::pair<std::string, Mode>, std::vector<const FloorShare*>> over;
  for (const FloorShare& fs : s.floor_shares)
    if (fs.published && fs.share_full > kFloorShareLimit) over[{fs.floor, fs.mode}].push_back(&fs);
  for (auto& [key, list] : over) {
    std::sort(list.begin(), list.end(), [](auto* x, auto* y) { return x->share_full > y->share_full; });
    std::string rows;
    for (std::size_t i = 0; i < list.size() && i < 3; ++i)
      rows += (i ? ", " : "") + list[i]->row + " " + fixed(100 * list[i]->share_full, 1) + "%";
    warnings.push_back("floor '" + key.first + "' above " + fixed(100 * kFloorShareLimit, 0) + "% of " +
                       std::to_string(list.size()) + " published test(s)' time in " + std::string(to_string(key.second)) +
                       " mode (" + rows + (list.size() > 3 ? ", ..." : "") + "; worst on " + list.front()->where_full +
                       "): the loop's own cost is part of their time");
  }
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

bool is_published(const Algorithm& a, const Lineup& lineup) {
  return !lineup.is_floor(&a) && a.citation.rfind("this project", 0) != 0;
}

double Summary::relative(const Entry& e) const {
  if (!e.mode) return NAN;
  const auto r = reference_ns.find({e.pool, *e.mode});
  if (e.ns_per_pair.empty() || r == reference_ns.end() || !std::isfinite(r->second)) return NAN;
  return median(e.ns_per_pair) / r->second;
}

Summary summarize(const EntryList& timed, const std::vector<PlannedPool>& pools, const Lineup& lineup,
                  std::size_t pool_size, const std::vector<Mode>& modes) {
  Summary s;
  s.reference = lineup.reference->name;
  s.reference_row = lineup.reference_row();
  for (const Algorithm* f : lineup.floors) s.floors.push_back(f->name);
  s.modes = modes;
  for (const auto& e : timed)
    if (e->row() == s.reference_row && !e->ns_per_pair.empty()) s.reference_ns[{e->pool, *e->mode}] = median(e->ns_per_pair);
  warn_wrong_answers(timed, modes.front(), s.warnings);
  measure_floor_shares(timed, lineup, pool_size, s);
  warn_floor_shares(s, s.warnings);
  measure_spreads(timed, s);
  warn_small_pools(pools, pool_size, s.warnings);
  std::size_t without = 0;
  for (const auto& planned : pools)
    for (Mode m : modes) without += planned.levels && !s.reference_ns.count({&planned.pool, m});
  if (without && !timed.empty())
    s.warnings.push_back("no reference: " + s.reference_row + " was not timed on " + std::to_string(without) +
                         " pool x mode(s) (--level, --filter or a fault): no relative times there");
  return s;
}

}  // namespace tritri::bench
