// `tritri hunt`: search out an algorithm's failures beyond the corpus, confirm each with the
// oracle, group them by signature and shrink one witness per group (harness/hunt/hunt.hpp).
#include "harness/cli/args.hpp"
#include "harness/cli/commands.hpp"
#include "harness/hunt/output.hpp"
#include "cases/util/atomic_file.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <unistd.h>

namespace tritri::cli {
namespace {

constexpr const char* kUsageText =
    "usage: tritri hunt --algo NAME... [--seconds S | --pairs N] [--seed K] [--level overlap|relation]\n"
    "                   [--baseline FILE...] [--batch N] [--shrink-rounds N] [--shrink-seconds S]\n"
    "                   [--shard K/N]\n"
    "                   [--plugin LIB...] [--exec COMMAND]... [--timeout S] [--max-faults N] --out DIR\n\n"
    "Searches for pairs each algorithm answers wrongly, beyond the corpus: corpus constructions\n"
    "drawn with fresh seeds, the bench's random shapes, small-integer and dyadic grids, perturbed\n"
    "singular pairs, and walks from one side of a decision to the other bisected down to two\n"
    "adjacent doubles; half the candidates are copies of the others under one exact\n"
    "transformation (argument swap, vertex order, signed axis permutation, 2^k scaling, exact\n"
    "translation) or rounded to float. Every candidate is judged by the 'exact' algorithm in\n"
    "batch (by the oracle when the algorithm hunted is exact itself); every failure counted is\n"
    "confirmed by the oracle (CGAL). Failures are grouped by a signature: the level, the answer,\n"
    "the oracle's relation, the plane configuration (coplanar, parallel, near_parallel,\n"
    "general), shared vertices, the scale class, and the transformation that broke an\n"
    "otherwise right answer. Each new group's cheapest failure is then shrunk, one step at a time,\n"
    "each step kept only while the algorithm gives the same wrong answer and the verdict does not\n"
    "change (a vertex to the origin, small integers, few significant bits, 2^k scaling, fewer\n"
    "distinct values), and the witness confirmed by the oracle. A crash or hang is a finding too\n"
    "(each algorithm runs in a child process); its pair is not shrunk.\n\n"
    "Writes DIR/witnesses.cases (one paste-ready case line per group, expect= the oracle's\n"
    "relation) and DIR/hunt.json (schema tritri-hunt/1, harness/README.md: pairs tried, failures\n"
    "per group, time to first failure, witness sizes). A progress line on stderr shows pairs/s\n"
    "and groups.\n\n"
    "  --algo NAME...       the algorithms to hunt, one after the other (required; 'tritri list')\n"
    "  --seconds S          search budget per algorithm (default 60); shrinking comes after it,\n"
    "                       with as many seconds again unless --shrink-seconds says otherwise\n"
    "  --pairs N            search budget in candidates instead: the run is then deterministic\n"
    "                       for a seed (the same groups, counts and witnesses on every run)\n"
    "  --seed K             the search's seed (default 1); batch k draws from (K, k) alone\n"
    "  --level L            overlap (default) or relation (algorithms answering relations)\n"
    "  --baseline FILE...   a previous hunt's JSON: groups with a signature recorded there are\n"
    "                       listed as known and not shrunk; exit 1 if a new group appears\n"
    "  --batch N            candidates per batch (default 4096)\n"
    "  --shrink-rounds N    at most N shrinking steps per witness (default 64)\n"
    "  --shrink-seconds S   the shrinking's budget per algorithm, all its groups together\n"
    "                       (default: --seconds; none with --pairs, so that run stays\n"
    "                       deterministic); groups shrink in order of discovery and those it\n"
    "                       does not reach keep the failure as found (shrink_cut in the JSON)\n"
    "  --shard K/N          with --pairs: hunt only part K of N of the run's batches (0 <= K < N;\n"
    "                       contiguous); 'tritri merge' joins the N hunt.json files into the\n"
    "                       one run's, the same but for the clock's fields (seconds,\n"
    "                       pairs_per_second, shrink_seconds, first_seconds,\n"
    "                       first_failure_seconds: the merge adds or takes the first shard's)\n"
    "  --out DIR            where the witnesses and the JSON go (created)\n";

constexpr const char* kExitStatus =
    "\nExit status: 0 (failures found without a baseline are findings, not errors), 1 when a\n"
    "baseline was given and a new group appeared, or a run stopped at --max-faults; 2 on bad\n"
    "arguments or input.\n";

// One line per batch: on a terminal redrawn in place, in a log every few seconds.
class ProgressLine {
 public:
  explicit ProgressLine(std::string name) : name_(std::move(name)), terminal_(isatty(fileno(stderr)) == 1) {}
  void update(std::size_t pairs, std::size_t groups, std::size_t failures, double seconds) {
    if (seconds - last_ < (terminal_ ? 0.2 : 5.0)) return;
    last_ = seconds;
    std::fprintf(stderr, "%shunt %s: %zu pairs, %.0f pairs/s, %zu groups, %zu failures, %.0f s%s",
                 terminal_ ? "\r" : "", name_.c_str(), pairs, seconds > 0 ? pairs / seconds : 0.0, groups,
                 failures, seconds, terminal_ ? "   " : "\n");
  }
  void finish() const {
    if (terminal_ && last_ > 0) std::fputc('\n', stderr);
  }

