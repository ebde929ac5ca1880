#include "harness/cli/args.hpp"
#include "cases/casefile.hpp"
#include "harness/cli/commands.hpp"

#include <iomanip>
#include <iostream>

namespace tritri::cli {

int cmd_list(int argc, char** argv) {
  Args args(argc, argv, merged({.flags = {"--tsv"}, .operands = false}, kRunOptions));
  if (args.help()) {
    std::cout << "usage: tritri list [--tsv] [--plugin LIB...] [--exec COMMAND]...\n\n"
                 "Every built-in algorithm: the answer levels it serves (overlap, relation, segment),\n"
                 "whether touching counts (closed) or not (open), its tolerance (value and the\n"
                 "quantity it is compared with, or none), whether it accepts zero-area triangles,\n"
                 "and its citation. --tsv prints one tab-separated row per algorithm. --plugin LIB and\n"
                 "--exec COMMAND add external algorithms, as for check.\n\n"
              << kListsHelp;
    return kOk;
  }
  if (!args.positional().empty()) throw UsageError("list takes no files");
  load_external_algorithms(args);
  auto tolerance_text = [](const Algorithm& a) {
    if (a.tolerance.none()) return std::string("none");
    return format_double(a.tolerance.value) + (a.tolerance.relative ? " relative" : " absolute") +
           " on " + a.tolerance.quantity;
  };
  const auto& all = registry().all();
  if (args.flag("--tsv")) {
    std::cout << "name\tlevels\tboundary\ttolerance\tdegenerate\tsummary\tcitation\tfolder\n";
    for (const auto& a : all)
      std::cout << a.name << '\t' << a.levels() << '\t' << (a.boundary == Boundary::closed ? "closed" : "open")
                << '\t' << tolerance_text(a) << '\t' << (a.accepts_degenerate ? "accepted" : "rejected")
                << '\t' << a.summary << '\t' << a.citation << '\t' << a.folder << '\n';
    return kOk;
  }
  std::size_t width = 4;
  for (const auto& a : all) width = std::max(width, a.name.size());
  for (const auto& a : all) {
    std::cout << std::left << std::setw(static_cast<int>(width)) << a.name << "  " << a.summary << '\n'
              << std::string(width + 2, ' ') << "levels: " << a.levels()
              << "; boundary: " << (a.boundary == Boundary::closed ? "closed" : "open")
              << "; degenerate triangles: " << (a.accepts_degenerate ? "accepted" : "not accepted") << '\n'
              << std::string(width + 2, ' ') << "tolerance: " << tolerance_text(a) << '\n'
              << std::string(width + 2, ' ') << a.citation << "\n\n";
  }
  return kOk;
}

}  // namespace tritri::cli
