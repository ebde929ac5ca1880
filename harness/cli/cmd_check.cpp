#include "harness/cli/args.hpp"
#include "cases/util/progress.hpp"
#include "harness/check/check.hpp"
#include "harness/check/check_output.hpp"
#include "harness/check/baseline_file.hpp"
#include "harness/check/stream.hpp"
#include "harness/cli/commands.hpp"
#include "cases/util/atomic_file.hpp"

#include <algorithm>
#include <iostream>
#include <map>

namespace tritri::cli {
namespace {

// --group-by SPEC (repeatable): each a grouping of the cases by their labels (grouping.hpp).
std::vector<Grouping> groupings_of(const std::vector<std::string>& specs) {
  std::vector<Grouping> out;
  for (const std::string& spec : specs) {
    try {
      out.push_back(parse_grouping(spec));
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--group-by: ") + e.what());
    }
  }
  return out;
}

void print_rows(const char* title, const std::vector<BaselineRow>& rows, std::size_t limit) {
  std::cout << title << ": " << rows.size() << '\n';
  std::size_t shown = 0;
  for (const auto& [algorithm, name, level, answer, expected] : rows) {
    if (shown++ == limit) {
      std::cout << "  ...\n";
      break;
    }
    std::cout << "  " << algorithm << '\t' << name << '\t' << level << "\tanswered " << answer
              << ", oracle " << expected << '\n';
  }
}

// Per algorithm "new: N, fixed: M", then the first few new disagreements' cases, paste-ready
// (hex float: exactly the input that was judged), so a regression can go straight into a case file.
void print_per_algorithm(const CheckResult& result, const BaselineComparison& comparison) {
  std::map<std::string, std::pair<std::size_t, std::size_t>> counts;
  for (const Algorithm* a : result.algorithms) counts[a->name];
  for (const auto& row : comparison.new_failures) ++counts[std::get<0>(row)].first;
  for (const auto& row : comparison.fixed) ++counts[std::get<0>(row)].second;
  std::cout << "per algorithm, against the baseline:\n";
  for (const auto& [name, c] : counts)
    std::cout << "  " << name << ": new: " << c.first << ", fixed: " << c.second << '\n';
  if (comparison.new_failures.empty()) return;
  std::map<std::string, const Case*> by_name;
  for (const Failure& f : result.failures) by_name.emplace(f.subject->name, f.subject.get());
  constexpr std::size_t kShown = 5;
  std::cout << "the first new disagreements' cases, paste-ready:\n";
  for (std::size_t i = 0; i < comparison.new_failures.size() && i < kShown; ++i) {
    const auto& [algorithm, name, level, answer, expected] = comparison.new_failures[i];
    std::cout << "# " << algorithm << " " << level << ": answered " << answer << ", oracle " << expected << '\n';
    if (auto it = by_name.find(name); it != by_name.end())
      std::cout << format_case(*it->second, NumberStyle::hex) << '\n';
  }
}

// --shard K/N, as the JSON records it.
std::optional<ShardInfo> shard_info(const Args& args) {
  const auto shard = shard_option(args);
  if (!shard) return std::nullopt;
  return ShardInfo{shard->index, shard->count, shard->range.first, shard->range.end, shard->total};
}

// The JSON and the baseline the command line asks for, each written atomically.
void write_outputs(const Args& args, const CheckResult& result, CheckJsonContext context) {
  if (auto json = args.value("--json")) {
    context.inputs = args.positional();
    context.corpus = identify_corpus(args.positional());
    if (args.value("--json-max-failures")) context.failure_cap = args.count("--json-max-failures", 0);
    write_file_atomically(*json, [&](std::ostream& out) { write_check_json(out, result, context); });
  }
  if (auto out_path = args.value("--write-baseline")) write_baseline_file(*out_path, baseline_of(result));
}

// --scorecard: one scorecard per algorithm, printed as one line each.
// The bases are drawn from the whole input (read again, keeping only the cases that can be
// bases), so every shard would draw the same: only shard 0 computes them, and merge keeps its.
std::vector<Scorecard> scorecards_of(const Args& args, const std::vector<const Algorithm*>& algorithms) {
  ScorecardOptions options;
  options.max_bases = args.count("--scorecard-bases", options.max_bases);
  std::vector<Case> candidates, chunk;
  CaseStream stream(args.positional());
  while (stream.next(chunk, 1 << 14))
    for (Case& c : chunk)
      if (is_scorecard_base(c)) candidates.push_back(std::move(c));
  const auto bases = scorecard_bases(candidates, options);
  std::vector<Scorecard> cards;
  Progress progress("scorecard", algorithms.size());
  for (const Algorithm* a : algorithms) {
    cards.push_back(compute_scorecard(*a, bases, options, isolation_options(args)));
    progress.update(cards.size());
  }
  progress.finish();
  print_scorecards(std::cout, cards, bases.size());
  return cards;
}

// --cross-check: two exact implementations, the oracle (CGAL Epeck) and the `exact` algorithm
// (algorithms/exact, written independently from orientation signs), must agree on every case
// at both levels; any disagreement is a bug in one of them, reported loudly.
constexpr const char* kCrossCheckAlgorithm = "exact";

int cross_check_verdict(const CheckResult& result) {
  std::size_t bad = 0;
  for (const auto& [key, t] : result.tallies)
    bad += t.false_positives + t.false_negatives + t.misclassified + t.unsupported + t.crashes + t.timeouts;
  if (bad == 0) {
    std::cout << "\ncross-check: the oracle and '" << kCrossCheckAlgorithm << "' agree on all " << result.case_count
              << " cases at both levels\n";
    return kOk;
  }
  std::cout << "\n*** CROSS-CHECK FAILED: the oracle and '" << kCrossCheckAlgorithm << "' disagree " << bad
            << " time(s). Both claim to be exact, so this is a bug in one of them. The cases:\n";
  print_failures(std::cout, result, result.failures.size());
  std::cerr << "tritri check --cross-check: " << bad << " disagreement(s) between two exact tests\n";
  return kFindings;
}

constexpr const char* kUsageText =
    "usage: tritri check [--algo NAME...] [--json OUT] [--baseline FILE...]\n"
    "                    [--write-baseline FILE] [--max-failures N] [--confusion] [--quiet]\n"
    "                    [--float] [--json-max-failures N] [--group-by GROUPING...]\n"
    "                    [--scorecard] [--scorecard-bases N]\n"
    "                    [--plugin LIB...] [--exec COMMAND]... [--timeout S] [--no-isolation]\n"
    "                    [--cross-check] [--judge exact-first|oracle] [--shard K/N] FILE...\n\n"
    "Runs each chosen algorithm (default: all) on every case and compares its answers with\n"
    "the exact oracle. Prints a table per algorithm x family (the case's family= label, else\n"
    "the file name): cases, FP (said they meet, they do not), FN (said they do not, they do),\n"
    "relation (misclassified relation, '-' when not answered), unsupported (declined, or\n"
    "degenerate input the algorithm does not accept), crash and timeout (the algorithm died\n"
    "or hung on the case: each algorithm runs in a child process, and the case responsible is\n"
    "found by bisection; the others are still checked). Then the first N disagreements\n"
    "(default 20), each paste-ready as a case line in %.17g and in hex float.\n\n"
    "For algorithms that answer the relation level, a confusion table follows: per algorithm\n"
    "x family, 'answered->oracle count' for every wrong cell (relation names, or dim:<d> for\n"
    "an algorithm that states only the dimension). For algorithms that answer the segment\n"
    "level, a segment table: cases answered, errors measured (Hausdorff distance between the\n"
    "answered and the exact point or segment, over the pair's bounding-box diagonal), their\n"
    "median and max, kind mismatches (answered empty/point/segment/area where the exact\n"
    "intersection has another dimension) and coplanar contacts answered without geometry.\n\n"
    "  --algo NAME...       the algorithms to check; see 'tritri list'.\n"
    "                       Default: all but the x86-64-v3/FMA builds (NAME@v3fma), which run\n"
    "                       when named\n"
    "  --json OUT           also write the results as JSON (schema in harness/README.md)\n"
    "  --baseline FILE...   recorded disagreements: exit 1 if any disagreement\n"
    "                       is new; list the recorded ones that no longer occur. Plain TSV,\n"
    "                       or gzip-compressed TSV (recognised by its content)\n"
    "  --write-baseline F   record this run's disagreements as a baseline (gzip-compressed\n"
    "                       when F ends in .gz)\n"
    "  --max-failures N     how many disagreements to print (default 20)\n"
    "  --json-max-failures N  keep only the first N disagreements per algorithm x family x\n"
    "                       level in the JSON (default: all); the tallies count every case\n"
    "  --confusion          print every confusion cell, the right ones too\n"
    "  --quiet              print only the tables (and the baseline comparison)\n"
    "  --float              run each algorithm's float instantiation instead (named NAME@float;\n"
    "                       each pair is rounded to float inside the call and judged against\n"
    "                       the oracle on the double input); algorithms without one are left\n"
    "                       out. No baseline records these names.\n"
    "  --group-by GROUPING...  tally per group of labels instead of per family, a GROUPING\n"
    "                       being KEY[,KEY]... (a case is counted once in each it is in):\n"
    "                       the group is 'KEY=value KEY=value' from the case's labels, and\n"
    "                       cases lacking a KEY are not in the grouping. KEY=VALUE keeps only\n"
    "                       the cases with that value; @base is the case's name up to its\n"
    "                       last '.' (the base construction of a corpus variant). E.g.\n"
    "                       --group-by subsuite=symmetry,@base --group-by subsuite,tilt\n"
    "  --scorecard          also compute each algorithm's robustness scorecard (JSON\n"
    "                       \"scorecards\", schema in harness/README.md) and print it: on base\n"
    "                       cases of the input (cases that are no variant, or the identity\n"
    "                       symmetry), the share whose answer changes under argument swap,\n"
    "                       the 36 vertex orders, the 48 signed axis permutations, scaling by\n"
    "                       2^k and exact translation; touching probes (shared vertex, shared\n"
    "                       edge, vertex on face, coplanar shared edge) in 72 symmetric forms\n"
    "                       against the declared boundary; degenerate probes, called even\n"
    "                       where the algorithm does not accept them; float against double\n"
    "  --scorecard-bases N  at most N base cases, evenly spaced (default 400)\n"

