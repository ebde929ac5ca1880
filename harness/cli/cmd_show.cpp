#include "harness/cli/args.hpp"
#include "harness/check/check.hpp"
#include "harness/check/judge.hpp"
#include "harness/cli/commands.hpp"

#include <cmath>
#include <iomanip>
#include <iostream>

namespace tritri::cli {

int cmd_show(int argc, char** argv) {
  Args args(argc, argv, merged({.lists = {"--algo"}}, kRunOptions));
  if (args.help()) {
    std::cout << "usage: tritri show NAME FILE... [--algo NAME...] [--plugin LIB...] [--exec COMMAND]...\n\n"
                 "One case in full: its coordinates (shortest exact decimal and hex float), its labels,\n"
                 "the oracle's record (with the exact intersection rounded to double) and the answers\n"
                 "of every algorithm (or those named with --algo).\n\n"
              << kRunOptionsHelp << '\n' << kListsHelp;
    return kOk;
  }
  if (args.positional().size() < 2) throw UsageError("show needs a case name and at least one file");
  const std::string wanted = args.positional().front();
  const std::vector<std::string> files(args.positional().begin() + 1, args.positional().end());
  load_external_algorithms(args);
  const auto algorithms = select_algorithms(args.values("--algo"));
  std::vector<Case> found;
  for (auto& c : load_cases(files))
    if (c.name == wanted) found.push_back(std::move(c));
  if (found.empty()) throw UsageError("no case named '" + wanted + "' in the given files");
  const Case& c = found.front();

  std::cout << "case " << c.name << "   (" << c.source << ':' << c.line << ")\n";
  const char* names[] = {"T1", "T2"};
  const Triangle* triangles[] = {&c.pair.t1, &c.pair.t2};
  for (int t = 0; t < 2; ++t)
    for (int v = 0; v < 3; ++v)
      std::cout << "  " << names[t] << "." << "abc"[v] << "  " << vec_text((*triangles[t])[v]) << "   ("
                << format_hex((*triangles[t])[v].x()) << ", " << format_hex((*triangles[t])[v].y()) << ", "
                << format_hex((*triangles[t])[v].z()) << ")\n";
  for (const auto& [k, v] : c.labels) std::cout << "  " << k << '=' << v << '\n';

  const OracleRecord r = oracle_label(c.pair);
  std::cout << "oracle (" << oracle_description() << ")\n"
            << "  overlap " << r.overlap << ", relation " << to_string(r.relation) << ", dim "
            << to_string(r.dimension) << ", coplanar " << r.coplanar << ", stage " << to_string(r.stage)
            << ", separation " << (std::isnan(r.separation) ? std::string("-") : format_double(r.separation))
            << '\n';
  for (int i = 0; i < r.point_count; ++i) std::cout << "  intersection point " << vec_text(r.points[i]) << '\n';

  std::cout << "answers\n";
  std::size_t width = 4;
  for (const Algorithm* a : algorithms) width = std::max(width, a->name.size());
  for (const Algorithm* a : algorithms) {
    const Answers ans = answer_cases(*a, found, isolation_options(args)).front();
    std::cout << "  " << std::left << std::setw(static_cast<int>(width)) << a->name;
    if (ans.declined) {
      std::cout << "  unsupported (degenerate input)\n";
      continue;
    }
    if (ans.fate != Fate::ok) {
      std::cout << "  " << to_string(ans.fate) << " (" << ans.fault << ")\n";
      continue;
    }
    if (a->answers(Level::overlap)) {
      const bool wrong = judge_overlap(ans.overlap, truth_of(r)) == Verdict::wrong;
      std::cout << "  overlap " << to_string(ans.overlap) << (wrong ? " (WRONG)" : "");
    }
    if (a->answers(Level::relation)) {
      const bool wrong = judge_relation(ans.relation, truth_of(r)).verdict == Verdict::wrong;
      std::cout << "  relation " << relation_word(ans.relation) << (wrong ? " (WRONG)" : "");
    }
    if (a->answers(Level::segment)) std::cout << "  segment " << segment_text(ans.segment);
    std::cout << '\n';
  }
  return kOk;
}

}  // namespace tritri::cli
