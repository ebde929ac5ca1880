#include "args.hpp"
#include "check.hpp"
#include "commands.hpp"

#include <iostream>

namespace tritri::cli {
namespace {

std::string relation_text(const Algorithm& a, const Answers& ans) {
  if (!a.relation) return "-";
  if (ans.declined) return "unsupported";
  if (ans.relation.relation == Relation::unknown) return "dim:" + std::string(to_string(ans.relation.dimension));
  return std::string(to_string(ans.relation.relation));
}

}  // namespace

int run_answer(int argc, char** argv) {
  Args args(argc, argv, {"--algo"}, {});
  if (args.help()) {
    std::cout << "usage: tritri answer --algo NAME FILE...\n\n"
                 "One algorithm's answers for every case, as TSV with a header line:\n"
                 "  name overlap relation segment\n"
                 "overlap: 0/1 or 'unsupported'; relation: the relation vocabulary (see 'tritri label\n"
                 "--help'), or dim:<dimension> for an algorithm that gives only the dimension; segment:\n"
                 "x,y,z for a point, x,y,z;x,y,z for a segment, or empty/area/coplanar/unsupported.\n"
                 "'-' marks a level the algorithm does not answer. A degenerate case that the\n"
                 "algorithm does not accept is answered 'unsupported' without calling it.\n";
    return kOk;
  }
  const auto names = args.values("--algo");
  if (names.size() != 1) throw UsageError("answer needs exactly one --algo NAME");
  const auto chosen = select_algorithms(names);
  if (chosen.size() != 1) throw UsageError("answer needs exactly one algorithm");
  const Algorithm& algorithm = *chosen.front();
  const auto cases = load_cases(args.positional());
  const auto answers = answer_cases(algorithm, cases);
  std::cout << "name\toverlap\trelation\tsegment\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Answers& a = answers[i];
    std::cout << cases[i].name << '\t'
              << (!algorithm.overlap ? "-" : a.declined ? "unsupported" : to_string(a.overlap)) << '\t'
              << relation_text(algorithm, a) << '\t'
              << (!algorithm.segment ? "-" : a.declined ? "unsupported" : segment_text(a.segment)) << '\n';
  }
  return kOk;
}

}  // namespace tritri::cli
