// A worker that segfaults, aborts, throws and hangs on known cases: each bad case is found and
// named, and every other case is still computed.
#include "harness/run/isolation.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <stdexcept>

namespace tritri {
namespace {

TEST(Isolation, FindsEveryBadCaseAndKeepsTheRest) {
  constexpr std::size_t n = 300;
  SharedArray<long> out(n);
  auto work = [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      if (i == 37) std::raise(SIGSEGV);
      if (i == 80) for (volatile bool forever = true; forever;) {}
      if (i == 100) throw std::runtime_error("bad input 100");
      if (i == 250) std::abort();
      out[i] = static_cast<long>(i) * 2 + 1;
    }
  };
  IsolationOptions options;
  options.stall_seconds = 0.3;
  options.chunk = 16;
  const auto faults = run_isolated(n, work, options);
  ASSERT_EQ(faults.size(), 4u);
  EXPECT_EQ(faults[0].index, 37u);
  EXPECT_EQ(faults[0].fate, Fate::crash);
  EXPECT_EQ(faults[0].detail, "SIGSEGV");
  EXPECT_EQ(faults[1].index, 80u);
  EXPECT_EQ(faults[1].fate, Fate::timeout);
  EXPECT_EQ(faults[2].index, 100u);
  EXPECT_EQ(faults[2].detail, "exception: bad input 100");
  EXPECT_EQ(faults[3].index, 250u);
  EXPECT_EQ(faults[3].detail, "SIGABRT");
  for (std::size_t i = 0; i < n; ++i) {
    if (i == 37 || i == 80 || i == 100 || i == 250) continue;
    EXPECT_EQ(out[i], static_cast<long>(i) * 2 + 1) << i;
  }
}

// A build that hangs on every case is stopped after max_faults timeouts, each found by one child
// (the case it made no progress on), with the first case not run named; the cases before the
// first fault are computed.
TEST(Isolation, StopsAtTheFaultLimitAndSaysWhereItStopped) {
  constexpr std::size_t n = 1000;
  SharedArray<long> out(n);
  auto work = [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      if (i >= 40) for (volatile bool forever = true; forever;) {}
      out[i] = 1;
    }
  };
  IsolationOptions options;
  options.stall_seconds = 0.1;
  options.chunk = 16;
  options.max_faults = 3;
  std::size_t stopped_at = 0;
  const auto faults = run_isolated(n, work, options, &stopped_at);
  ASSERT_EQ(faults.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(faults[k].index, 40 + k);
    EXPECT_EQ(faults[k].fate, Fate::timeout);
  }
  EXPECT_EQ(stopped_at, 43u);
  for (std::size_t i = 0; i < 40; ++i) EXPECT_EQ(out[i], 1) << i;
  // No limit: every case is tried.
  options.max_faults = 0;
  SharedArray<long> few(50);
  const auto all = run_isolated(50, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      if (i % 10 == 3) std::abort();
      few[i] = 1;
    }
  }, options, &stopped_at);
  EXPECT_EQ(all.size(), 5u);
  EXPECT_EQ(stopped_at, 50u);
}

TEST(Isolation, AGoodWorkerRunsInOneChildWithNoFaults) {
  SharedArray<int> out(1000);
  const auto faults = run_isolated(1000, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) out[i] = static_cast<int>(i);
  });
  EXPECT_TRUE(faults.empty());
  EXPECT_EQ(out[999], 999);
}

TEST(Isolation, CanBeSwitchedOffAndThenExceptionsPropagate) {
  IsolationOptions off;
  off.enabled = false;
  EXPECT_THROW(run_isolated(10, [](std::size_t, std::size_t) { throw std::runtime_error("x"); }, off),
               std::runtime_error);
}

TEST(Isolation, NothingToDoIsFine) {
  EXPECT_TRUE(run_isolated(0, [](std::size_t, std::size_t) { std::abort(); }).empty());
}

}  // namespace
}  // namespace tritri

// Under AddressSanitizer the deliberate segfault must kill its child as a signal.
extern "C" const char* __asan_default_options() { return "handle_segv=0:handle_abort=0"; }
