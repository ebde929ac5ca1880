#include "harness/bench/bench.hpp"

#include "cases/util/stats.hpp"

#include "harness/run/process_plugin.hpp"

#include "cases/generator/corpus.hpp"
#include "cases/util/atomic_file.hpp"

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <unistd.h>

#if __has_include(<fcl/config.h>)
#include <fcl/config.h>
#endif

#ifndef TRITRI_BUILD_FLAGS
#define TRITRI_BUILD_FLAGS "unknown"
#endif
#ifndef TRITRI_BUILD_TYPE
#define TRITRI_BUILD_TYPE "unknown"
#endif
#ifndef TRITRI_SOURCE_DIR
#define TRITRI_SOURCE_DIR "."
#endif

namespace tritri::bench {
namespace {

constexpr const char* kReference = "moller97";  // every time is also given relative to it

// ---- the floor: used when no `null` algorithm is registered ----

// Reads every coordinate and returns one bit of them: the cost of the loop, the memory traffic
// and the answer fold, with no test in it.
bool floor_kernel(const TrianglePair& p) {
  std::uint64_t h = 0;
  for (const Triangle* t : {&p.t1, &p.t2})
    for (const auto& v : t->v) h ^= std::bit_cast<std::uint64_t>(v[0]) ^ std::bit_cast<std::uint64_t>(v[1]) ^
                                    std::bit_cast<std::uint64_t>(v[2]);
  return (h >> 52) & 1u;
}

const Algorithm& internal_floor() {
  static const Algorithm a = [] {
    Algorithm f;
    f.name = "floor";
    f.summary = "the harness floor: reads every coordinate (integer XOR, no dependency chain), returns a bit";
    f.accepts_degenerate = true;
    f.set_batch<Level::overlap>(Scalar::double_, overlap_batch<&floor_kernel>);
    return f;
  }();
  return a;
}

// ---- the timed loops ----

template <class Answer, class Batch>
void time_level(benchmark::State& state, Batch batch, const TrianglePair* pairs, std::size_t n) {
  std::array<Answer, kBatch> out{};
  std::uint64_t checksum = 0;
  for (auto _ : state) {
    for (std::size_t at = 0; at < n; at += kBatch) {
      const std::size_t m = std::min(kBatch, n - at);
      batch(pairs + at, m, out.data());
      std::uint64_t sum = 0;
      for (std::size_t i = 0; i < m; ++i) sum += fold_answer(out[i]);
      checksum += sum;
      benchmark::DoNotOptimize(checksum);
    }
  }
}

void time_stage(benchmark::State& state, StageRunBatch run, const TrianglePair* pairs, std::size_t n) {
  std::uint64_t checksum = 0;
  for (auto _ : state) {
    for (std::size_t at = 0; at < n; at += kBatch) {
      checksum += run(pairs + at, std::min(kBatch, n - at));
      benchmark::DoNotOptimize(checksum);
    }
  }
}

// ---- what gets registered ----

struct Entry {
  std::string algo;
  std::string level;  // "overlap", "relation", "segment", "stage:NAME"
  const Algorithm* algorithm = nullptr;
  std::optional<Level> answer_level;  // unset for stages
  const StageEntry* stage = nullptr;
  const Pool* pool = nullptr;
  std::vector<TrianglePair> prepared;  // a stage's input when it has a prepare step
  bool floor = false;
  Score score;
  std::vector<Fault> faults;    // pairs it crashed or hung on when checked: then it is not timed
  std::string not_timed;        // why it is checked but not timed, when it is not for a fault
  std::optional<OpCounts> ops;  // totals over the pool
  std::vector<double> ns_per_pair;  // one per repetition (CPU time)

