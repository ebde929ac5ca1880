#include "harness/cli/args.hpp"
#include "harness/check/check.hpp"
#include "harness/cli/commands.hpp"

#include <cmath>
#include <iostream>

namespace tritri::cli {

int cmd_label(int argc, char** argv) {
  Args args(argc, argv, {.valued = {"--shard"}});
  if (args.help()) {
    std::cout << "usage: tritri label FILE...\n\n"
                 "The exact oracle's record for every case, as TSV with a header line:\n"
                 "  name overlap relation dim coplanar separation stage\n"
                 "overlap, coplanar: 0/1. relation: disjoint, cross, touch-point, touch-segment,\n"
                 "coplanar-overlap, coplanar-disjoint, coplanar-point, coplanar-segment, parallel, or\n"
                 "degenerate (a triangle of zero area). dim: none/point/segment/area. separation: the\n"
                 "distance between the triangles (0 when they meet; '-' when not computed). stage:\n"
                 "where a plane-rejecting test decides the pair: plane2, plane1, coplanar, interval.\n"
                 "The cases are read and labelled a chunk at a time (memory does not grow with them).\n\n"
              << kShardHelp;
    return kOk;
  }
  if (args.positional().empty()) throw UsageError("no case file given (the built-in cases are cases/builtin.cases)");
  const auto shard = shard_option(args);
  CaseStream stream(args.positional(), shard ? shard->range : CaseRange{});
  std::vector<Case> cases;
  if (!shard || shard->index == 0) std::cout << "name\toverlap\trelation\tdim\tcoplanar\tseparation\tstage\n";
  while (stream.next(cases, 1 << 15)) {
    const auto records = label_cases(cases);
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const auto& r = records[i];
      std::cout << cases[i].name << '\t' << r.overlap << '\t' << to_string(r.relation) << '\t'
                << to_string(r.dimension) << '\t' << r.coplanar << '\t'
                << (std::isnan(r.separation) ? std::string("-") : format_double(r.separation)) << '\t'
                << to_string(r.stage) << '\n';
    }
  }
  return kOk;
}

}  // namespace tritri::cli
