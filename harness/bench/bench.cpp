// `tritri bench` put together: what to run, the pools, the entries, timing, the tables, the JSON.
#include "harness/bench/bench.hpp"

#include "harness/bench/entry.hpp"
#include "harness/bench/report.hpp"
#include "harness/bench/timing.hpp"
#include "harness/bench/workload.hpp"
#include "harness/bench/workloads/family.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <optional>
#include <ostream>
#include <regex>
#include <stdexcept>

namespace tritri::bench {
namespace {

// --filter as Google Benchmark 1.7 reads it (POSIX extended syntax, matched anywhere in the name,
// a leading '-' keeps the names that do not match), applied to the entries before they are
// counted and registered: the plan's count of benchmarks and its time are then the run's.
struct NameFilter {
  explicit NameFilter(std::string spec) {
    if (spec.empty() || spec == "all") return;
    if (spec.front() == '-') {
      negative = true;
      spec.erase(0, 1);
    }
    try {
      regex.emplace(spec, std::regex::extended);
    } catch (const std::regex_error& e) {
      throw std::invalid_argument("--filter: '" + spec + "' is not a regular expression (" + e.what() + ")");
    }
  }
  bool keeps(const std::string& name) const { return !regex || std::regex_search(name, *regex) != negative; }

  std::optional<std::regex> regex;
  bool negative = false;
};

const Algorithm& reference_algorithm(const std::string& name) {
  const Algorithm* a = registry().find(name);
  if (!a) {
    std::string known;
    for (const auto& x : registry().all())
      if (x.timeable()) known += (known.empty() ? "" : ", ") + x.name;
    throw std::invalid_argument("unknown reference algorithm '" + name + "' (known: " + known + ")");
  }
  if (!a->timeable()) throw std::invalid_argument("reference '" + name + "' is a process plug-in: Google Benchmark cannot time it");
  if (std::none_of(std::begin(kLevels), std::end(kLevels), [&](Level v) { return a->answers(v); }))
    throw std::invalid_argument("reference '" + name + "' answers no level");
  return *a;
}

// The floors first: the harness's own (loop, loads, fold) and the `null` plug-in when there is
// one; then the reference; then the algorithms asked for, in their order.
Lineup lineup_of(const Options& options, const Algorithm& reference) {
  Lineup l;
  l.algorithms = options.algorithms;
  if (l.algorithms.empty())
    for (const auto& a : registry().all())
      if (a.build.empty()) l.algorithms.push_back(&a);
  l.floors = {&harness_floor()};
  if (const Algorithm* null = registry().find("null")) l.floors.push_back(null);
  for (const Algorithm* f : l.floors) std::erase(l.algorithms, f);
  l.algorithms.insert(l.algorithms.begin(), l.floors.begin(), l.floors.end());
  if (std::find(l.algorithms.begin(), l.algorithms.end(), &reference) == l.algorithms.end())
    l.algorithms.insert(l.algorithms.begin() + static_cast<std::ptrdiff_t>(l.floors.size()), &reference);
  l.reference = &reference;
  l.reference_level = *std::find_if(std::begin(kLevels), std::end(kLevels), [&](Level v) { return reference.answers(v); });
  return l;
}

std::string corpus_hash_of(const std::vector<PlannedPool>& pools) {
  std::vector<const Pool*> list;
  for (const auto& p : pools) list.push_back(&p.pool);
  return hex64(hash_pools(list));
}

// The cases the family pools come from, as the JSON records them (and tritri check does).
CorpusIdentity family_corpus(const Options& options, const WorkloadInput& input) {
  CorpusIdentity corpus = options.family_corpus;
  if (corpus.files.empty()) corpus.generated_by = generator_source(input);
  return corpus;
}

}  // namespace

std::string_view to_string(Mode m) { return m == Mode::call ? "call" : "batch"; }

std::optional<Mode> parse_mode(std::string_view s) {
  for (Mode m : kModes)
    if (to_string(m) == s) return m;
  return std::nullopt;
}

Options quick_options() {
  Options o;
  o.pool_size = 4096;
  o.repetitions = 3;
  o.min_time = 0.005;
  o.min_warmup_time = 0;
  o.quick = true;
  return o;
}

int run(const Options& options, std::ostream& out) {
  // ---- what to run ----
  if (options.modes.empty()) throw std::invalid_argument("no timing mode (call, batch) chosen");
  const NameFilter filter(options.filter);
  const Lineup lineup = lineup_of(options, reference_algorithm(options.reference));
  std::vector<Level> levels = options.levels;
  if (levels.empty()) levels.assign(std::begin(kLevels), std::end(kLevels));
  const std::vector<Selected> selected = select_workloads(options.workloads, lineup.algorithms);

  // ---- the pools ----
  out << "tritri bench: building pools of " << options.pool_size << " pairs (seed " << options.seed
      << ") and labelling them with the oracle...\n";
  out.flush();
  WorkloadInput input{{options.pool_size, options.seed}, options.quick, options.family_corpus, options.read_family_cases,
                      options.authors_code};
  const Planned planned = build_pools_cached(selected, input, options.cache, out);

  // ---- the entries: checked and counted before anything is timed ----
  CheckCache checks(options.cache, planned.cache_key, options, out);
  Entries entries = make_entries(planned.pools, lineup, levels, options, checks);
  checks.save(out);
  std::erase_if(entries.timed, [&](const auto& e) { return !filter.keeps(e->name()); });
  report_untimed(entries.untimed, out);

  // ---- Google Benchmark ----
  init_google_benchmark(options);
  register_benchmarks(entries.timed, options.repetitions);
  const std::string corpus_hash = corpus_hash_of(planned.pools);
  const RunContext context = run_context(options, planned, corpus_hash);
  print_pools(planned.pools, out);
  // What the timing will take: each repetition runs at least its minimum time after its warm-up;
  // finding the iteration count adds about a tenth (measured on the main job's bench).
  const double timing_seconds = 1.1 * static_cast<double>(entries.timed.size()) * options.repetitions *
                         (options.min_time + options.min_warmup_time);
  out << "corpus hash " << corpus_hash << "; " << entries.timed.size() << " benchmarks, " << options.repetitions
      << " repetitions each" << (options.interleave ? ", randomly interleaved" : "") << "; times relative to "
      << lineup.reference_row() << "; about " << static_cast<long>(timing_seconds + 0.5) << " s of timing.\n\n";
  out.flush();
  if (options.list_only) {
    list_benchmarks();
    return 0;
  }
  const TimingRun timing = run_benchmarks(entries.timed, options.repetitions);

  // ---- the tables, the harness's numbers, the JSON ----
  const Summary summary = summarize(entries.timed, planned.pools, lineup, options.pool_size, options.modes);
  print_tables(entries.timed, summary, options.repetitions, out);
  print_self_timed(entries.self_timed, summary, out);
  print_harness(summary, out);
  if (!options.json_path.empty()) {
    write_json(options.json_path, timing.json, context, entries, planned.pools, summary, family_corpus(options, input));
    out << "\nwrote " << options.json_path << '\n';
  }
  return timing.errors ? 1 : 0;
}

}  // namespace tritri::bench
