#include "harness/run/process_child.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace tritri {
namespace {

// The environment for the child, built before fork: after it only async-signal-safe calls.
std::vector<std::string> child_environment(const char* protocol) {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "TRITRI_PROTOCOL=", 16) != 0) env.emplace_back(*e);
  env.push_back(std::string("TRITRI_PROTOCOL=") + protocol);
  return env;
}

}  // namespace

ProcessChild::ProcessChild(const std::string& command, const char* protocol) {
  const std::vector<std::string> env = child_environment(protocol);
  std::vector<char*> envp;
  for (const auto& e : env) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);
  int in[2], out[2];
  if (pipe(in) != 0 || pipe(out) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  pid_ = fork();
  if (pid_ < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (pid_ == 0) {
    setpgid(0, 0);  // its own process group, so a timeout kills whatever it started
    dup2(in[0], STDIN_FILENO);
    dup2(out[1], STDOUT_FILENO);
    close(in[0]); close(in[1]); close(out[0]); close(out[1]);
    execle("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr), envp.data());
    _exit(127);
  }
  close(in[0]);
  close(out[1]);
  to_ = in[1];
  from_ = out[0];
  // Never block on a write: a plug-in busy writing answers we have not read yet is not reading.
  fcntl(to_, F_SETFL, fcntl(to_, F_GETFL) | O_NONBLOCK);
}

bool ProcessChild::flush_some() {
  while (!pending_.empty()) {
    const ssize_t n = ::write(to_, pending_.data(), pending_.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return true;
    if (n <= 0) {  // EPIPE: it has gone, or closed its input
      pending_.clear();
      return false;
    }
    pending_.erase(0, static_cast<std::size_t>(n));
  }
  return true;
}

ProcessChild::Read ProcessChild::read_line(std::string& line, double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  for (;;) {
    if (auto nl = buffer_.find('\n'); nl != std::string::npos) {
      line = buffer_.substr(0, nl);
      buffer_.erase(0, nl + 1);
      return Read::line;
    }
    flush_some();
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return Read::timeout;
    pollfd p[2] = {{from_, POLLIN, 0}, {to_, POLLOUT, 0}};
    const int ready = poll(p, pending_.empty() ? 1 : 2, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) return Read::timeout;
    if (!(p[0].revents & (POLLIN | POLLHUP | POLLERR))) continue;  // only writable
    char chunk[65536];
    const ssize_t n = ::read(from_, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return Read::eof;
    buffer_.append(chunk, static_cast<std::size_t>(n));
  }
}

std::string ProcessChild::stop() {
  if (pid_ <= 0) return "";
  if (to_ >= 0) close(to_);
  if (from_ >= 0) close(from_);
  to_ = from_ = -1;
  int status = 0;
  if (waitpid(pid_, &status, WNOHANG) == 0) {
    kill(-pid_, SIGKILL);
    waitpid(pid_, &status, 0);
  }
  pid_ = -1;
  if (WIFSIGNALED(status)) return std::string("killed by signal ") + std::to_string(WTERMSIG(status));
  return "exit status " + std::to_string(WEXITSTATUS(status));
}

}  // namespace tritri
