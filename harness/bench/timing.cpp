#include "harness/bench/timing.hpp"

#include "cases/util/stats.hpp"
#include "tritri/add_level.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>
#include <unistd.h>

namespace tritri::bench {
namespace {

// ---- the floor ----

// Reads every coordinate and returns one bit of them: the cost of the loop, the memory traffic
// and the answer fold, with no test in it.
bool floor_kernel(const TrianglePair& p) {
  std::uint64_t h = 0;
  for (const Triangle* t : {&p.t1, &p.t2})
    for (const auto& v : t->v) h ^= std::bit_cast<std::uint64_t>(v[0]) ^ std::bit_cast<std::uint64_t>(v[1]) ^
                                    std::bit_cast<std::uint64_t>(v[2]);
  return (h >> 52) & 1u;
}

// ---- the timed loops ----

template <Level L>
void time_level(benchmark::State& state, const Algorithm& algorithm, const TrianglePair* pairs, std::size_t n) {
  const BatchFn<L> batch = algorithm.batch<L>();
  std::array<AnswerOf<L>, kBatch> out{};
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

// One pair per call through `fn` (a function pointer), `call(fn, pair)` making the call and
// folding its answer. The empty asm makes the pointer opaque to the compiler on every pair, so
// it can neither inline the test nor hoist or vectorise anything across calls: each pair is a
// real indirect call, as a BVH traversal makes (harness/bench/README.md, "What is measured", says how the
// generated loop was checked).
template <class Fn, class Call>
void time_calls(benchmark::State& state, Fn fn, Call call, const TrianglePair* pairs, std::size_t n) {
  std::uint64_t checksum = 0;
  for (auto _ : state) {
    for (std::size_t at = 0; at < n; at += kBatch) {
      const std::size_t m = std::min(kBatch, n - at);
      std::uint64_t sum = 0;
      for (std::size_t i = 0; i < m; ++i) {
        Fn f = fn;
        asm volatile("" : "+r"(f));
        sum += call(f, pairs[at + i]);
      }
      checksum += sum;
      benchmark::DoNotOptimize(checksum);
    }
  }
}

// Call mode goes through the one-pair entry, or, for an algorithm without one (a C-ABI
// plug-in), through its batch with n = 1.
template <Level L>
void time_entry_level(benchmark::State& state, const Algorithm& a, Mode mode, const TrianglePair* pairs, std::size_t n) {
  if (mode == Mode::batch) {
    time_level<L>(state, a, pairs, n);
  } else if (const PairFn<L> one = a.one_pair<L>()) {
    time_calls(state, one, [](PairFn<L> f, const TrianglePair& p) { return fold_answer(f(p)); }, pairs, n);
  } else {
    const auto one_of_batch = [](BatchFn<L> f, const TrianglePair& p) {
      AnswerOf<L> answer{};
      f(&p, 1, &answer);
      return fold_answer(answer);
    };
    time_calls(state, a.batch<L>(), one_of_batch, pairs, n);
  }
}

using LevelTimer = void (*)(benchmark::State&, const Algorithm&, Mode, const TrianglePair*, std::size_t);

LevelTimer timer_of(Level level) {
  LevelTimer timer = nullptr;
  for_each_level([&](auto l) {
    if (decltype(l)::value == level) timer = &time_entry_level<decltype(l)::value>;
  });
  return timer;
}

double spread_statistic(const std::vector<double>& v) {
  const double s = spread(v);
  return std::isfinite(s) ? s : 0.0;
}

// The counters beside the time: pairs per pass, the check's verdicts, the operation counts.
void set_counters(benchmark::State& state, const Entry& entry, std::size_t n) {
  const double pairs_done = static_cast<double>(state.iterations()) * static_cast<double>(n);
  state.SetItemsProcessed(static_cast<std::int64_t>(pairs_done));
  using C = benchmark::Counter;
  state.counters["per_pair"] = C(static_cast<double>(n), C::kIsIterationInvariantRate | C::kInvert);
  state.counters["wrong"] = C(static_cast<double>(entry.score.wrong));
  state.counters["unsupported"] = C(static_cast<double>(entry.score.unsupported));
  state.counters["pool"] = C(static_cast<double>(n));
  if (!entry.ops) return;
  const double per = 1.0 / static_cast<double>(n);
  state.counters["add"] = C(static_cast<double>(entry.ops->add) * per);
  state.counters["mul"] = C(static_cast<double>(entry.ops->mul) * per);
  state.counters["div"] = C(static_cast<double>(entry.ops->div) * per);
  state.counters["cmp"] = C(static_cast<double>(entry.ops->cmp) * per);
  state.counters["sqrt"] = C(static_cast<double>(entry.ops->sqrt) * per);
}

// ---- reporting: the console gets the medians, the JSON everything ----

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

}  // namespace

const Algorithm& harness_floor() {
  static const Algorithm a = [] {
    Algorithm f;
    f.name = "floor";
    f.summary = "the harness floor: reads every coordinate (integer XOR, no dependency chain), returns a bit";
    f.accepts_degenerate = true;
    add_level<Level::overlap>(f, [](const TrianglePair& p) { return floor_kernel(p); });
    return f;
  }();
  return a;
}

void init_google_benchmark(const Options& options) {
  // Google Benchmark keeps a pointer to argv[0] (the program name it prints in the context), so it
  // must outlive this call; the flags themselves are parsed and copied here.
  static char program_name[] = "tritri-bench";
  std::vector<std::string> flags = {
      "--benchmark_repetitions=" + std::to_string(std::max(1, options.repetitions)),
      "--benchmark_enable_random_interleaving=" + std::string(options.interleave ? "true" : "false"),
      "--benchmark_min_time=" + std::to_string(options.min_time),
      "--benchmark_min_warmup_time=" + std::to_string(options.min_warmup_time),
  };
  // Every flag a run may set is given each time: Google Benchmark keeps a flag's value from one
  // Initialize to the next, and the tests run several benches in one process.
  // The filter itself is applied to the entries before they are registered (bench.cpp), so Google
  // Benchmark runs every registered benchmark.
  flags.push_back("--benchmark_filter=");
  flags.push_back("--benchmark_list_tests=" + std::string(options.list_only ? "true" : "false"));
  std::vector<char*> argv = {program_name};
  for (auto& f : flags) argv.push_back(f.data());
  int argc = static_cast<int>(argv.size());
  benchmark::Initialize(&argc, argv.data());
}

void register_benchmarks(const EntryList& timed, int repetitions) {
  for (const auto& e : timed) {
    const Entry* entry = e.get();
    const std::size_t n = entry->pool->size();
    const LevelTimer timer = entry->stage ? nullptr : timer_of(*entry->level);
    auto* b = benchmark::RegisterBenchmark(entry->name().c_str(), [entry, n, timer](benchmark::State& state) {
      if (entry->stage) time_stage(state, entry->stage->run, entry->input(), n);
      else timer(state, *entry->algorithm, *entry->mode, entry->input(), n);
      set_counters(state, *entry, n);
    });
    b->Unit(benchmark::kMicrosecond);
    if (repetitions > 1) b->ComputeStatistics("spread", spread_statistic, benchmark::StatisticUnit::kPercentage);
  }
}

TimingRun run_benchmarks(const EntryList& timed, int repetitions) {
  std::map<std::string, Entry*> by_name;
  for (const auto& e : timed) by_name[e->name()] = e.get();
  Reporter reporter(by_name, isatty(fileno(stdout)) == 1, repetitions);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  // The benchmarks point at the entries, which do not outlive the run.
  benchmark::ClearRegisteredBenchmarks();
  benchmark::Shutdown();
  return {reporter.json(), reporter.errors()};
}

void list_benchmarks() {
  benchmark::RunSpecifiedBenchmarks();
  benchmark::ClearRegisteredBenchmarks();
  benchmark::Shutdown();
}

}  // namespace tritri::bench
