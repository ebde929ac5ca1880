// The exit statuses (kExitStatusHelp): what a command returns, 2 for the user's input (every
// InputError: a usage error, a bad case file), 3 with "a bug in tritri" and the command line for
// anything else, such as the oracle contradicting itself (a std::logic_error).
#include "harness/cli/args.hpp"
#include "cases/casefile.hpp"
#include "harness/cli/commands.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace tritri::cli;

struct Ran {
  int status;
  std::string err;
};

Ran run(int (*body)(int, char**), std::vector<std::string> words = {}) {
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  std::ostringstream err;
  const int status = run_command({"fake", "a command for this test", body}, static_cast<int>(argv.size()),
                                 argv.data(), err);
  return {status, err.str()};
}

TEST(ExitStatus, WhatTheCommandReturnsIsTheStatus) {
  EXPECT_EQ(run([](int, char**) { return kOk; }).status, 0);
  EXPECT_EQ(run([](int, char**) { return kFindings; }).status, 1);
}

TEST(ExitStatus, TheUsersArgumentsOrInputAreTwo) {
  Ran r = run([](int, char**) -> int { throw UsageError("unknown option '--bogus'"); });
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "tritri fake: unknown option '--bogus'\n(see 'tritri fake --help')\n");
  r = run([](int, char**) -> int { throw tritri::CaseFileError("x.cases", 3, "coordinate 18 is NaN"); });
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "tritri fake: x.cases:3: coordinate 18 is NaN\n");
  r = run([](int, char**) -> int { throw tritri::InputError("plug-in 'x.so': declares no name"); });
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.find("bug"), std::string::npos) << r.err;
}

TEST(ExitStatus, AnythingElseIsThreeAndSaysItIsABugWithTheCommandLine) {
  Ran r = run([](int, char**) -> int { throw std::logic_error("oracle: CGAL's do_intersect and intersection disagree"); },
              {"--algo", "moller97", "cases/builtin.cases"});
  EXPECT_EQ(r.status, 3);
  EXPECT_EQ(r.err,
            "tritri fake: internal error: oracle: CGAL's do_intersect and intersection disagree — this is a bug in "
            "tritri, please report it\n  while running: tritri fake --algo moller97 cases/builtin.cases\n");
  r = run([](int, char**) -> int { throw std::runtime_error("disjoint triangles at distance zero"); });
  EXPECT_EQ(r.status, 3);
  r = run([](int, char**) -> int { throw 42; });
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("internal error: an exception that is not a std::exception"), std::string::npos) << r.err;
}

TEST(ExitStatus, TheHelpListsEveryStatus) {
  for (const char* status : {"0 ok", "1 findings", "2 bad arguments or\ninput", "3 an internal error"})
    EXPECT_NE(std::string(kExitStatusHelp).find(status), std::string::npos) << status;
}

}  // namespace