 private:
  std::string name_;
  bool terminal_;
  double last_ = 0;
};

hunt::HuntOptions options_of(const Args& args, hunt::HuntRun& run) {
  hunt::HuntOptions o;
  o.seed = run.seed = args.seed("--seed", 1);
  if (args.value("--pairs") && args.value("--seconds")) throw UsageError("give --seconds or --pairs, not both");
  if (args.value("--pairs")) o.pairs = run.pairs = args.count("--pairs", 0);
  else o.seconds = *(run.seconds = args.seconds("--seconds").value_or(60.0));
  const std::string level = args.value("--level").value_or("overlap");
  if (level != "overlap" && level != "relation") throw UsageError("--level: overlap or relation, not '" + level + "'");
  o.level = level == "overlap" ? Level::overlap : Level::relation;
  run.level = level;
  o.batch = run.batch = args.count("--batch", o.batch);
  if (o.batch < 2) throw UsageError("--batch: at least 2");
  o.shrink_rounds = static_cast<int>(args.count("--shrink-rounds", static_cast<std::size_t>(o.shrink_rounds)));
  o.shrink_seconds = args.seconds("--shrink-seconds");
  if (!o.shrink_seconds && !o.pairs) o.shrink_seconds = o.seconds;
  run.shrink_seconds = o.shrink_seconds;
  o.isolation = isolation_options(args);
  if (const auto shard = shard_spec(args)) {
    if (!o.pairs) throw UsageError("--shard K/N needs --pairs N: a hunt in seconds has no fixed set of batches to split");
    const auto [first, end] = hunt::take_shard(o, shard->index, shard->count);
    run.shard = hunt::HuntRun::Shard{shard->index, shard->count, first, end, *o.pairs};
  }
  return o;
}

void print_summary(const hunt::HuntResult& r) {
  std::cout << r.algorithm << ": " << r.pairs << " pairs in " << r.seconds << " s, " << r.failures
            << " failures in " << r.groups.size() << " groups (" << hunt::new_groups(r) << " new)";
  if (r.first_failure_seconds) std::cout << ", first after " << *r.first_failure_seconds << " s";
  if (r.unconfirmed) std::cout << ", " << r.unconfirmed << " not confirmed by the oracle";
  std::cout << '\n';
  for (const hunt::Group& g : r.groups)
    std::cout << "  " << g.count << "\t" << g.signature.key() << (g.known ? "  (known)" : "") << '\n';
}

}  // namespace

int cmd_hunt(int argc, char** argv) {
  Args args(argc, argv,
            merged({.valued = {"--seconds", "--pairs", "--seed", "--level", "--batch", "--shrink-rounds", "--shrink-seconds",
                               "--out", "--shard"},
                    .lists = {"--algo", "--baseline"},
                    .operands = false},
                   kRunOptions));
  if (args.help()) {
    std::cout << kUsageText << kRunOptionsHelp << '\n' << kListsHelp << kExitStatus;
    return kOk;
  }
  if (!args.positional().empty()) throw UsageError("hunt takes no operands: '" + args.positional()[0] + "'");
  const auto out = args.value("--out");
  if (!out) throw UsageError("--out DIR is required");
  if (args.values("--algo").empty()) throw UsageError("--algo NAME is required (see 'tritri list')");
  load_external_algorithms(args);
  const auto algorithms = select_algorithms(args.values("--algo"));
  hunt::HuntRun run;
  hunt::HuntOptions options = options_of(args, run);
  std::map<std::string, std::set<std::string>> known;
  for (const auto& file : args.values("--baseline")) {
    run.baselines.push_back(file);
    for (auto& [name, keys] : hunt::read_hunt_baseline(file)) known[name].insert(keys.begin(), keys.end());
  }
  for (const Algorithm* a : algorithms) {  // before any hunt: a long run does not die at its fifth algorithm
    try {
      hunt::check_level(*a, options.level);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
  }
  std::filesystem::create_directories(*out);
  std::vector<hunt::HuntResult> results;
  bool findings = false;
  for (const Algorithm* a : algorithms) {
    ProgressLine line(a->name);
    options.known = known[a->name];
    options.progress = [&line](std::size_t p, std::size_t g, std::size_t f, double s) { line.update(p, g, f, s); };
    results.push_back(hunt::run_hunt(*a, options));
    line.finish();
    print_summary(results.back());
    findings = findings || results.back().stopped || (!run.baselines.empty() && hunt::new_groups(results.back()) > 0);
    // Written after each algorithm, so an interrupted run keeps what it found.
    write_file_atomically(*out + "/witnesses.cases", [&](std::ostream& o) { hunt::write_witnesses(o, results, run); });
    write_file_atomically(*out + "/hunt.json", [&](std::ostream& o) { o << hunt::hunt_json(results, run).dump(2) << '\n'; });
  }
  return findings ? kFindings : kOk;
}

}  // namespace tritri::cli
