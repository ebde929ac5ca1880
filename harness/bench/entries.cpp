#include "harness/bench/entry.hpp"

#include "cases/util/progress.hpp"
#include "harness/check/judge.hpp"
#include "cases/util/input_error.hpp"
#include "harness/run/process_plugin.hpp"
#include "harness/run/runner.hpp"

#include <algorithm>
#include <ostream>
#include <stdexcept>

namespace tritri::bench {
namespace {

template <class Answer, class Judge>
Score score_with(const Pool& pool, const std::vector<Answer>& answers, Judge judge) {
  Score s;
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const Verdict v = judge(answers[i], pool.truth[i]);
    s.wrong += v == Verdict::wrong;
    s.unsupported += v == Verdict::unsupported;
  }
  return s;
}

// The names a pool's pairs go by where a protocol quotes them.
std::vector<std::string> pair_names(const Pool& pool) {
  std::vector<std::string> names(pool.size());
  for (std::size_t i = 0; i < names.size(); ++i) names[i] = "pair-" + std::to_string(i);
  return names;
}

// Scores one level of the algorithm over the pool, run in a child process (isolation.hpp) so
// that a crash or a hang costs that entry, not the run.
Score score_entry(const Algorithm& a, Level level, const Pool& pool, const IsolationOptions& isolation,
                  std::vector<Fault>& faults) {
  RunAnswers got = run_algorithm(a, pair_names(pool), pool.pairs, {level}, isolation);
  faults = std::move(got.faults);
  if (level == Level::overlap) return score_overlap(pool, got.overlap);
  if (level == Level::relation) return score_relation(pool, got.relation);
  return score_segment(pool, got.segment);
}

std::unique_ptr<Entry> new_entry(const Algorithm* a, std::optional<Level> level, const Pool& pool) {
  auto e = std::make_unique<Entry>();
  e->algo = a->name;
  e->level = level;
  e->algorithm = a;
  e->pool = &pool;
  return e;
}

// A checked entry, timed once per mode: the check does not depend on how the pairs are handed
// over. The path counters are counted through the batch entry, so only batch mode keeps them.
void add_timed(const Entry& checked, const std::vector<Mode>& modes, Entries& entries) {
  for (Mode mode : modes) {
    auto e = std::make_unique<Entry>(checked);
    e->mode = mode;
    if (mode != Mode::batch) e->counters.clear();
    entries.timed.push_back(std::move(e));
  }
}

// An entry per level a process plug-in answers, scored on its answers.
template <class Each>
void process_entries(const Algorithm* a, const Pool& pool, const std::vector<Level>& levels,
                     const std::vector<Overlap>& overlap, const std::vector<RelationAnswer>& relation, Each each) {
  for (Level level : levels) {
    if (level == Level::segment || !a->answers(level)) continue;
    auto e = new_entry(a, level, pool);
    e->score = level == Level::overlap ? score_overlap(pool, overlap) : score_relation(pool, relation);
    each(std::move(e));
  }
}

// A process plug-in (its answers cross a pipe: its time there would be the pipe's) that times
// itself is handed the pool once and times its own loop over it in its own runtime (one time per
// level it answers: it answers them in one call); its answers there are checked like any others.
// One that does not, or fails to, is checked on every pool like the others and reported, not timed.
void process_plugin_entries(const Algorithm* a, const Pool& pool, const std::vector<Level>& levels,
                            const Options& options, Entries& entries) {
  const ProcessPluginOptions& process = *find_process_plugin(a->name);
  std::string why = "a process plug-in that does not time itself (harness/run/process_plugin.hpp, '#time'): "
                    "its answers cross a pipe, so it is checked, not timed";
  if (process_features(a->name).timing) {
    try {
      const SelfTimed t = time_process_plugin(process, pair_names(pool), pool.pairs, options.repetitions, options.min_time);
      process_entries(a, pool, levels, t.answers.overlap, t.answers.relation, [&](std::unique_ptr<Entry> e) {
        e->mode = Mode::call;
        e->ns_per_pair = t.ns_per_pair;
        e->timed_by_plugin = true;
        entries.self_timed.push_back(std::move(e));
      });
      return;
    } catch (const InputError& e) {
      why = std::string("its own timing failed: ") + e.what();
    }
  }
  const RunAnswers got =
      run_algorithm(*a, pair_names(pool), pool.pairs, {Level::overlap, Level::relation}, options.isolation);
  process_entries(a, pool, levels, got.overlap, got.relation, [&](std::unique_ptr<Entry> e) {
    e->faults = got.faults;
    e->not_timed = why;
    entries.untimed.push_back(std::move(e));
  });
}

// One untimed pass of the level over the pool on this thread, between a reset and a read of
// the algorithm's path counters (after its check: the pass cannot crash the run).
template <class Answer, class Batch>
CounterList run_counters(const PathCounters& counters, Batch batch, const Pool& pool) {
  std::vector<Answer> out(pool.size());
  counters.reset();
  batch(pool.pairs.data(), pool.size(), out.data());
  return counters.read();
}

CounterList path_counters(const Algorithm& a, Level level, const Pool& pool) {
  CounterList list;
  for_each_level([&](auto l) {
    constexpr Level L = decltype(l)::value;
    if (L == level) list = run_counters<AnswerOf<L>>(a.counters, a.batch<L>(), pool);
  });
  return list;
}

// The levels `a` is timed at on `pool`: each asked for that it answers, or, where the pool's
// query asks one level, the lowest of those that answers the query (a relation or a segment
// answers whether the triangles meet).
std::vector<Level> timed_levels(const Algorithm& a, const Pool& pool, const std::vector<Level>& levels) {
  std::vector<Level> out;
  for (Level level : levels)
    if (a.answers(level) && (!pool.query || level >= *pool.query)) out.push_back(level);
  if (pool.query && out.size() > 1) out.assign(1, *std::min_element(out.begin(), out.end()));
  return out;
}

void level_entries(const Algorithm* a, const Pool& pool, const Lineup& lineup, const std::vector<Level>& levels,
                   const Options& options, CheckCache& checks, Entries& entries) {
  for (Level level : timed_levels(*a, pool, levels)) {
    auto e = new_entry(a, level, pool);
    e->floor = lineup.is_floor(a);
    if (const CachedCheck* done = checks.find(e->name())) {
      e->score = done->score;
      e->ops = done->ops;
      if (a->counters) e->counters = path_counters(*a, level, pool);
      add_timed(*e, options.modes, entries);
      continue;
    }
    e->score = score_entry(*a, level, pool, options.isolation, e->faults);
    if (!e->faults.empty()) {
      entries.untimed.push_back(std::move(e));
      continue;
    }
    if (options.count_operations) e->ops = count_operations(*a, level, pool);
    if (a->counters) e->counters = path_counters(*a, level, pool);
    checks.put(e->name(), {e->score, e->ops});
    add_timed(*e, options.modes, entries);
  }
}

void stage_entries(const Algorithm* a, const Pool& pool, Entries& entries) {
  for (const StageEntry& s : a->stages) {
    if (!s.run) throw std::logic_error(a->name + ": stage '" + s.name + "' has no run function");
    auto e = new_entry(a, std::nullopt, pool);
    e->stage = &s;
    e->mode = Mode::batch;  // a stage is a batch function (algorithm.hpp, StageEntry)
    if (s.prepare) {
      e->prepared.resize(pool.size());
      s.prepare(pool.pairs.data(), pool.size(), e->prepared.data());
    }
    entries.timed.push_back(std::move(e));
  }
}

// Runs one counting batch over the pool from zeroed counts; false when the level has none.
template <class Answer, class Batch>
bool run_counted(Batch batch, const Pool& pool, OpCounts& counts) {
  if (!batch) return false;
  std::vector<Answer> out(pool.size());
  counts = {};
  batch(pool.pairs.data(), pool.size(), out.data());
  return true;
}

}  // namespace

