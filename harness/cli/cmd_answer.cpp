#include "harness/cli/args.hpp"
#include "harness/check/check.hpp"
#include "harness/check/judge.hpp"
#include "harness/check/stream.hpp"
#include "harness/cli/commands.hpp"

#include <iostream>

namespace tritri::cli {
namespace {

std::string relation_text(const Algorithm& a, const Answers& ans) {
  if (!a.answers(Level::relation)) return "-";
  if (ans.declined) return "unsupported";
  return relation_word(ans.relation);
}

// The overlap column: the overlap level's answer, else what the relation decides.
std::string overlap_text(const Algorithm& a, const Answers& ans) {
  if (ans.declined && (a.answers(Level::overlap) || a.answers(Level::relation))) return "unsupported";
  if (a.answers(Level::overlap)) return std::string(to_string(ans.overlap));
  if (a.answers(Level::relation)) return std::string(to_string(implied_overlap(ans.relation)));
  return "-";
}

void print_answer(const Algorithm& algorithm, const Case& c, const Answers& a) {
  if (a.fate != Fate::ok) {
    const std::string word = to_string(a.fate);
    std::cout << c.name << '\t' << word << '\t' << word << '\t' << word << '\n';
    return;
  }
  std::cout << c.name << '\t' << overlap_text(algorithm, a) << '\t' << relation_text(algorithm, a) << '\t'
            << (!algorithm.answers(Level::segment) ? "-" : a.declined ? "unsupported" : segment_text(a.segment))
            << '\n';
}

}  // namespace

int cmd_answer(int argc, char** argv) {
  Args args(argc, argv, merged({.valued = {"--shard"}, .lists = {"--algo"}}, kRunOptions));
  if (args.help()) {
    std::cout << "usage: tritri answer --algo NAME [--plugin LIB | --exec COMMAND] FILE...\n\n"
                 "One algorithm's answers for every case, as TSV with a header line:\n"
                 "  name overlap relation segment\n"
                 "overlap: 0/1 or 'unsupported'; for an algorithm that answers only the relation, what\n"
                 "its relation decides (dimension none: 0, any other: 1). relation: the relation\n"
                 "vocabulary (see 'tritri label --help'), or dim:<dimension> for an algorithm that\n"
                 "gives only the dimension. segment:\n"
                 "x,y,z for a point, x,y,z;x,y,z for a segment, or empty/area/coplanar/unsupported.\n"
                 "'-' marks a level the algorithm does not answer. A degenerate case that the\n"
                 "algorithm does not accept is answered 'unsupported' without calling it. A case on\n"
                 "which the algorithm crashed or hung is answered 'crash' or 'timeout' in every column,\n"
                 "and one it did not reach after --max-faults faults 'not-run' (exit status 1).\n"
                 "The cases are read and answered a chunk at a time (memory does not grow with them).\n\n"
              << kShardHelp << kRunOptionsHelp << '\n' << kListsHelp;
    return kOk;
  }
  load_external_algorithms(args);
  const auto names = args.values("--algo");
  if (names.size() != 1) throw UsageError("answer needs exactly one --algo NAME");
  const auto chosen = select_algorithms(names);
  if (chosen.size() != 1) throw UsageError("answer needs exactly one algorithm");
  const Algorithm& algorithm = *chosen.front();
  if (args.positional().empty()) throw UsageError("no case file given (the built-in cases are cases/builtin.cases)");
  const auto shard = shard_option(args);
  CaseStream stream(args.positional(), shard ? shard->range : CaseRange{});
  const IsolationOptions isolation = isolation_options(args);
  RunState run = start_run(algorithm, isolation);
  std::vector<Case> cases;
  if (!shard || shard->index == 0) std::cout << "name\toverlap\trelation\tsegment\n";
  while (stream.next(cases, 1 << 15)) {
    const auto answers = answer_chunk(algorithm, cases, isolation, run);
    for (std::size_t i = 0; i < cases.size(); ++i) print_answer(algorithm, cases[i], answers[i]);
  }
  if (!run.account.not_run) return kOk;
  print_stopped(std::cerr, run.account);
  return kFindings;
}

}  // namespace tritri::cli
