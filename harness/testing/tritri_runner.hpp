// Runs the built tritri binary for tests that exercise it as a user would.
#pragma once

#include <array>
#include <cstdio>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace tritri::testing_support {

struct Outcome {
  int status = -1;  // exit status; -1 if it did not exit normally
  std::string out;  // stdout and stderr together
};

inline Outcome run_tritri(const std::string& arguments) {
  const std::string command = std::string(TRITRI_BINARY_DIR) + "/bin/tritri " + arguments + " 2>&1";
  Outcome run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe)) run.out += buffer.data();
  const int raw = pclose(pipe);
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return run;
}

// The path of the test plug-in NAME built into the build tree (libNAME.so).
inline std::string plugin_library(const std::string& name) {
  return std::string(TRITRI_BINARY_DIR) + "/plugins/lib" + name + ".so";
}

// Writes `text` to a file under the build tree and returns its path. Written beside and renamed
// into place, because ctest runs tests in parallel and several may write the same fixture.
inline std::string scratch_file(const std::string& name, const std::string& text) {
  const std::string path = std::string(TRITRI_BINARY_DIR) + "/scratch-" + name;
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
  std::ofstream(temporary, std::ios::binary) << text;
  std::rename(temporary.c_str(), path.c_str());
  return path;
}

}  // namespace tritri::testing_support
