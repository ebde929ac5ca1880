#include "harness/run/isolation.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace tritri {
namespace {

// What a child tells its parent, in shared memory.
struct ChildReport {
  std::atomic<std::size_t> done;  // cases finished, counted from the child's `begin`
  char message[240];              // an exception's text
};

constexpr int kExceptionExit = 86;

std::string signal_name(int sig) {
  switch (sig) {
    case SIGSEGV: return "SIGSEGV";
    case SIGABRT: return "SIGABRT";
    case SIGFPE: return "SIGFPE";
    case SIGBUS: return "SIGBUS";
    case SIGILL: return "SIGILL";
    case SIGKILL: return "SIGKILL";
    default: return "signal " + std::to_string(sig);
  }
}

struct Attempt {
  bool ok = true;
  std::size_t done = 0;  // cases completed before the failure
  Fate fate = Fate::ok;
  std::string detail;
};

// Runs [begin, end) in one child, `chunk` cases at a time, watching its progress.
Attempt run_child(std::size_t begin, std::size_t end, std::size_t chunk,
                  const std::function<void(std::size_t, std::size_t)>& work, double stall_seconds) {
  SharedArray<ChildReport> report(1);
  report[0].done = 0;
  std::fflush(nullptr);  // nothing buffered may be written twice
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
  if (pid == 0) {
    try {
      for (std::size_t b = begin; b < end; b += chunk) {
        const std::size_t e = std::min(end, b + chunk);
        work(b, e);
        report[0].done = e - begin;
      }
    } catch (const std::exception& ex) {
      std::snprintf(report[0].message, sizeof report[0].message, "exception: %s", ex.what());
      _exit(kExceptionExit);
    } catch (...) {
      std::snprintf(report[0].message, sizeof report[0].message, "exception of unknown type");
      _exit(kExceptionExit);
    }
    _exit(0);
  }

  using Clock = std::chrono::steady_clock;
  std::size_t last_done = 0;
  auto last_progress = Clock::now();
  auto pause = std::chrono::microseconds(50);
  for (;;) {
    int status = 0;
    const pid_t r = waitpid(pid, &status, WNOHANG);
    if (r == pid) {
      Attempt a;
      a.done = report[0].done;
      if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return a;
      a.ok = false;
      a.fate = Fate::crash;
      if (WIFSIGNALED(status)) a.detail = signal_name(WTERMSIG(status));
      else if (WEXITSTATUS(status) == kExceptionExit) a.detail = report[0].message;
      else a.detail = "exit status " + std::to_string(WEXITSTATUS(status));
      return a;
    }
    const std::size_t done = report[0].done;
    if (done != last_done) {
      last_done = done;
      last_progress = Clock::now();
    } else if (std::chrono::duration<double>(Clock::now() - last_progress).count() > stall_seconds) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      Attempt a;
      a.ok = false;
      a.done = report[0].done;
      a.fate = Fate::timeout;
      char text[64];
      std::snprintf(text, sizeof text, "no progress for %g s", stall_seconds);
      a.detail = text;
      return a;
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(20000));
  }
}

// [begin, end) failed as a whole: each case that fails is found by running the range again one
// case per progress step, so that a child that dies or hangs names its case by how far it got;
// the rest of the range goes on in a fresh child. One child per fault: a build that hangs on
// every case costs one stall per case, not a halving search of each chunk.
// Returns the first case not run when `limit` faults were reached, else `end`.
std::size_t isolate(std::size_t begin, std::size_t end, const std::function<void(std::size_t, std::size_t)>& work,
                    double stall_seconds, std::size_t limit, std::vector<Fault>& faults) {
  for (std::size_t next = begin; next < end;) {
    if (limit && faults.size() >= limit) return next;
    const Attempt a = run_child(next, end, 1, work, stall_seconds);
    if (a.ok) break;
    faults.push_back({next + a.done, a.fate, a.detail});
    next += a.done + 1;
  }
  return end;
}

}  // namespace

std::string to_string(Fate f) {
  switch (f) {
    case Fate::ok: return "ok";
    case Fate::crash: return "crash";
    case Fate::timeout: return "timeout";
    case Fate::not_run: return "not-run";
  }
  return "?";
}

std::vector<Fault> run_isolated(std::size_t n, const std::function<void(std::size_t, std::size_t)>& work,
                                const IsolationOptions& options, std::size_t* stopped_at) {
  std::vector<Fault> faults;
  if (stopped_at) *stopped_at = n;
  const std::size_t chunk = std::max<std::size_t>(1, options.chunk);
  if (!options.enabled) {
    for (std::size_t b = 0; b < n; b += chunk) work(b, std::min(n, b + chunk));
    return faults;
  }
  std::size_t next = 0;
  while (next < n) {
    const Attempt a = run_child(next, n, chunk, work, options.stall_seconds);
    if (a.ok) break;
    // The child finished `a.done` cases; the failure is in the chunk after them.
    const std::size_t bad_begin = next + a.done;
    const std::size_t bad_end = std::min(n, bad_begin + chunk);
    next = isolate(bad_begin, bad_end, work, options.stall_seconds, options.max_faults, faults);
    if (next < n && options.max_faults && faults.size() >= options.max_faults) {
      if (stopped_at) *stopped_at = next;
      return faults;
    }
  }
  return faults;
}

}  // namespace tritri
