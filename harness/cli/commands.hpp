// The `tritri` subcommands. Command NAME lives in harness/cli/cmd_NAME.cpp (which CMake picks up
// by its name), defines `int cmd_NAME(int argc, char** argv)` and is listed once, in
// TRITRI_CLI_COMMANDS below: adding a command is that file and one line there.
#pragma once

#include "tritri/algorithm.hpp"

#include <iosfwd>
#include <string>
#include <vector>

// X(NAME, summary), in the order `tritri --help` lists them. argv excludes the command name; the
// entry point returns the exit status.
#define TRITRI_CLI_COMMANDS(X)                                                                                \
  X(list, "every algorithm with its levels, boundary semantics, tolerance and citation")                      \
  X(label, "the oracle's record for every case in case files (TSV)")                                          \
  X(answer, "one algorithm's answers for every case in case files (TSV)")                                     \
  X(check, "algorithms against the oracle: errors per algorithm and family")                                  \
  X(show, "one case: coordinates, the oracle's record and every algorithm's answer")                          \
  X(corpus, "generate and label the singular-configuration corpus (case files per family)")                   \
  X(bench, "time every algorithm by intersection ratio, type, family and stage (Google Benchmark)")           \
  X(scene, "a scene's candidate pairs (FCL's BVH broad phase on moving meshes) as case files")                \
  X(compare, "what changed between two check or bench results (with a U test for times)")                    \
  X(diff, "where two algorithms answer differently (e.g. a port and its authors' code)")                     \
  X(hunt, "search out an algorithm's failures beyond the corpus and shrink each to a minimal witness")       \
  X(merge, "join the shards of a campaign (check --shard K/N) into the result of one run")

namespace tritri::cli {

struct Command {
  const char* name;
  const char* summary;
  int (*run)(int argc, char** argv);  // argv excludes the command name; returns the exit status
};

// Exit statuses shared by every command.
inline constexpr int kOk = 0;
inline constexpr int kFindings = 1;  // e.g. check: new failures against a baseline
inline constexpr int kUsage = 2;     // the user's arguments or input: InputError (and UsageError)
inline constexpr int kInternal = 3;  // any other exception: a bug in tritri
// What `tritri --help` and the README say about them.
extern const char* const kExitStatusHelp;

// Runs one command, turning what it throws into its exit status and a message on `err`: an
// InputError names the user's mistake (2); anything else is reported as a bug in tritri with the
// command line that met it (3).
int run_command(const Command& command, int argc, char** argv, std::ostream& err);

#define TRITRI_CLI_DECLARE(name, summary) int cmd_##name(int argc, char** argv);
TRITRI_CLI_COMMANDS(TRITRI_CLI_DECLARE)
#undef TRITRI_CLI_DECLARE

// Algorithms named by --algo (Args has split its list); when none is named, all but the
// other builds (NAME@v3fma: run when named, Algorithm::build). NAME@float names NAME's float
// instantiation (float_instantiations below). Throws UsageError naming an unknown algorithm and
// listing the known ones.
std::vector<const Algorithm*> select_algorithms(const std::vector<std::string>& names);

// Each chosen algorithm's float instantiation (Algorithm::on_scalar), named NAME@float, in place
// of it (`beside`: false) or right after it (true). Those with none (FCL, CGAL: libraries called
// on double; plug-ins) are left out, both builds, and named on stderr, after `who` ("tritri
// check --float"). The copies
// live as long as the process, since results keep pointers to them. Throws UsageError when no
// chosen algorithm has one.
std::vector<const Algorithm*> float_instantiations(const std::vector<const Algorithm*>& chosen, bool beside,
                                                   const std::string& who);

}  // namespace tritri::cli

#include "harness/cli/args.hpp"
#include "cases/casefile.hpp"
#include "harness/check/check.hpp"
#include "harness/run/isolation.hpp"

#include <optional>
#include <set>

namespace tritri::cli {

// Reads every file; case names must be unique across them (baselines and `show` key on names).
std::vector<Case> load_cases(const std::vector<std::string>& files);

std::string segment_text(const SegmentAnswer& s);  // "-", "empty", "x,y,z", "x,y,z;x,y,z", ...

// The options of every command that runs algorithms: external algorithms (--plugin LIB...,
// --exec COMMAND with --exec-name NAME) and how they are run (--timeout S, --no-isolation).
extern const OptionSpec kRunOptions;
extern const std::string kRunOptionsHelp;
// Loads the --plugin libraries and starts the --exec commands, adding them to the registry.
void load_external_algorithms(const Args& args);
IsolationOptions isolation_options(const Args& args);
std::string vec_text(const Vec3<double>& v);
// When `algorithm`'s run stopped at the fault limit (--max-faults): one line on `out` naming it,
// its first faulting cases and how many were not run, and true (the command then exits 1).
bool report_stopped(std::ostream& out, const Algorithm& algorithm, const std::vector<Case>& cases,
                    const std::vector<Answers>& answers);

// --shard K/N (check, label, answer): part K of N of the input, cases [first, end) of total
// (cases/case_stream.hpp, shard_range); counts the cases of the files to find its range.
struct Shard {
  std::size_t index = 0, count = 1;
  CaseRange range;
  std::size_t total = 0;
};
extern const char* const kShardHelp;
std::optional<Shard> shard_option(const Args& args);
// --shard K/N parsed and checked (index and count only), for commands whose parts are not cases.
std::optional<Shard> shard_spec(const Args& args);

}  // namespace tritri::cli
