// Which route a chunk of a batch takes: the SIMD passes (and the scalar pass for what they leave),
// or every pair through the one-pair path. Both give the same exact answers. Which is faster
// depends on the pairs and on the machine: where the lanes leave many pairs to the scalar pass,
// on a core that lowers its clock while wide floating-point instructions run, the scalar pass
// after the lanes runs at the lower clock and the one-pair path alone is faster
// (algorithms/exact/README.md, "The batch's route: lanes or one pair at a time"). So the batch
// measures both routes on the pairs it is given and keeps the faster.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>

namespace tritri::exact::detail {

enum class BatchRoute : std::uint8_t { lanes, one_pair };

// A cheap monotonic tick count. Only the two routes' ticks per pair are compared, so the unit
// does not matter: the time-stamp counter on x86-64 (constant rate on the cores that throttle),
// the virtual counter on aarch64.
inline std::uint64_t ticks() {
#if defined(__x86_64__) || defined(__i386__)
  return __builtin_ia32_rdtsc();
#elif defined(__aarch64__)
  std::uint64_t t;
  asm volatile("mrs %0, cntvct_el0" : "=r"(t));
  return t;
#else
  return static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
#endif
}

// One per thread and level. Lengths are in pairs, so that the choice does not depend on how a
// caller cuts its batches. The current route's cost per pair is a running mean; the other route
// is tried for a stretch of pairs, timed on the stretch's second half (the clock takes a while to
// come back after wide instructions stop), and takes over if it was cheaper. The gap between
// tries doubles after each try that loses, from kMinGap to kMaxGap, and falls back to kMinGap
// when a try wins or when the current route's cost moves away from its mean for kDrift pairs
// (other pairs). The one-pair route is tried only while the lanes leave at least kGate of their
// pairs to the scalar pass: below that, every pair the lanes decide costs a fraction of a one-pair
// decision, so the try could not win and would cost time on the pools the lanes are built for.
class RouteChooser {
 public:
  static constexpr std::uint64_t kTryOnePair = 16384;  // pairs of a one-pair try
  static constexpr std::uint64_t kTryLanes = 4096;     // pairs of a lanes try
  static constexpr std::uint64_t kMinGap = 65536, kMaxGap = 262144;
  static constexpr std::uint64_t kDrift = 1024;
  static constexpr double kGate = 0.25;
  // Chunks with fewer pairs are run on the current route and not timed: two tick reads would
  // weigh on them, and a few pairs say little about the next ones.
  static constexpr std::size_t kMinPairs = 64;

  // A chooser that keeps `route` whatever it measures (the tests drive each route through it).
  static RouteChooser pinned(BatchRoute route) {
    RouteChooser c;
    c.current_ = route;
    c.pinned_ = true;
    return c;
  }

  BatchRoute next() const { return trying_ ? other(current_) : current_; }
  BatchRoute current() const { return current_; }

  // `route` ran `pairs` pairs in `spent` ticks; on the lanes route, `scalar` of them reached the
  // scalar pass.
  void record(BatchRoute route, std::uint64_t pairs, std::uint64_t spent, std::uint64_t scalar) {
    if (pinned_) return;
    if (route == BatchRoute::lanes) share_ += (static_cast<double>(scalar) / static_cast<double>(pairs) - share_) / 8.0;
    if (trying_) return tried(pairs, spent);
    const double c = static_cast<double>(spent) / static_cast<double>(pairs);
    double& mean = cost_[index(current_)];
    if (mean < 0.0) mean = c;
    drift_ = (c > 1.5 * mean || 1.5 * c < mean) ? drift_ + pairs : 0;
    if (drift_ >= kDrift) {  // other pairs: measure afresh and try the other route soon
      mean = c, drift_ = 0, gap_ = kMinGap, until_ = 0;
    } else {
      mean += (c - mean) / 8.0;
    }
    until_ = until_ > pairs ? until_ - pairs : 0;
    if (until_ == 0) {
      if (current_ == BatchRoute::one_pair || share_ >= kGate) start_try();
      else until_ = gap_;
    }
  }

 private:
  static BatchRoute other(BatchRoute r) { return r == BatchRoute::lanes ? BatchRoute::one_pair : BatchRoute::lanes; }
  static int index(BatchRoute r) { return static_cast<int>(r); }

  void start_try() {
    trying_ = true;
    left_ = other(current_) == BatchRoute::one_pair ? kTryOnePair : kTryLanes;
    timed_ = left_ / 2;
    spent_ = pairs_ = 0;
  }
  void tried(std::uint64_t pairs, std::uint64_t spent) {
    // the stretch's second half (or its last chunk, when one chunk spans more than half)
    if (left_ <= timed_ || (left_ <= pairs && pairs_ == 0)) spent_ += spent, pairs_ += pairs;
    left_ = left_ > pairs ? left_ - pairs : 0;
    if (left_ > 0) return;
    trying_ = false;
    const BatchRoute tried_route = other(current_);
    const double c = static_cast<double>(spent_) / static_cast<double>(pairs_);  // pairs_ > 0: the last chunk is timed
    cost_[index(tried_route)] = c;
    if (c < cost_[index(current_)]) {
      current_ = tried_route;
      gap_ = kMinGap;
    } else {
      gap_ = gap_ * 2 < kMaxGap ? gap_ * 2 : kMaxGap;
    }
    until_ = gap_;
    drift_ = 0;
  }

  BatchRoute current_ = BatchRoute::lanes;
  double cost_[2] = {-1.0, -1.0};  // ticks per pair: the current route's running mean, the other's last try
  double share_ = 0.0;             // running share of the lanes' pairs that reached the scalar pass
  std::uint64_t gap_ = kMinGap, until_ = kMinGap, drift_ = 0;
  bool trying_ = false, pinned_ = false;
  std::uint64_t left_ = 0, timed_ = 0, spent_ = 0, pairs_ = 0;  // the try under way
};

}  // namespace tritri::exact::detail
