#include "cases/util/atomic_file.hpp"
#include "cases/util/input_error.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace tritri {
namespace {

// The temporary file being written, so that Ctrl-C or a kill between writing and renaming
// removes it instead of leaving a half-written file behind.
char g_temporary[4096];
volatile std::sig_atomic_t g_writing = 0;

void remove_temporary_and_stop(int sig) {
  if (g_writing) ::unlink(g_temporary);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

struct TemporaryGuard {
  explicit TemporaryGuard(const std::string& path) {
    static const bool installed = [] {
      for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, remove_temporary_and_stop);
      return true;
    }();
    (void)installed;
    std::snprintf(g_temporary, sizeof g_temporary, "%s", path.c_str());
    g_writing = 1;
  }
  ~TemporaryGuard() { g_writing = 0; }
};

}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& fill) {
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
  TemporaryGuard guard(temporary);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError("cannot write '" + path + "': " + std::strerror(errno));
    try {
      fill(out);
    } catch (...) {
      out.close();
      std::remove(temporary.c_str());
      throw;
    }
    out.flush();
    if (!out) {
      out.close();
      std::remove(temporary.c_str());
      throw InputError("error while writing '" + path + "'");
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::remove(temporary.c_str());
    throw InputError("cannot write '" + path + "': " + error.message());
  }
}

}  // namespace tritri