  std::string row() const { return algo + "/" + level; }
  std::string name() const { return row() + "/" + pool->name(); }
  const TrianglePair* input() const { return prepared.empty() ? pool->pairs.data() : prepared.data(); }
};

double spread_statistic(const std::vector<double>& v) {
  const double s = spread(v);
  return std::isfinite(s) ? s : 0.0;
}

std::string shell_output(const std::string& command) {
  std::string out;
  if (FILE* p = popen(command.c_str(), "r")) {
    char buf[256];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

// Scores one algorithm at one level on a pool, through its own batch entry point.
// Runs one level of the algorithm over the pool in a child process (isolation.hpp), so that a
// crash or a hang costs that entry, not the run.
template <class Answer, class Batch>
std::vector<Answer> answers_isolated(Batch batch, const Pool& pool, const IsolationOptions& isolation,
                                     std::vector<Fault>& faults) {
  const std::size_t n = pool.size();
  SharedArray<Answer> shared(n);
  faults = run_isolated(n, [&](std::size_t b, std::size_t e) { batch(pool.pairs.data() + b, e - b, shared.data() + b); },
                        isolation);
  return std::vector<Answer>(shared.data(), shared.data() + n);
}

Score score_entry(const Algorithm& a, Level level, const Pool& pool, const IsolationOptions& isolation,
                  std::vector<Fault>& faults) {
  switch (level) {
    case Level::overlap:
      return score_overlap(pool, answers_isolated<Overlap>(a.batch<Level::overlap>(), pool, isolation, faults));
    case Level::relation:
      return score_relation(pool, answers_isolated<RelationAnswer>(a.batch<Level::relation>(), pool, isolation, faults));
    case Level::segment:
      return score_segment(pool, answers_isolated<SegmentAnswer>(a.batch<Level::segment>(), pool, isolation, faults));
  }
  return {};
}

// ---- reporting: the console gets the medians, the JSON everything, the tables our numbers ----

class Reporter : public benchmark::BenchmarkReporter {
 public:
  Reporter(std::map<std::string, Entry*> entries, bool color, int repetitions)
      : console_(color ? benchmark::ConsoleReporter::OO_Color : benchmark::ConsoleReporter::OO_None),
        entries_(std::move(entries)),
        repetitions_(repetitions) {
    console_.SetOutputStream(&std::cout);
    console_.SetErrorStream(&std::cerr);
    json_.SetOutputStream(&json_text_);
    json_.SetErrorStream(&std::cerr);
  }

  bool ReportContext(const Context& context) override {
    console_.ReportContext(context);
    return json_.ReportContext(context);
  }

  void ReportRuns(const std::vector<Run>& runs) override {
    json_.ReportRuns(runs);
    std::vector<Run> shown;
    for (const Run& run : runs) {
      if (run.error_occurred) {
        ++errors_;
        shown.push_back(run);
        continue;
      }
      auto it = entries_.find(run.run_name.function_name);
      if (run.run_type == Run::RT_Iteration && it != entries_.end() && run.iterations > 0)
        it->second->ns_per_pair.push_back(run.cpu_accumulated_time * 1e9 /
                                          (static_cast<double>(run.iterations) *
                                           static_cast<double>(it->second->pool->size())));
      const bool median_row = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
      if (median_row || repetitions_ <= 1) {
        Run r = run;
        for (const char* op : {"add", "mul", "div", "cmp", "sqrt"}) r.counters.erase(op);
        shown.push_back(std::move(r));
      }
    }
    if (!shown.empty()) console_.ReportRuns(shown);
  }

  void Finalize() override {
    console_.Finalize();
    json_.Finalize();
  }

  std::string json() const { return json_text_.str(); }
  int errors() const { return errors_; }

 private:
  benchmark::ConsoleReporter console_;
  benchmark::JSONReporter json_;
  std::ostringstream json_text_;
  std::map<std::string, Entry*> entries_;
  int repetitions_;
  int errors_ = 0;
};

std::string fixed(double x, int decimals) {
  if (!std::isfinite(x)) return "-";
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << x;
  return s.str();
}

std::string pad(const std::string& s, std::size_t width, bool left = false) {
  if (s.size() >= width) return s;
  return left ? s + std::string(width - s.size(), ' ') : std::string(width - s.size(), ' ') + s;
}

struct Table {
  std::vector<const Pool*> pools;    // the columns
  std::vector<std::string> rows;     // algo/level, in registration order
};

std::vector<std::pair<std::string, Table>> tables_of(const std::vector<std::unique_ptr<Entry>>& entries) {
  std::vector<std::pair<std::string, Table>> tables;
  for (const auto& e : entries) {
    const std::string group = e->stage ? "stage" : e->pool->workload;
    auto it = std::find_if(tables.begin(), tables.end(), [&](const auto& t) { return t.first == group; });
    if (it == tables.end()) it = tables.insert(tables.end(), {group, {}});
    Table& t = it->second;
    if (std::find(t.pools.begin(), t.pools.end(), e->pool) == t.pools.end()) t.pools.push_back(e->pool);
    if (std::find(t.rows.begin(), t.rows.end(), e->row()) == t.rows.end()) t.rows.push_back(e->row());
  }
  return tables;
}

std::string column_title(const Pool* p, const std::string& group) {
  return group == "ratio" || group == "stage" ? p->value : p->value.substr(0, 11);
}

}  // namespace

Options quick_options() {
  Options o;
  o.pool_size = 4096;
  o.repetitions = 3;
  o.min_time = 0.005;
  o.min_warmup_time = 0;
  o.quick = true;
  return o;
}

Score score_overlap(const Pool& pool, const std::vector<Overlap>& answers) {
  Score s;
  for (std::size_t i = 0; i < answers.size(); ++i) {
    if (answers[i] == Overlap::unsupported) ++s.unsupported;
    else if ((answers[i] == Overlap::yes) != pool.truth[i].overlap) ++s.wrong;
  }
  return s;
}

Score score_relation(const Pool& pool, const std::vector<RelationAnswer>& answers) {
  Score s;
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const RelationAnswer& a = answers[i];
    const Truth& t = pool.truth[i];
    if (a.relation == Relation::unsupported) {
      ++s.unsupported;
    } else if (a.relation == Relation::unknown) {  // an algorithm that states the dimension only
      if (a.dimension != t.dimension) ++s.wrong;
    } else if (a.relation != t.relation) {
      ++s.wrong;
    }
  }
  return s;
}

Score score_segment(const Pool& pool, const std::vector<SegmentAnswer>& answers) {
  Score s;
  for (std::size_t i = 0; i < answers.size(); ++i) {
    if (answers[i].kind == SegmentKind::unsupported) ++s.unsupported;
    else if ((answers[i].kind != SegmentKind::empty) != pool.truth[i].overlap) ++s.wrong;
  }
  return s;
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

std::optional<OpCounts> count_operations(const Algorithm& a, Level level, const Pool& pool) {
  OpCounts& counts = op_counts();
  const OpCounts before = counts;
  bool ran = false;
  switch (level) {
    case Level::overlap: ran = run_counted<Overlap>(a.batch<Level::overlap>(Scalar::counted), pool, counts); break;
    case Level::relation: ran = run_counted<RelationAnswer>(a.batch<Level::relation>(Scalar::counted), pool, counts); break;
    case Level::segment: ran = run_counted<SegmentAnswer>(a.batch<Level::segment>(Scalar::counted), pool, counts); break;
  }
  if (!ran) return std::nullopt;
  const OpCounts total = counts;
  counts = before;
  return total;
}

std::vector<std::pair<std::string, std::string>> build_context() {
  std::vector<std::pair<std::string, std::string>> c;
  const std::string dir = TRITRI_SOURCE_DIR;
  const std::string sha = shell_output("git -C '" + dir + "' rev-parse HEAD 2>/dev/null");
  c.emplace_back("git_sha", sha.empty() ? "unknown" : sha);
  c.emplace_back("git_dirty", sha.empty() ? "unknown"
                                          : shell_output("git -C '" + dir +
                                                         "' status --porcelain --untracked-files=no 2>/dev/null")
                                                    .empty()
                                                ? "false"
                                                : "true");
#if defined(__clang__)
  c.emplace_back("compiler", std::string("clang ") + __clang_version__);
#elif defined(__GNUC__)
  c.emplace_back("compiler", std::string("gcc ") + __VERSION__);
#else
  c.emplace_back("compiler", "unknown");
#endif
  c.emplace_back("build_type", TRITRI_BUILD_TYPE);
  c.emplace_back("compiler_flags", TRITRI_BUILD_FLAGS);
  c.emplace_back("fp_contract", std::string(TRITRI_BUILD_FLAGS).find("-ffp-contract=off") != std::string::npos
                                    ? "off"
                                    : "compiler default");
  c.emplace_back("cgal_version", oracle_description());
#ifdef FCL_VERSION
  c.emplace_back("fcl_version", FCL_VERSION);
#else
  c.emplace_back("fcl_version", "not found");
#endif
  c.emplace_back("eigen_version", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) +
                                      "." + std::to_string(EIGEN_MINOR_VERSION));
  c.emplace_back("google_benchmark", "1.7.1 (Debian libbenchmark-dev, find_package(benchmark))");
  return c;
}

int run(const Options& options, std::ostream& out) {
  // ---- what to run ----
  std::vector<const Algorithm*> algorithms = options.algorithms;
  if (algorithms.empty())
    for (const auto& a : registry().all()) algorithms.push_back(&a);
  // The floors first: the harness's own (loop, loads, fold) and the `null` plug-in when there is
  // one; then the reference.
  std::vector<const Algorithm*> floors = {&internal_floor()};
  if (const Algorithm* null = registry().find("null")) floors.push_back(null);
  for (const Algorithm* f : floors) {
    auto it = std::find(algorithms.begin(), algorithms.end(), f);
    if (it != algorithms.end()) algorithms.erase(it);
  }
  algorithms.insert(algorithms.begin(), floors.begin(), floors.end());
  if (const Algorithm* ref = registry().find(kReference);
      ref && std::find(algorithms.begin(), algorithms.end(), ref) == algorithms.end())
    algorithms.insert(algorithms.begin() + static_cast<std::ptrdiff_t>(floors.size()), ref);
  auto is_floor = [&](const Algorithm* a) { return std::find(floors.begin(), floors.end(), a) != floors.end(); };

  std::vector<Level> levels = options.levels;
  if (levels.empty()) levels = {Level::overlap, Level::relation, Level::segment};
  const bool any_stages = std::any_of(algorithms.begin(), algorithms.end(), [](const Algorithm* a) { return !a->stages.empty(); });
  std::vector<std::string> workloads = options.workloads;
  if (workloads.empty()) {
    workloads = {"ratio", "type", "family"};
    if (any_stages) workloads.push_back("stage");
  }

  // ---- the pools ----
  const PoolOptions pool_options{options.pool_size, options.seed};
  std::vector<double> ratios;
  std::vector<Dimension> types;
  std::vector<std::string> families;
  bool all_families = false, stage = false;
  for (const auto& w : workloads) {
    const auto colon = w.find(':');
    const std::string kind = w.substr(0, colon);
    const std::string value = colon == std::string::npos ? "" : w.substr(colon + 1);
    if (kind == "ratio") {
      if (value.empty()) {
        for (double r : default_ratios()) ratios.push_back(r);
      } else {
        char* end = nullptr;
        const double r = std::strtod(value.c_str(), &end);
        if (*end || !(r >= 0 && r <= 1)) throw std::invalid_argument("ratio '" + value + "' is not a number in [0, 1]");
        ratios.push_back(r);
      }
    } else if (kind == "type") {
      bool found = value.empty();
      for (Dimension d : kTypes)
        if (value.empty() || type_text(d) == value) types.push_back(d), found = true;
      if (!found) throw std::invalid_argument("type '" + value + "' is not one of disjoint, point, segment, area");
    } else if (kind == "family") {
      if (value.empty()) all_families = true;
      else families.push_back(value);
    } else if (kind == "stage") {
      stage = true;
    } else {
      throw std::invalid_argument("unknown workload '" + w + "' (ratio[:R], type[:T], family[:F], stage)");
    }
  }
  std::sort(ratios.begin(), ratios.end());
  ratios.erase(std::unique(ratios.begin(), ratios.end()), ratios.end());
  const bool stage_pool_extra = stage && std::find(ratios.begin(), ratios.end(), 0.5) == ratios.end();

  out << "tritri bench: building pools of " << options.pool_size << " pairs (seed " << options.seed
      << ") and labelling them with the oracle...\n";
  out.flush();
  std::vector<Pool> pools;
  std::string family_source = options.family_source;
  {
    std::vector<double> to_build = ratios;
    if (stage_pool_extra) to_build.push_back(0.5);
    if (!to_build.empty())
      for (auto& p : ratio_pools(to_build, pool_options)) pools.push_back(std::move(p));
    for (Dimension d : types) pools.push_back(type_pool(d, pool_options));
    if (all_families || !families.empty()) {
      std::vector<Case> generated;
      if (options.family_cases.empty()) {
        auto corpus_options = options.quick ? corpus::quick_options(options.seed) : corpus::default_options(options.seed);
        corpus_options.families = families;
        generated = corpus::generate_corpus(corpus_options);
        family_source = std::string("tritri corpus") + (options.quick ? " --quick" : "") + " --seed " +
                        std::to_string(options.seed) + " (cases/generator)";
      }
      for (auto& p : family_pools(options.family_cases.empty() ? generated : options.family_cases, pool_options))
        if (all_families || std::find(families.begin(), families.end(), p.value) != families.end())
          pools.push_back(std::move(p));
    }
  }
  const Pool* stage_pool = nullptr;
  for (const auto& p : pools)
    if (p.workload == "ratio" && p.value == ratio_text(0.5)) stage_pool = &p;

  // ---- the entries: checked and counted before anything is timed ----
  std::vector<std::unique_ptr<Entry>> entries;
  std::vector<std::unique_ptr<Entry>> faulted;  // checked and reported, not timed
  for (const Pool& pool : pools) {
    const bool extra = stage_pool_extra && &pool == stage_pool;  // built for the stages only
    for (const Algorithm* a : algorithms) {
      if (a->kind == Algorithm::Kind::process) {
        // A process plug-in answers over a pipe: its time would be the pipe's. It is checked on
        // every pool like the others, and reported, not timed.
        if (extra) continue;
        std::vector<std::string> names(pool.size());
        for (std::size_t i = 0; i < names.size(); ++i) names[i] = "pair-" + std::to_string(i);
        const ProcessAnswers got = run_process_plugin({a->process.command, a->process.timeout_seconds}, names, pool.pairs);
        for (Level level : levels) {
          if (level == Level::segment || !a->answers(level)) continue;
          auto e = std::make_unique<Entry>();
          e->algo = a->name;
          e->level = std::string(to_string(level));
          e->algorithm = a;
          e->answer_level = level;
          e->pool = &pool;
          e->score = level == Level::overlap ? score_overlap(pool, got.overlap) : score_relation(pool, got.relation);
          e->faults = got.faults;
          e->not_timed = "a process plug-in: its answers cross a pipe, so it is checked, not timed";
          faulted.push_back(std::move(e));
        }
        continue;
      }
      if (!extra) {
        for (Level level : levels) {
          if (!a->answers(level)) continue;
          auto e = std::make_unique<Entry>();
          e->algo = a->name;
          e->level = std::string(to_string(level));
          e->algorithm = a;
          e->answer_level = level;
          e->pool = &pool;
          e->floor = is_floor(a);
          e->score = score_entry(*a, level, pool, options.isolation, e->faults);
          if (!e->faults.empty()) {
            faulted.push_back(std::move(e));
            continue;
          }
          if (options.count_operations)
            if (auto ops = count_operations(*a, level, pool)) e->ops = ops;
          entries.push_back(std::move(e));
        }
      }
      if (stage && &pool == stage_pool) {
        for (const StageEntry& s : a->stages) {
          if (!s.run) throw std::logic_error(a->name + ": stage '" + s.name + "' has no run function");
          auto e = std::make_unique<Entry>();
          e->algo = a->name;
          e->level = "stage:" + s.name;
          e->algorithm = a;
          e->stage = &s;
          e->pool = &pool;
          if (s.prepare) {
            e->prepared.resize(pool.size());
            s.prepare(pool.pairs.data(), pool.size(), e->prepared.data());
          }
          entries.push_back(std::move(e));
        }
      }
    }
  }

  for (const auto& e : faulted) {
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

  // ---- Google Benchmark ----
  std::vector<std::string> flags = {
      "tritri-bench",
      "--benchmark_repetitions=" + std::to_string(std::max(1, options.repetitions)),
      "--benchmark_enable_random_interleaving=" + std::string(options.interleave ? "true" : "false"),
      "--benchmark_min_time=" + std::to_string(options.min_time),
      "--benchmark_min_warmup_time=" + std::to_string(options.min_warmup_time),
  };
  if (!options.filter.empty()) flags.push_back("--benchmark_filter=" + options.filter);
  if (options.list_only) flags.push_back("--benchmark_list_tests=true");
  std::vector<char*> argv;
  for (auto& f : flags) argv.push_back(f.data());
  int argc = static_cast<int>(argv.size());
  benchmark::Initialize(&argc, argv.data());

  std::map<std::string, Entry*> by_name;
  for (auto& e : entries) {
    Entry* entry = e.get();
    by_name[entry->name()] = entry;
    const std::size_t n = entry->pool->size();
    auto* b = benchmark::RegisterBenchmark(entry->name().c_str(), [entry, n](benchmark::State& state) {
      const TrianglePair* pairs = entry->input();
      if (entry->stage) {
        time_stage(state, entry->stage->run, pairs, n);
      } else {
        switch (*entry->answer_level) {
          case Level::overlap: time_level<Overlap>(state, entry->algorithm->batch<Level::overlap>(), pairs, n); break;
          case Level::relation: time_level<RelationAnswer>(state, entry->algorithm->batch<Level::relation>(), pairs, n); break;
          case Level::segment: time_level<SegmentAnswer>(state, entry->algorithm->batch<Level::segment>(), pairs, n); break;
        }
      }
      const double pairs_done = static_cast<double>(state.iterations()) * static_cast<double>(n);
      state.SetItemsProcessed(static_cast<std::int64_t>(pairs_done));
      using C = benchmark::Counter;
      state.counters["per_pair"] = C(static_cast<double>(n), C::kIsIterationInvariantRate | C::kInvert);
      state.counters["wrong"] = C(static_cast<double>(entry->score.wrong));
      state.counters["unsupported"] = C(static_cast<double>(entry->score.unsupported));
      state.counters["pool"] = C(static_cast<double>(n));
      if (entry->ops) {
        const double per = 1.0 / static_cast<double>(n);
        state.counters["add"] = C(static_cast<double>(entry->ops->add) * per);
        state.counters["mul"] = C(static_cast<double>(entry->ops->mul) * per);
        state.counters["div"] = C(static_cast<double>(entry->ops->div) * per);
        state.counters["cmp"] = C(static_cast<double>(entry->ops->cmp) * per);
        state.counters["sqrt"] = C(static_cast<double>(entry->ops->sqrt) * per);
      }
    });
    b->Unit(benchmark::kMicrosecond);
    if (options.repetitions > 1) b->ComputeStatistics("spread", spread_statistic, benchmark::StatisticUnit::kPercentage);
  }

  std::vector<const Pool*> pool_list;
  for (const auto& p : pools) pool_list.push_back(&p);
  const std::string corpus_hash = hex64(hash_pools(pool_list));
  for (const auto& [k, v] : build_context()) benchmark::AddCustomContext(k, v);
  benchmark::AddCustomContext("corpus_hash", corpus_hash);
  benchmark::AddCustomContext("seed", std::to_string(options.seed));
  benchmark::AddCustomContext("pool_size", std::to_string(options.pool_size));
  benchmark::AddCustomContext("oracle", oracle_description());
  benchmark::AddCustomContext("repetitions", std::to_string(options.repetitions));
  benchmark::AddCustomContext("random_interleaving", options.interleave ? "true" : "false");
  benchmark::AddCustomContext("timing", "CPU time per pair: one iteration is one in-order pass over the pool");
  if (!family_source.empty()) benchmark::AddCustomContext("family_source", family_source);
  for (const auto& p : pools)
    benchmark::AddCustomContext("pool " + p.name(), "size=" + std::to_string(p.size()) + " intersecting=" +
                                                        std::to_string(p.intersecting()) + " " + p.stage_mix_text());

  out << "pools:\n";
  for (const auto& p : pools)
    out << "  " << pad(p.name(), 22, true) << pad(std::to_string(p.size()), 7) << " pairs, "
        << pad(std::to_string(p.intersecting()), 6) << " intersecting; stages: " << p.stage_mix_text() << '\n';
  out << "corpus hash " << corpus_hash << "; " << entries.size() << " benchmarks, " << options.repetitions
      << " repetitions each" << (options.interleave ? ", randomly interleaved" : "") << ".\n\n";
  out.flush();

  Reporter reporter(by_name, isatty(fileno(stdout)) == 1, options.repetitions);
  if (options.list_only) {
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
  }
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();

  // ---- the tables ----
  std::map<const Pool*, double> reference;  // moller97/overlap median per pool
  for (const auto& e : entries)
    if (e->algo == kReference && e->level == "overlap") reference[e->pool] = median(e->ns_per_pair);

  out << "\nns per pair: median of " << options.repetitions
      << " repetitions, CPU time. In brackets: relative to moller97/overlap on the same pool.\n"
         "'!': wrong answers on that pool (see the warnings); floor and null are not tests.\n";
  for (const auto& [group, table] : tables_of(entries)) {
    out << '\n' << group << (group == "stage" ? " (pool ratio:0.50)" : "") << '\n';
    out << pad("algorithm/level", 34, true);
    for (const Pool* p : table.pools) out << pad(column_title(p, group), 14);
    out << '\n';
    for (const auto& row : table.rows) {
      out << pad(row, 34, true);
      for (const Pool* p : table.pools) {
        auto it = std::find_if(entries.begin(), entries.end(), [&](const auto& e) { return e->row() == row && e->pool == p; });
        std::string cell = "";
        if (it != entries.end() && !(*it)->ns_per_pair.empty()) {
          const double t = median((*it)->ns_per_pair);
          cell = fixed(t, t < 100 ? 2 : 1);
          if (auto r = reference.find(p); r != reference.end() && std::isfinite(r->second))
            cell += " (" + fixed(t / r->second, 2) + ")";
          cell += (*it)->score.wrong && !(*it)->floor ? "!" : " ";
        }
        out << pad(cell, 14);
      }
      out << '\n';
    }
  }

  // Operation counts.
  if (std::any_of(entries.begin(), entries.end(), [](const auto& e) { return e->ops.has_value(); })) {
    out << "\noperations per pair (the counting instantiation; 'div' includes nothing else, 'cmp' every comparison)\n";
    for (const auto& [group, table] : tables_of(entries)) {
      if (group == "stage") continue;
      out << '\n' << group << '\n' << pad("algorithm/level  op", 34, true);
      for (const Pool* p : table.pools) out << pad(column_title(p, group), 12);
      out << '\n';
      for (const auto& row : table.rows) {
        for (int op = 0; op < 4; ++op) {
          bool any = false;
          std::string line = pad(row + "  " + std::array{"add", "mul", "div", "cmp"}[op], 34, true);
          for (const Pool* p : table.pools) {
            auto it = std::find_if(entries.begin(), entries.end(), [&](const auto& e) { return e->row() == row && e->pool == p; });
            std::string cell;
            if (it != entries.end() && (*it)->ops) {
              const OpCounts& c = *(*it)->ops;
              const std::uint64_t v = std::array{c.add, c.mul, c.div, c.cmp}[op];
              cell = fixed(static_cast<double>(v) / static_cast<double>(p->size()), 1);
              any = true;
            }
            line += pad(cell, 12);
          }
          if (any) out << line << '\n';
        }
      }
    }
  }

  // Wrong answers, the harness's own numbers and the warnings.
  std::vector<std::string> warnings;
  {
    struct Bad {
      std::size_t pools = 0, wrong = 0, unsupported = 0, pairs = 0;
      std::string worst;
      double worst_share = -1;
    };
    std::vector<std::pair<std::string, Bad>> bad;
    for (const auto& e : entries) {
      if (e->floor || e->stage || (!e->score.wrong && !e->score.unsupported)) continue;
      auto it = std::find_if(bad.begin(), bad.end(), [&](const auto& b) { return b.first == e->row(); });
      if (it == bad.end()) it = bad.insert(bad.end(), {e->row(), {}});
      Bad& b = it->second;
      ++b.pools;
      b.wrong += e->score.wrong;
      b.unsupported += e->score.unsupported;
      b.pairs += e->pool->size();
      const double share = static_cast<double>(e->score.wrong + e->score.unsupported) / static_cast<double>(e->pool->size());
      if (share > b.worst_share) b.worst_share = share, b.worst = e->pool->name();
    }
    for (const auto& [row, b] : bad)
      warnings.push_back("wrong answers timed: " + row + ": " + std::to_string(b.wrong) + " wrong, " +
                         std::to_string(b.unsupported) + " unsupported, on " + std::to_string(b.pools) +
                         " pools; worst " + b.worst + " (" + fixed(100 * b.worst_share, 2) + "% of its pairs)");
  }

  // The floors' share of the fastest real algorithm's time, worst pool first.
  struct FloorShare {
    std::string name;
    double share = NAN;  // over every pool
    std::string where;
    double share_full = NAN;  // over the pools of the full size (small ones are learnt)
    std::string where_full;
  };
  std::vector<FloorShare> floor_shares;
  for (const Algorithm* f : floors) {
    FloorShare fs{f->name};
    for (const auto& p : pools) {
      double floor_t = NAN, fastest = INFINITY;
      std::string fastest_name;
      for (const auto& e : entries) {
        if (e->pool != &p || e->ns_per_pair.empty() || e->stage) continue;
        const double t = median(e->ns_per_pair);
        if (e->algorithm == f) floor_t = t;
        else if (!e->floor && t < fastest) fastest = t, fastest_name = e->row();
      }
      if (!std::isfinite(floor_t) || !std::isfinite(fastest)) continue;
      const std::string where = p.name() + " (" + f->name + " " + fixed(floor_t, 2) + " ns, fastest " + fastest_name +
                                " " + fixed(fastest, 2) + " ns)";
      if (!(floor_t / fastest <= fs.share)) fs.share = floor_t / fastest, fs.where = where;
      if (p.size() >= options.pool_size && !(floor_t / fastest <= fs.share_full))
        fs.share_full = floor_t / fastest, fs.where_full = where;
    }
    floor_shares.push_back(fs);
  }
  double worst_spread = NAN;
  std::string spread_where;
  std::vector<double> spreads;
  for (const auto& e : entries) {
    const double s = spread(e->ns_per_pair);
    if (!std::isfinite(s)) continue;
    spreads.push_back(s);
    if (!(s <= worst_spread)) worst_spread = s, spread_where = e->name();
  }
  {
    std::size_t unstable = 0;
    for (double s : spreads) unstable += s > 0.05;
    if (unstable)
      warnings.push_back("unstable: " + std::to_string(unstable) + " of " + std::to_string(spreads.size()) +
                         " benchmarks spread more than 5% over their repetitions (worst " + spread_where + ", " +
                         fixed(100 * worst_spread, 1) +
                         "%): quiet the machine, raise --min-time or --repetitions; the medians are more robust");
  }
  {
    std::size_t small = 0;
    std::string example;
    for (const auto& p : pools)
      if (p.size() < options.pool_size) ++small, example = p.name() + " has " + std::to_string(p.size()) + " pairs";
    if (small)
      warnings.push_back("small pools: " + std::to_string(small) + " pools are smaller than " +
                         std::to_string(options.pool_size) + " pairs (e.g. " + example +
                         "): the branch predictor may learn them; compare their times with care");
  }
  for (const auto& fs : floor_shares) {
    out << "\nharness: floor '" << fs.name << "' at most " << fixed(100 * fs.share_full, 1)
        << "% of the fastest algorithm's time per pair on the full-size pools (limit 10%), worst on "
        << fs.where_full;
    if (fs.where != fs.where_full)
      out << "\n         on every pool, small ones included: " << fixed(100 * fs.share, 1) << "%, on " << fs.where;
  }
  out << '\n';
  out << "harness: repetition spread (max/min - 1) median " << fixed(100 * median(spreads), 1) << "%, worst "
      << fixed(100 * worst_spread, 1) << "% on " << spread_where << " (limit 5% on a quiet machine)\n";
  if (!warnings.empty()) {
    out << "\nwarnings:\n";
    const std::size_t limit = 40;
    for (std::size_t i = 0; i < warnings.size() && i < limit; ++i) out << "  " << warnings[i] << '\n';
    if (warnings.size() > limit) out << "  ... and " << warnings.size() - limit << " more\n";
  }

  // ---- the JSON: Google Benchmark's, plus a "tritri" section with our summaries ----
  if (!options.json_path.empty()) {
    // Google Benchmark writes NaN for statistics of constant-zero counters (their cv): not JSON.
    std::string text = reporter.json();
    for (const char* bad : {"-NaN", "NaN", "-Infinity", "Infinity", "-inf", "inf", "-nan", "nan"}) {
      const std::string from = std::string(": ") + bad;
      for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) {
        const char next = at + from.size() < text.size() ? text[at + from.size()] : '\n';
        if (next == ',' || next == '\n' || next == ' ' || next == '}') text.replace(at, from.size(), ": null");
        else at += from.size();
      }
    }
    nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
    if (!doc.is_discarded()) {
      nlohmann::json summary = nlohmann::json::array();
      for (const auto& e : entries) {
        nlohmann::json s = {{"name", e->name()},
                            {"algorithm", e->algo},
                            {"level", e->level},
                            {"workload", e->pool->name()},
                            {"pool_size", e->pool->size()},
                            {"wrong", e->score.wrong},
                            {"unsupported", e->score.unsupported},
                            {"ns_per_pair", e->ns_per_pair}};
        if (!e->ns_per_pair.empty()) {
          s["ns_per_pair_median"] = median(e->ns_per_pair);
          if (auto r = reference.find(e->pool); r != reference.end() && std::isfinite(r->second))
            s["relative_to_moller97"] = median(e->ns_per_pair) / r->second;
          if (std::isfinite(spread(e->ns_per_pair))) s["spread"] = spread(e->ns_per_pair);
        }
        if (e->ops) {
          const double n = static_cast<double>(e->pool->size());
          s["ops_per_pair"] = {{"add", e->ops->add / n}, {"mul", e->ops->mul / n}, {"div", e->ops->div / n},
                               {"cmp", e->ops->cmp / n}, {"sqrt", e->ops->sqrt / n}};
        }
        summary.push_back(std::move(s));
      }
      nlohmann::json pool_json = nlohmann::json::array();
      for (const auto& p : pools) {
        nlohmann::json stages;
        const auto mix = p.stage_mix();
        for (Stage st : {Stage::plane2, Stage::plane1, Stage::coplanar, Stage::interval})
          stages[std::string(to_string(st))] = mix[static_cast<std::size_t>(st)];
        pool_json.push_back({{"name", p.name()}, {"size", p.size()}, {"intersecting", p.intersecting()},
                             {"seed", hex64(p.seed)}, {"stages", stages}});
      }
      nlohmann::json untimed = nlohmann::json::array();
      for (const auto& e : faulted) {
        nlohmann::json faults = nlohmann::json::array();
        for (const Fault& f : e->faults)
          faults.push_back({{"pair", f.index}, {"fate", to_string(f.fate)}, {"detail", f.detail},
                            {"line", format_case(Case{e->pool->name() + "#" + std::to_string(f.index), e->pool->pairs[f.index], {}, "", 0})}});
        untimed.push_back({{"name", e->name()}, {"algorithm", e->algo}, {"level", e->level},
                           {"workload", e->pool->name()}, {"reason", e->not_timed.empty() ? "crashed or hung when checked" : e->not_timed},
                           {"wrong", e->score.wrong}, {"unsupported", e->score.unsupported}, {"faults", faults}});
      }
      doc["tritri"] = {{"not_timed", untimed},
                       {"pools", pool_json},
                       {"results", summary},
                       {"harness",
                        {{"floor_share_of_fastest",
                          [&] {
                            nlohmann::json j;
                            for (const auto& fs : floor_shares)
                              j[fs.name] = {
                                  {"full_size_pools", std::isfinite(fs.share_full) ? nlohmann::json(fs.share_full) : nlohmann::json()},
                                  {"all_pools", std::isfinite(fs.share) ? nlohmann::json(fs.share) : nlohmann::json()}};
                            return j;
                          }()},
                         {"spread_median", spreads.empty() ? nlohmann::json() : nlohmann::json(median(spreads))},
                         {"spread_worst", std::isfinite(worst_spread) ? nlohmann::json(worst_spread) : nlohmann::json()}}}};
      text = doc.dump(2);
    } else {
      std::cerr << "tritri bench: warning: could not parse Google Benchmark's JSON; writing it unchanged\n";
    }
    write_file_atomically(options.json_path, [&](std::ostream& f) { f << text << '\n'; });
    out << "\nwrote " << options.json_path << '\n';
  }
  return reporter.errors() ? 1 : 0;
}

}  // namespace tritri::bench
