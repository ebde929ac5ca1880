// tritri: the reference test-suite and benchmark harness for 3-D triangle–triangle tests.
#include "harness/cli/args.hpp"
#include "harness/cli/commands.hpp"

#include <cstring>
#include <deque>
#include <string_view>
#include <iostream>

namespace tritri::cli {
namespace {

constexpr std::string_view kFloatSuffix = "@float";  // as Algorithm::on_scalar names them

#define TRITRI_CLI_ROW(name, summary) {#name, summary, cmd_##name},
constexpr Command kCommands[] = {TRITRI_CLI_COMMANDS(TRITRI_CLI_ROW)};
#undef TRITRI_CLI_ROW

void print_usage(std::ostream& out) {
  out << "usage: tritri <command> [options] [files]\n\n"
         "tritri checks 3-D triangle-triangle intersection tests against an exact oracle (CGAL)\n"
         "and times them. Commands:\n";
  for (const auto& c : kCommands) out << "  " << c.name << std::string(10 - std::strlen(c.name), ' ') << c.summary << '\n';
  out << "\n'tritri <command> --help' describes a command.\n" << kExitStatusHelp;
}

}  // namespace

std::vector<const Algorithm*> select_algorithms(const std::vector<std::string>& names) {
  std::vector<const Algorithm*> chosen;
  if (names.empty()) {
    for (const auto& a : registry().all())
      if (a.build.empty()) chosen.push_back(&a);
    return chosen;
  }
  for (const auto& name : names) {
    const Algorithm* a = registry().find(name);
    if (!a && name.ends_with(kFloatSuffix) && registry().find(name.substr(0, name.size() - kFloatSuffix.size())))
      a = float_instantiations({registry().find(name.substr(0, name.size() - kFloatSuffix.size()))}, false, name)[0];
    if (!a) {
      std::string known;
      for (const auto& k : registry().all()) known += (known.empty() ? "" : ", ") + k.name;
      throw UsageError("unknown algorithm '" + name + "' (known: " + known + ")");
    }
    if (std::find(chosen.begin(), chosen.end(), a) == chosen.end()) chosen.push_back(a);
  }
  return chosen;
}

std::vector<const Algorithm*> float_instantiations(const std::vector<const Algorithm*>& chosen, bool beside,
                                                   const std::string& who) {
  static std::deque<Algorithm> copies;
  std::vector<const Algorithm*> out;
  std::string skipped;
  for (const Algorithm* a : chosen) {
    auto f = a->on_scalar(Scalar::float_);
    if (!f) {
      skipped += (skipped.empty() ? "" : ", ") + a->name;
      continue;
    }
    if (beside) out.push_back(a);
    out.push_back(&copies.emplace_back(std::move(*f)));
  }
  if (!skipped.empty()) std::cerr << who << ": no float instantiation, left out: " << skipped << '\n';
  if (out.empty()) throw UsageError(who + ": none of the chosen algorithms has a float instantiation");
  return out;
}

}  // namespace tritri::cli

int main(int argc, char** argv) {
  using namespace tritri::cli;
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "help") == 0) {
    print_usage(argc < 2 ? std::cerr : std::cout);
    return argc < 2 ? kUsage : kOk;
  }
  for (const auto& command : kCommands) {
    if (std::strcmp(argv[1], command.name) != 0) continue;
    return run_command(command, argc - 2, argv + 2, std::cerr);
  }
  std::cerr << "tritri: unknown command '" << argv[1] << "'\n\n";
  print_usage(std::cerr);
  return kUsage;
}
