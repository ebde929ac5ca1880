// The one parallel loop of tritri: labelling, answering and generating all go through it.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace tritri {

struct ParallelOptions {
  std::size_t chunk = 256;  // items a worker takes at a time
  // Called (from any worker, serialised) after each finished chunk with (done, total); empty:
  // nothing. Long jobs report through it (cases/util/progress.hpp).
  std::function<void(std::size_t, std::size_t)> progress;
  unsigned workers = 0;  // 0: every core
};

// Runs run(begin, end) over [0, count) in chunks on every core. The first exception thrown by
// any chunk stops the others from starting new chunks and is rethrown here.
template <class Run>
void parallel_chunks(std::size_t count, Run&& run, const ParallelOptions& options = {}) {
  const std::size_t chunk = std::max<std::size_t>(1, options.chunk);
  const std::size_t chunks = (count + chunk - 1) / chunk;
  const unsigned cores = options.workers ? options.workers : std::max(1u, std::thread::hardware_concurrency());
  const unsigned workers = static_cast<unsigned>(std::max<std::size_t>(1, std::min<std::size_t>(cores, chunks)));
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::exception_ptr failure;
  std::mutex lock;
  auto work = [&] {
    for (;;) {
      const std::size_t begin = next.fetch_add(chunk);
      if (begin >= count) return;
      const std::size_t end = std::min(count, begin + chunk);
      try {
        run(begin, end);
      } catch (...) {
        std::lock_guard guard(lock);
        if (!failure) failure = std::current_exception();
        next = count;
        return;
      }
      if (options.progress) {
        std::lock_guard guard(lock);
        done += end - begin;
        options.progress(done, count);
      }
    }
  };
  std::vector<std::thread> threads;
  for (unsigned i = 1; i < workers; ++i) threads.emplace_back(work);
  work();
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace tritri
