#include "harness/cli/args.hpp"
#include "cases/util/progress.hpp"
#include "harness/check/check.hpp"
#include "harness/cli/commands.hpp"

#include <cmath>
#include <iostream>

namespace tritri::cli {

int cmd_label(int argc, char** argv) {
  Args args(argc, argv, {});
  if (args.help()) {
    std::cout << "usage: tritri label FILE...\n\n"
                 "The exact oracle's record for every case, as TSV with a header line:\n"
                 "  name overlap relation dim coplanar separation stage\n"
                 "overlap, coplanar: 0/1. relation: disjoint, cross, touch-point, touch-segment,\n"
                 "coplanar-overlap, coplanar-disjoint, coplanar-point, coplanar-segment, parallel, or\n"
                 "degenerate (a triangle of zero area). dim: none/point/segment/area. separation: the\n"
                 "distance between the triangles (0 when they meet; '-' when not computed). stage:\n"
                 "where a plane-rejecting test decides the pair: plane2, plane1, coplanar, interval.\n";
    return kOk;
  }
  const auto cases = load_cases(args.positional());
  Progress progress("labelling", cases.size());
  const auto records = label_cases(cases, progress.callback());
  progress.finish();
  std::cout << "name\toverlap\trelation\tdim\tcoplanar\tseparation\tstage\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto& r = records[i];
    std::cout << cases[i].name << '\t' << r.overlap << '\t' << to_string(r.relation) << '\t'
              << to_string(r.dimension) << '\t' << r.coplanar << '\t'
              << (std::isnan(r.separation) ? std::string("-") : format_double(r.separation)) << '\t'
              << to_string(r.stage) << '\n';
  }
  return kOk;
}

}  // namespace tritri::cli
