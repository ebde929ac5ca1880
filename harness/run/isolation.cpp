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

// [begin, end) failed as a whole: find each case that fails on its own by halving.
void bisect(std::size_t begin, std::size_t end, const Attempt& failure,
            const std::function<void(std::size_t, std::size_t)>& work, double stall_seconds,
            std::vector<Fault>& faults) {
  if (end - begin == 1) {
    faults.push_back({begin, failure.fate, failure.detail});
    return;
  }
  const std::size_t mid = begin + (end - begin) / 2;
  for (auto [b, e] : {std::pair{begin, mid}, std::pair{mid, end}}) {
    const Attempt a = run_child(b, e, e - b, work, stall_seconds);
    if (!a.ok) bisect(b, e, a, work, stall_seconds, faults);
  }
}

}  // namespace

std::string to_string(Fate f) {
  switch (f) {
    case Fate::ok: return "ok";
    case Fate::crash: return "crash";
    case Fate::timeout: return "timeout";
  }
  return "?";
}

std::vector<Fault> run_isolated(std::size_t n, const std::function<void(std::size_t, std::size_t)>& work,
                                const IsolationOptions& options) {
  std::vector<Fault> faults;
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
    bisect(bad_begin, bad_end, a, work, options.stall_seconds, faults);
    next = bad_end;
  }
  std::sort(faults.begin(), faults.end(), [](const Fault& x, const Fault& y) { return x.index < y.index; });
  return faults;
}

}  // namespace tritri
