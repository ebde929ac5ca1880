// Running code that may be wrong without letting it take the harness down.
//
// A plug-in may segfault, abort, throw or loop forever on some input. run_isolated() runs the
// work in a child process, chunk by chunk, with its results written to memory shared with the
// parent. When the child dies or stops making progress, the failing chunk is bisected in fresh
// children down to the single case responsible, which is recorded as a crash or a timeout; the
// cases around it are still computed.
#pragma once

#include <cstddef>
#include <functional>
#include <new>
#include <string>
#include <sys/mman.h>
#include <type_traits>
#include <vector>

namespace tritri {

// not_run: the run stopped at the fault limit (IsolationOptions::max_faults) before this case.
enum class Fate : std::uint8_t { ok, crash, timeout, not_run };

struct Fault {
  std::size_t index = 0;
  Fate fate = Fate::crash;
  std::string detail;  // "SIGSEGV", "exception: ...", "no progress for 2 s"
};

struct IsolationOptions {
  bool enabled = true;            // false: run in this process (faster, no protection)
  double stall_seconds = 2.0;     // a chunk that makes no progress for this long is a timeout
  std::size_t chunk = 64;         // cases per progress step
  // After this many crashes or timeouts the run stops and the remaining cases are not run, so
  // that a build that fails on every case is told so in seconds (each timeout costs
  // stall_seconds); 0: no limit.
  std::size_t max_faults = 20;
};

// Calls `work(begin, end)` over consecutive chunks of [0, n). `work` must write its results to
// memory the parent can see (SharedArray below). Returns the cases that crashed or timed out;
// every other case before `*stopped_at` completed. `*stopped_at` (when given) is n, or the first
// case not run once options.max_faults faults were found. With isolation disabled, exceptions
// propagate.
std::vector<Fault> run_isolated(std::size_t n, const std::function<void(std::size_t, std::size_t)>& work,
                                const IsolationOptions& options = {}, std::size_t* stopped_at = nullptr);

// A fixed-size array in anonymous shared memory, so a forked child's writes are seen by the
// parent. T must be plain data in practice: its bytes are its value and nothing needs destroying
// (Eigen's fixed-size vectors qualify, though they declare their own copy operations).
template <class T>
class SharedArray {
  static_assert(std::is_trivially_destructible_v<T>);

 public:
  explicit SharedArray(std::size_t n) : size_(n) {
    const std::size_t bytes = std::max<std::size_t>(1, n * sizeof(T));
    void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    data_ = static_cast<T*>(p);
    for (std::size_t i = 0; i < n; ++i) new (data_ + i) T();
  }
  ~SharedArray() { munmap(data_, std::max<std::size_t>(1, size_ * sizeof(T))); }
  SharedArray(const SharedArray&) = delete;
  SharedArray& operator=(const SharedArray&) = delete;

  T* data() { return data_; }
  T& operator[](std::size_t i) { return data_[i]; }
  std::size_t size() const { return size_; }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

std::string to_string(Fate);

}  // namespace tritri
