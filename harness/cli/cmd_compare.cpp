#include "harness/cli/args.hpp"
#include "harness/cli/commands.hpp"
#include "harness/check/compare.hpp"

#include <cstdlib>
#include <iostream>

namespace tritri::cli {

int cmd_compare(int argc, char** argv) {
  Args args(argc, argv, {.valued = {"--alpha", "--min-change"}});
  if (args.help()) {
    std::cout << "usage: tritri compare [--alpha P] [--min-change C] A.json B.json\n\n"
                 "What changed from run A to run B.\n"
                 "  Two 'tritri check --json' results: per algorithm x family, every error count that\n"
                 "  changed (FP, FN, relation, unsupported, crash, timeout), and rows only in one run.\n"
                 "  Two 'tritri bench' results: per benchmark, the median time per pair in each run,\n"
                 "  their ratio B/A, and a two-sided Mann-Whitney U test over the repetitions (exact for\n"
                 "  small samples without ties). A change counts when it is significant (p < P, default\n"
                 "  0.05) and at least C (default 0.02, i.e. 2%) of A's median: runs minutes apart drift\n"
                 "  by about a percent, which nine repetitions detect but which is not a regression.\n"
                 "  Then the geometric mean of the ratios.\n\n"
                 "Exit status: 0; 1 if B is worse (a higher error count, or a significant slowdown);\n"
                 "2 on bad arguments or input.\n";
    return kOk;
  }
  if (args.positional().size() != 2) throw UsageError("compare takes exactly two result files");
  CompareOptions options;
  if (auto alpha = args.value("--alpha")) {
    char* end = nullptr;
    options.alpha = std::strtod(alpha->c_str(), &end);
    if (*end != '\0' || !(options.alpha > 0 && options.alpha < 1))
      throw UsageError("--alpha takes a probability between 0 and 1, not '" + *alpha + "'");
  }
  if (auto change = args.value("--min-change")) {
    char* end = nullptr;
    options.min_change = std::strtod(change->c_str(), &end);
    if (*end != '\0' || !(options.min_change >= 0 && options.min_change < 1))
      throw UsageError("--min-change takes a fraction between 0 and 1, not '" + *change + "'");
  }
  const bool worse = print_comparison(std::cout, args.positional()[0], args.positional()[1], options);
  return worse ? kFindings : kOk;
}

}  // namespace tritri::cli