Score score_overlap(const Pool& pool, const std::vector<Overlap>& answers) {
  return score_with(pool, answers, [](Overlap a, const Truth& t) { return judge_overlap(a, t); });
}

Score score_relation(const Pool& pool, const std::vector<RelationAnswer>& answers) {
  return score_with(pool, answers, [](const RelationAnswer& a, const Truth& t) { return judge_relation(a, t).verdict; });
}

Score score_segment(const Pool& pool, const std::vector<SegmentAnswer>& answers) {
  return score_with(pool, answers,
                    [](const SegmentAnswer& a, const Truth& t) { return judge_overlap(implied_overlap(a), t); });
}

std::optional<OpCounts> count_operations(const Algorithm& a, Level level, const Pool& pool) {
  OpCounts& counts = op_counts();
  const OpCounts before = counts;
  bool ran = false;
  for_each_level([&](auto l) {
    constexpr Level L = decltype(l)::value;
    if (L == level) ran = run_counted<AnswerOf<L>>(a.batch<L>(Scalar::counted), pool, counts);
  });
  if (!ran) return std::nullopt;
  const OpCounts total = counts;
  counts = before;
  return total;
}

bool Lineup::is_floor(const Algorithm* a) const { return std::find(floors.begin(), floors.end(), a) != floors.end(); }

std::string Lineup::reference_row() const { return reference->name + "/" + std::string(to_string(reference_level)); }

Entries make_entries(const std::vector<PlannedPool>& pools, const Lineup& lineup, const std::vector<Level>& levels,
                     const Options& options, CheckCache& checks) {
  Entries entries;
  // Each algorithm runs over each pool in a child process first: minutes on the default pools.
  // Always shown (quiet_below 0): the step is long even though it counts few items.
  Progress progress("checking every algorithm on every pool (algorithm x pool)",
                    pools.size() * lineup.algorithms.size(), 0);
  std::size_t done = 0;
  for (const PlannedPool& planned : pools) {
    for (const Algorithm* a : lineup.algorithms) {
      progress.update(done++);
      if (!a->timeable()) {
        if (planned.levels) process_plugin_entries(a, planned.pool, levels, options, entries);
        continue;
      }
      if (planned.levels) level_entries(a, planned.pool, lineup, levels, options, checks, entries);
      if (planned.stages) stage_entries(a, planned.pool, entries);
    }
  }
  return entries;
}

void report_untimed(const EntryList& untimed, std::ostream& out) {
  for (const auto& e : untimed) {
    if (!e->not_timed.empty()) {
      out << "not timed: " << e->name() << ": " << e->not_timed << "; " << e->score.wrong << " wrong, "
          << e->score.unsupported << " unsupported of " << e->pool->size() << " pairs";
      if (!e->faults.empty()) out << ", " << e->faults.size() << " crash(es) or timeout(s)";
      out << '\n';
      if (e->faults.empty()) continue;
    }
    std::size_t crashes = 0;
    for (const Fault& f : e->faults) crashes += f.fate == Fate::crash;
    const Fault& first = e->faults.front();
    Case c;
    c.name = e->pool->name() + "#" + std::to_string(first.index);
    c.pair = e->pool->pairs[first.index];
    out << "not timed: " << e->name() << ": " << crashes << " crash(es), " << e->faults.size() - crashes
        << " timeout(s) when checked; first: " << to_string(first.fate) << " (" << first.detail << ") on\n"
        << format_case(c, NumberStyle::g17) << '\n' << format_case(c, NumberStyle::hex) << '\n';
  }
}

}  // namespace tritri::bench
