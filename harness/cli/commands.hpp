// The `tritri` subcommands. Each lives in its own file and is listed once in main.cpp.
#pragma once

#include "tritri/algorithm.hpp"

#include <string>
#include <vector>

namespace tritri::cli {

struct Command {
  const char* name;
  const char* summary;
  int (*run)(int argc, char** argv);  // argv excludes the command name; returns the exit status
};

// Exit statuses shared by every command.
inline constexpr int kOk = 0;
inline constexpr int kFindings = 1;  // e.g. check: new failures against a baseline
inline constexpr int kUsage = 2;     // bad arguments, unreadable or malformed input

int cmd_list(int argc, char** argv);
int cmd_label(int argc, char** argv);
int cmd_answer(int argc, char** argv);
int cmd_check(int argc, char** argv);
int cmd_show(int argc, char** argv);
int cmd_compare(int argc, char** argv);
int cmd_diff(int argc, char** argv);  // harness/cli/cmd_diff.cpp: two algorithms' answers, case by case
int cmd_corpus(int argc, char** argv);
int cmd_bench(int argc, char** argv);  // harness/cli/cmd_bench.cpp, harness/bench/
int cmd_scene(int argc, char** argv);  // harness/cli/cmd_scene.cpp, cases/scenes/

// Algorithms named by --algo (repeatable, or comma-separated); when none is named, all but the
// build variants (NAME@v3fma: named explicitly, Algorithm::build). Throws
// UsageError naming an unknown algorithm and listing the known ones.
std::vector<const Algorithm*> select_algorithms(const std::vector<std::string>& names);

}  // namespace tritri::cli

#include "harness/cli/args.hpp"
#include "cases/casefile.hpp"
#include "harness/run/isolation.hpp"

#include <set>

namespace tritri::cli {

// Reads every file; case names must be unique across them (baselines and `show` key on names).
std::vector<Case> load_cases(const std::vector<std::string>& files);

std::string segment_text(const SegmentAnswer& s);  // "-", "empty", "x,y,z", "x,y,z;x,y,z", ...

// The options of every command that runs algorithms: external algorithms (--plugin LIB,
// --exec COMMAND with --exec-name NAME) and how they are run (--timeout S, --no-isolation).
extern const std::set<std::string> kRunValuedOptions;
extern const std::set<std::string> kRunFlags;
extern const char* const kRunOptionsHelp;
// Loads the --plugin libraries and starts the --exec commands, adding them to the registry.
void load_external_algorithms(const Args& args);
IsolationOptions isolation_options(const Args& args);
inline std::set<std::string> with(std::set<std::string> a, const std::set<std::string>& b) {
  a.insert(b.begin(), b.end());
  return a;
}
std::string vec_text(const Vec3<double>& v);

}  // namespace tritri::cli
