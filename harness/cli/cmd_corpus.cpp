#include "harness/cli/args.hpp"
#include "cases/util/progress.hpp"
#include "harness/check/check.hpp"
#include "harness/cli/commands.hpp"
#include "cases/generator/corpus.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace tritri::cli {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void print_help() {
  std::cout << "usage: tritri corpus [--quick] [--families NAME...] [--per-family N] [--seed S]\n"
               "                     [--out DIR]\n\n"
               "Generates the singular-configuration corpus, labels every case with the exact oracle,\n"
               "writes one case file per family to DIR/<family>.cases and prints the number of cases\n"
               "per family x oracle relation.\n\n"
               "Each family builds base cases exactly on small-integer or dyadic grids, cycling through\n"
               "its configurations; each base case then gets the transformation sub-suites, named by\n"
               "the subsuite= label: symmetry (vertex orders x argument order; 72 per base case by\n"
               "default), scale (by 2^k, exact), translate (by 2^k offsets, exact), rotate (random,\n"
               "rounded to double) and perturb (T2's first vertex moved by +-delta x the pair's size,\n"
               "delta = 1e-16, 1e-14, ..., 1e-2). The random family gets only symmetry and scale.\n"
               "Exact cases carry expect=<relation>; all carry family=, config=, subsuite=,\n"
               "transform= and oracle=<relation>.\n\n"
               "  --quick            the CI corpus: 10 base cases per family, 6 of the 72 symmetry\n"
               "                     variants, one scale, translation and rotation each (about 4,000)\n"
               "                     instead of 144 base cases with all variants (about 214,000)\n"
               "  --families NAME... only these families; the 16 are:\n";
  for (const auto& f : corpus::families()) std::cout << "                       " << f.name << " - " << f.summary << '\n';
  std::cout << "  --per-family N     base cases per family (default 144, or 10 with --quick)\n"
               "  --seed S           random seed (default 1): the same seed gives the same bytes\n"
               "  --out DIR          where to write (default: corpus, or corpus-quick with --quick)\n\n"
               "Progress goes to stderr on a terminal. Exit status: 0; 1 if the oracle contradicts an\n"
               "expect= label (a generator bug: the cases are still written); 2 on bad arguments.\n\n"
            << kListsHelp;
}

}  // namespace

int cmd_corpus(int argc, char** argv) {
  Args args(argc, argv,
            {.valued = {"--per-family", "--seed", "--out"}, .lists = {"--families"}, .flags = {"--quick"}, .operands = false});
  if (args.help()) {
    print_help();
    return kOk;
  }
  if (!args.positional().empty()) throw UsageError("unexpected argument '" + args.positional()[0] + "'");
  const bool quick = args.flag("--quick");
  const std::uint64_t seed = args.seed("--seed", corpus::CorpusOptions{}.seed);
  corpus::CorpusOptions options = quick ? corpus::quick_options(seed) : corpus::default_options(seed);
  options.per_family = args.count("--per-family", options.per_family);
  options.families = args.values("--families");
  const std::string dir = args.value("--out").value_or(quick ? "corpus-quick" : "corpus");

  std::size_t planned = 0;
  try {
    planned = corpus::planned_size(options);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const bool terminal = isatty(fileno(stderr)) == 1;
  if (terminal) std::fprintf(stderr, "generating about %zu cases...\n", planned);
  const auto start = std::chrono::steady_clock::now();
  std::vector<Case> cases = corpus::generate_corpus(options);
  const double generated = seconds_since(start);
  Progress progress("labelling", cases.size());
  const auto records = label_cases(cases, progress.callback());
  progress.finish();
  const double labelled = seconds_since(start) - generated;
  corpus::attach_oracle_labels(cases, records);

  std::ostringstream provenance;
  provenance << "tritri corpus" << (quick ? " --quick" : "") << " --seed " << seed << " --per-family "
             << options.per_family;
  if (!options.families.empty()) {
    provenance << " --families ";
    for (std::size_t i = 0; i < options.families.size(); ++i) provenance << (i ? "," : "") << options.families[i];
  }
  const auto paths = corpus::write_corpus(dir, cases, provenance.str());

  corpus::print_counts(std::cout, cases, records);
  std::size_t contradicted = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto expect = cases[i].label("expect");
    if (!expect || *expect == to_string(records[i].relation)) continue;
    if (contradicted++ < 10)
      std::cout << "oracle contradicts the construction: " << cases[i].name << " expect=" << *expect
                << " oracle=" << to_string(records[i].relation) << '\n';
  }
  std::cout << '\n'
            << cases.size() << " cases in " << paths.size() << " files under " << dir << "/ (generated in "
            << generated << " s, labelled in " << labelled << " s)\n";
  if (contradicted) std::cout << contradicted << " cases where the oracle contradicts expect=\n";
  return contradicted ? kFindings : kOk;
}

}  // namespace tritri::cli