    "  --judge J            exact-first (default): the 'exact' algorithm decides overlap and\n"
    "                       relation, the oracle (CGAL) what it declines, the exact intersection\n"
    "                       for the segment level, and about one case in 64 (seeded by the\n"
    "                       case's place in the input) as a cross-check: a disagreement is an\n"
    "                       error (exit 3). oracle: the oracle judges every case\n"
    "  --shard K/N          check only part K of N of the input (0 <= K < N; contiguous ranges\n"
    "                       of the cases in file order); 'tritri merge' joins the N JSON results\n"
    "                       into the one a single run writes (scripts/cluster/). With --scorecard,\n"
    "                       shard 0 computes the scorecards (over the whole input's bases)\n"
    "  --cross-check        the second judge: check only the 'exact' algorithm (exact by\n"
    "                       construction, written independently of the oracle) at both\n"
    "                       levels; any disagreement is a bug in the oracle or in it: all are\n"
    "                       printed paste-ready and the exit status is 1\n";

constexpr const char* kExitStatus =
    "\n"
    "Exit status: 0, or 1 when a baseline was given and a new disagreement appeared (or, with\n"
    "--cross-check, any disagreement), 2 on bad arguments or input.\n";

}  // namespace

namespace {

// How the cases are judged: exact first unless --judge oracle, and the oracle alone for
// --cross-check (which checks `exact` itself against it).
JudgeOptions judge_options(const Args& args, const std::vector<const Algorithm*>& algorithms, bool cross_check) {
  JudgeOptions judge;
  try {
    judge.kind = judge_kind_of(args.value("--judge").value_or("exact-first"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--judge: ") + e.what());
  }
  if (cross_check) judge.kind = JudgeKind::oracle;
  judge.geometry = std::any_of(algorithms.begin(), algorithms.end(),
                               [](const Algorithm* a) { return a->answers(Level::segment); });
  return judge;
}

void print_results(const Args& args, const CheckResult& result) {
  print_check_table(std::cout, result);
  print_confusion(std::cout, result, args.flag("--confusion"));
  print_segment_errors(std::cout, result);
  if (!args.flag("--quiet") && !result.failures.empty()) {
    std::cout << '\n';
    print_failures(std::cout, result, args.count("--max-failures", 20));
  }
  std::cout << "judged: " << result.judged.exact << " cases by exact, " << result.judged.oracle
            << " by the oracle; " << result.judged.cross_checked << " cross-checked by the oracle (--judge "
            << to_string(result.judge) << ")\n";
}

}  // namespace

int cmd_check(int argc, char** argv) {
  Args args(argc, argv,
            merged({.valued = {"--json", "--write-baseline", "--max-failures", "--json-max-failures",
                               "--scorecard-bases", "--judge", "--shard"},
                    .lists = {"--algo", "--baseline"},
                    .word_lists = {"--group-by"},
                    .flags = {"--quiet", "--confusion", "--float", "--scorecard", "--cross-check"}},
                   kRunOptions));
  if (args.help()) {
    std::cout << kUsageText << kRunOptionsHelp << '\n' << kListsHelp << kExitStatus;
    return kOk;
  }
  load_external_algorithms(args);
  // Named algorithms, else every built-in one plus every plug-in given.
  const bool cross_check = args.flag("--cross-check");
  if (cross_check && (args.flag("--float") || !args.values("--algo").empty()))
    throw UsageError("--cross-check checks the 'exact' algorithm on double: no --algo or --float with it");
  const auto algorithms = cross_check ? select_algorithms({kCrossCheckAlgorithm})
                          : args.flag("--float") ? float_instantiations(select_algorithms(args.values("--algo")), false,
                                                                        "tritri check --float")
                                                 : select_algorithms(args.values("--algo"));
  const std::size_t max_failures = args.count("--max-failures", 20);
  // Read the baselines before the (possibly long) run, so a wrong path fails at once.
  Baseline recorded;
  const auto baseline_files = args.values("--baseline");
  for (const auto& file : baseline_files)
    for (auto& row : read_baseline(file)) recorded.insert(row);
  if (args.positional().empty()) throw UsageError("no case file given (the built-in cases are cases/builtin.cases)");
  CheckJsonContext context;
  context.shard = shard_info(args);
  context.judge = judge_options(args, algorithms, cross_check);
  StreamOptions options{.groupings = groupings_of(args.values("--group-by")),
                        .isolation = isolation_options(args),
                        .judge = context.judge};
  if (context.shard) options.range = {context.shard->first, context.shard->end};
  const CheckResult result = check_files(algorithms, args.positional(), options);

  print_results(args, result);
  if (args.flag("--scorecard") && (!context.shard || context.shard->index == 0))
    context.scorecards = scorecards_of(args, algorithms);
  write_outputs(args, result, context);
  if (report_incomplete(std::cerr, result)) return kFindings;  // a gate that did not run every case fails
  if (cross_check) return cross_check_verdict(result);

  if (baseline_files.empty()) return kOk;
  const auto comparison = compare_with_baseline(recorded, result);
  std::cout << '\n';
  print_rows("new disagreements (not in the baseline)", comparison.new_failures, max_failures);
  print_rows("fixed (in the baseline, no longer occurring)", comparison.fixed, max_failures);
  print_per_algorithm(result, comparison);
  return comparison.new_failures.empty() ? kOk : kFindings;
}

}  // namespace tritri::cli
