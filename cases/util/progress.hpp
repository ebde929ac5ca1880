// The one progress meter of tritri: long steps say what they do and how far they are.
//
// On a terminal it redraws one line (at most ten times a second); in a log (stderr not a
// terminal) it writes a line every few seconds, so a CI log shows a long step moving without
// being flooded. Short jobs (under `quiet_below` items) print nothing.
#pragma once

#include <chrono>
#include <cstdlib>
#include <cstddef>
#include <cstdio>
#include <mutex>
#include <string>
#include <unistd.h>

namespace tritri {

class Progress {
 public:
  Progress(std::string what, std::size_t total, std::size_t quiet_below = 20000)
      : what_(std::move(what)),
        total_(total),
        terminal_(isatty(fileno(stderr)) == 1),
        shown_(total >= quiet_below && !std::getenv("TRITRI_NO_PROGRESS")),
        start_(Clock::now()),
        last_(start_) {}
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  ~Progress() { finish(); }

  // Safe to call from several threads.
  void update(std::size_t done) {
    if (!shown_) return;
    std::lock_guard guard(lock_);
    done_ = done;
    const auto now = Clock::now();
    const double since = std::chrono::duration<double>(now - last_).count();
    if (since < (terminal_ ? 0.1 : 5.0)) return;
    last_ = now;
    print(false);
  }

  // A callback for parallel_chunks and the labeller: (done, total).
  auto callback() {
    return [this](std::size_t done, std::size_t) { update(done); };
  }

  void finish() {
    if (!shown_ || finished_) return;
    std::lock_guard guard(lock_);
    finished_ = true;
    done_ = total_;
    print(true);
  }

 private:
  using Clock = std::chrono::steady_clock;

  void print(bool final) {
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    const double rate = elapsed > 0 ? static_cast<double>(done_) / elapsed : 0.0;
    char line[256];
    if (final) {
      std::snprintf(line, sizeof line, "%s: %zu of %zu in %.1f s (%.0f/s)", what_.c_str(), done_, total_, elapsed, rate);
    } else {
      const double left = rate > 0 ? static_cast<double>(total_ - done_) / rate : 0.0;
      std::snprintf(line, sizeof line, "%s: %zu of %zu (%.0f/s, about %.0f s left)", what_.c_str(), done_, total_,
                    rate, left);
    }
    if (terminal_) std::fprintf(stderr, "\r%-78s%s", line, final ? "\n" : "");
    else std::fprintf(stderr, "%s\n", line);
    std::fflush(stderr);
  }

  std::string what_;
  std::size_t total_;
  std::size_t done_ = 0;
  bool terminal_;
  bool shown_;
  bool finished_ = false;
  Clock::time_point start_, last_;
  std::mutex lock_;
};

}  // namespace tritri
