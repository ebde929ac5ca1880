#include "harness/cli/args.hpp"
#include "harness/bench/bench.hpp"
#include "harness/cli/commands.hpp"
#include "tritri/isa.hpp"

#include <algorithm>
#include <cstdlib>

#include <iostream>

namespace tritri::cli {
namespace {

constexpr const char* kHelp =
    "usage: tritri bench [--quick] [--algo NAME...] [--level L...] [--workload W...]\n"
    "                    [--mode call|batch|both] [--isa NAME]\n"
    "                    [--reference NAME] [--filter REGEX] [--pool N] [--seed S]\n"
    "                    [--repetitions N] [--min-time SEC] [--no-interleave] [--no-ops]\n"
    "                    [--json OUT] [--cases FILE...] [--list] [--cache DIR] [--no-cache]\n"
    "                    [--float] [--authors-code PATH]\n\n"
    "Times every algorithm on every workload and level it serves, on Google Benchmark.\n"
    "Workloads are pools of distinct pairs, built and labelled by the exact oracle before\n"
    "anything is timed, shuffled once and streamed in order (default 65536 pairs):\n"
    "  ratio:R    R = 0, 0.1, ..., 1: exactly R of the pairs intersect; triangles of mixed\n"
    "             sizes, so every exit stage of a plane-rejecting test occurs\n"
    "  type:T     T = disjoint, point, segment, area: the dimension of the intersection\n"
    "  family:F   one pool per corpus family (the generator's, or the cases of --cases):\n"
    "             what singular and near-singular input costs\n"
    "  stage      the stages an algorithm registers (Yu-He's transform / test in the frame),\n"
    "             on the ratio:0.50 pool\n"
    "  size:N     the ratio:0.50 pool at N pairs; bare 'size' is N = 4096, 16384, 65536,\n"
    "             262144, 1048576: how a small pool lets the branch predictor learn the\n"
    "             answers. Not in the default set (labelling a million pairs takes a while);\n"
    "             --pool does not apply to it\n"
    "  paper:P    P = shen03, shen03-drawn, tropp06, yuhe13: a paper's own timing driver\n"
    "             (its distribution, pool, order and ratio), with /shuffled, /n:N, /r:R,\n"
    "             /ours to change one thing of it (harness/bench/workloads/paper.hpp); not\n"
    "             in the default set. paper:shen03 reads the authors' data files\n"
    "             (--authors-code) and is skipped with one line without them\n"
    "Benchmarks are named algo/level/workload:value/mode (e.g. moller97/overlap/ratio:0.50/call;\n"
    "a stage: yuhe13/stage:transform/ratio:0.50/batch). Every\n"
    "algorithm is checked on every pool first: 'wrong' counts its disagreements with the\n"
    "oracle, shown beside the time. Prints ns per pair per algorithm x workload, relative\n"
    "to the reference, the operation counts of the counting instantiations, the harness\n"
    "floor (and the null algorithm) and the repetitions' spread.\n\n"
    "  --quick            CI: pools of 4096 pairs, the CI corpus, 3 repetitions, short runs\n"
    "  --algo NAME...     algorithms to time; default all but the\n"
    "                     x86-64-v3/FMA builds (NAME@v3fma), which run when named. The\n"
    "                     reference and the floors are always included\n"
    "  --level L...       overlap, relation or segment; default all\n"
    "  --mode M           how pairs reach the test, an axis of every benchmark:\n"
    "                       call   one pair per out-of-line call through a pointer, as a BVH\n"
    "                              traversal calls its narrow-phase test (a C-ABI plug-in: its\n"
    "                              batch function with n = 1); the default: it compares every\n"
    "                              test on the same terms\n"
    "                       batch  the pool in batches of 256 through the batch entry, where a\n"
    "                              SIMD test (exact) decides several pairs per instruction\n"
    "                       both   each, side by side (the main job, scripts/run)\n"
    "                     Stages are timed in batch mode whatever the mode. The floors are timed\n"
    "                     in every mode, and their share is given per test and mode\n"
    "  --isa NAME         scalar, sse2, avx2, avx512 (neon on aarch64): every lane algorithm\n"
    "                     (exact, guigue03-lanes, moller97-lanes) runs on at\n"
    "                     most NAME, to show the times on an older CPU; refused when this\n"
    "                     machine lacks NAME. Sets TRITRI_ISA (tritri/isa.hpp), which they read;\n"
    "                     the JSON records the ISA used, the machine's and the CPU model\n"
    "  --workload W...    ratio, ratio:R, type, type:T, family, family:F, stage, size, size:N,\n"
    "                     scene, scene:NAME, paper, paper:P; default ratio, type, family, stage\n"
    "  --reference NAME   every time is also given relative to NAME's overlap level (or its\n"
    "                     first level) on the same pool, in the same run (default moller97);\n"
    "                     the JSON records it and each result's 'relative_to_reference'\n"
    "  --filter REGEX     time only the benchmarks whose name REGEX matches (POSIX extended,\n"
    "                     anywhere in the name, as Google Benchmark reads it; a leading '-'\n"
    "                     times those it does not match), e.g. 'ratio:|/call$' for the ratio\n"
    "                     pools in every mode and the rest in call mode\n"
    "  --pool N           pairs per pool (default 65536)\n"
    "  --seed S           seed of the pools (default 20240601); recorded in the JSON\n"
    "  --repetitions N    repetitions per benchmark, median reported (default 9)\n"
    "  --min-time SEC     minimum time per repetition (default 0.1)\n"
    "  --no-interleave    run the repetitions of a benchmark back to back\n"
    "  --no-ops           skip the operation counts\n"
    "  --json OUT         write Google Benchmark's JSON with tritri's context keys and a\n"
    "                     'tritri' section (reference, pools, medians, ratios, operation\n"
    "                     counts); default tritri-bench.json; '-' for none\n"
    "  --cases FILE...    case files for the family workloads, instead of the\n"
    "                     corpus generator's families\n"
    "  --float            also time each algorithm's float instantiation, as NAME@float beside\n"
    "                     it (each pair rounded to float inside the call, as tritri check\n"
    "                     --float answers); algorithms without one are named and left out;\n"
    "                     null@float, timed too, is the cost of that rounding alone\n"
    "  --authors-code PATH  a jgt-code checkout: paper:shen03 reads Shen's data files from it\n"
    "  --list             build the pools, list the benchmarks' names and exit\n"
    "  --cache DIR        keep the labelled pools in DIR and reuse them on the next run with\n"
    "                     the same workloads, seed, pool size, cases, generator and oracle\n"
    "                     (default $XDG_CACHE_HOME/tritri, else ~/.cache/tritri); with them\n"
    "                     each algorithm's check on each pool, reused while the code loaded\n"
    "                     (tritri, its libraries, the plug-ins) is the same file for file.\n"
    "                     An entry that is stale or corrupt is rebuilt, never trusted\n"
    "  --no-cache         build the pools and check afresh, and keep nothing\n\n"
    "  --plugin LIB...    also time the algorithms in shared libraries LIB (tritri/plugin.h)\n"
    "  --timeout S        when each algorithm is first checked on a pool (in a child\n"
    "                     process), a pair that makes no progress for S seconds is a timeout\n"
    "                     (default ";
// kHelp continues, after --timeout's default (IsolationOptions, harness/run/isolation.hpp):
constexpr const char* kHelpAfterTimeout =
    "); an algorithm that crashes or hangs on a pool is\n"
    "                     reported with the pair, paste-ready, and not timed on that pool\n"
    "  --no-isolation     check in this process (a crash ends the run)\n\n"
    "  --exec COMMAND     a process plug-in (harness/run/process_plugin.hpp); name it in --algo\n"
    "                     (--exec-name NAME names it). One that offers 'timing' in its\n"
    "                     greeting is handed each pool once and times its own loop over it in\n"
    "                     its own runtime: its answers are checked, its times reported apart,\n"
    "                     'timed in-process by the plug-in' (JSON: tritri.self_timed). One that\n"
    "                     does not is checked on every pool and reported, not timed (its\n"
    "                     answers cross a pipe). Registered process peers (three-mesh-bvh,\n"
    "                     fast-tri-tri, rapier) are timed the same way.\n\n"
    "Exit status: 0, 1 if a benchmark reported an error, 2 on bad arguments (an unknown\n"
    "workload or reference among them).\n\n";

// --isa NAME: asks every lane algorithm for NAME, before any of them is first used (tritri/isa.hpp).
void request_isa(const std::optional<std::string>& name) {
  if (!name) return;
  const auto isa = parse_isa(*name);
  if (!isa) throw UsageError("unknown --isa '" + *name + "' (scalar, sse2, avx2, avx512, neon)");
  if (!isa_runs_here(*isa))
    throw UsageError("--isa " + *name + ": this machine (" + bench::cpu_model() + ") runs at most " +
                     std::string(to_string(machine_isa())));
  setenv(kIsaVariable, name->c_str(), 1);
}

// The options the command line asks for, checked.
bench::Options options_from(const Args& args) {
  bench::Options options = args.flag("--quick") ? bench::quick_options() : bench::Options{};
  options.isolation = isolation_options(args);
  if (const auto names = args.values("--algo"); !names.empty()) options.algorithms = select_algorithms(names);
  if (args.flag("--float")) {
    options.algorithms = float_instantiations(options.algorithms.empty() ? select_algorithms({}) : options.algorithms,
                                              true, "tritri bench --float");
    // The float entries round each pair inside the call: null@float times that rounding alone.
    const bool has = std::any_of(options.algorithms.begin(), options.algorithms.end(),
                                 [](const Algorithm* a) { return a->name == "null@float"; });
    if (!has && registry().find("null")) options.algorithms.push_back(select_algorithms({"null@float"}).front());
  }
  options.authors_code = args.value("--authors-code").value_or("");
  for (const auto& v : args.values("--level")) {
    const auto level = parse_level(v);
    if (!level) throw UsageError("unknown level '" + v + "' (overlap, relation, segment)");
    options.levels.push_back(*level);
  }
  options.workloads = args.values("--workload");
  if (auto m = args.value("--mode")) {
    if (*m == "both") options.modes = {bench::Mode::call, bench::Mode::batch};
    else if (auto mode = bench::parse_mode(*m)) options.modes = {*mode};
    else throw UsageError("unknown --mode '" + *m + "' (call, batch, both)");
  }
  options.reference = args.value("--reference").value_or(options.reference);
  options.filter = args.value("--filter").value_or("");
  options.pool_size = args.count("--pool", options.pool_size);
  if (options.pool_size == 0) throw UsageError("--pool must be at least 1");
  options.seed = args.seed("--seed", options.seed);
  options.repetitions = static_cast<int>(args.count("--repetitions", static_cast<std::size_t>(options.repetitions)));
  if (options.repetitions < 1) throw UsageError("--repetitions must be at least 1");
  options.min_time = args.seconds("--min-time").value_or(options.min_time);
  options.interleave = !args.flag("--no-interleave");
  options.count_operations = !args.flag("--no-ops");
  options.list_only = args.flag("--list");
  options.cache.enabled = !args.flag("--no-cache");
  options.cache.directory = args.value("--cache").value_or("");
  const std::string json = args.value("--json").value_or("tritri-bench.json");
  options.json_path = json == "-" ? "" : json;
  const auto case_files = args.values("--cases");
  if (!case_files.empty()) {
    options.family_corpus = identify_corpus(case_files);
    options.read_family_cases = [case_files] { return load_cases(case_files); };
  }
  return options;
}

}  // namespace

int cmd_bench(int argc, char** argv) {
  Args args(argc, argv,
            merged({.valued = {"--mode", "--isa", "--filter", "--pool", "--seed", "--repetitions", "--min-time", "--json", "--reference",
                               "--cache", "--authors-code"},
                    .lists = {"--algo", "--level", "--workload", "--cases"},
                    .flags = {"--quick", "--no-interleave", "--no-ops", "--list", "--no-cache", "--float"},
                    .operands = false},
                   kRunOptions));
  if (args.help()) {
    std::cout << kHelp << format_double(IsolationOptions{}.stall_seconds) << kHelpAfterTimeout << kListsHelp;
    return kOk;
  }
  if (!args.positional().empty()) throw UsageError("unexpected argument '" + args.positional().front() + "'");

  request_isa(args.value("--isa"));
  load_external_algorithms(args);
  const bench::Options options = options_from(args);
  try {
    return bench::run(options, std::cout);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

}  // namespace tritri::cli
