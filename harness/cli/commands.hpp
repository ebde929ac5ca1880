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

int run_list(int argc, char** argv);
int run_label(int argc, char** argv);
int run_answer(int argc, char** argv);
int run_check(int argc, char** argv);
int run_show(int argc, char** argv);

// Algorithms named by --algo (repeatable, or comma-separated); all when none is named. Throws
// UsageError naming an unknown algorithm and listing the known ones.
std::vector<const Algorithm*> select_algorithms(const std::vector<std::string>& names);

}  // namespace tritri::cli

#include "casefile.hpp"

namespace tritri::cli {

// Reads every file; case names must be unique across them (baselines and `show` key on names).
std::vector<Case> load_cases(const std::vector<std::string>& files);

std::string segment_text(const SegmentAnswer& s);  // "-", "empty", "x,y,z", "x,y,z;x,y,z", ...
std::string vec_text(const Vec3<double>& v);

}  // namespace tritri::cli
