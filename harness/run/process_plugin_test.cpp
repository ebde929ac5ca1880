// The process protocol (process_plugin.hpp) against real processes: many cases in flight, the
// protocol-2 greeting, self-timing, and a protocol-1 plug-in served as before.
#include "harness/run/process_plugin.hpp"

#include "cases/util/input_error.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace tritri {
namespace {

const std::string kPlugins = std::string(TRITRI_SOURCE_DIR) + "/harness/run/test_plugins/";
const ProcessPluginOptions kGreeter{"python3 " + kPlugins + "greeter.py", 5.0};
const ProcessPluginOptions kProtocol1{"python3 " + kPlugins + "unreliable.py", 5.0};

TrianglePair some_pair() {
  return {Triangle{{Vec3<double>(0, 0, 0), Vec3<double>(4, 0, 0), Vec3<double>(0, 4, 0)}},
          Triangle{{Vec3<double>(1, 1, -1), Vec3<double>(1, 1, 1), Vec3<double>(2, 2, 1)}}};
}

// n cases named yes-i (i odd) and no-i, with the name `odd` at index `at` when given.
std::vector<std::string> names(std::size_t n, std::size_t at = SIZE_MAX, const std::string& odd = "") {
  std::vector<std::string> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = i == at ? odd : (i % 2 ? "yes-" : "no-") + std::to_string(i);
  return out;
}

TEST(ProcessProtocol, AGreetingPluginAnswersThousandsOfCasesInFlightInOrder) {
  const auto n = names(3000);
  const ProcessAnswers got = run_process_plugin(kGreeter, n, std::vector<TrianglePair>(n.size(), some_pair()));
  EXPECT_TRUE(got.faults.empty());
  EXPECT_TRUE(got.features.greeted);
  EXPECT_TRUE(got.features.degenerate);
  EXPECT_TRUE(got.features.timing);
  for (std::size_t i = 0; i < n.size(); ++i)
    ASSERT_EQ(got.overlap[i], i % 2 ? Overlap::yes : Overlap::no) << n[i];
}

TEST(ProcessProtocol, ACrashAmidTheCasesInFlightFallsOnTheFirstUnansweredOne) {
  const auto n = names(600, 300, "boom");
  const ProcessAnswers got = run_process_plugin(kProtocol1, n, std::vector<TrianglePair>(n.size(), some_pair()));
  ASSERT_EQ(got.faults.size(), 1u);
  EXPECT_EQ(got.faults[0].index, 300u);
  EXPECT_EQ(got.faults[0].fate, Fate::crash);
  EXPECT_FALSE(got.features.greeted);  // protocol 1: served as before
  for (std::size_t i = 0; i < n.size(); ++i)
    if (i != 300) ASSERT_EQ(got.overlap[i], Overlap::yes) << n[i];  // it says 1 to everything
}

TEST(ProcessProtocol, ThePluginTimesItselfOnThePoolAndItsAnswersComeBack) {
  const auto n = names(500);
  const SelfTimed t = time_process_plugin(kGreeter, n, std::vector<TrianglePair>(n.size(), some_pair()), 3, 0.01);
  EXPECT_EQ(t.ns_per_pair, (std::vector<double>{1.5, 2.5, 3.5}));
  for (std::size_t i = 0; i < n.size(); ++i)
    ASSERT_EQ(t.answers.overlap[i], i % 2 ? Overlap::yes : Overlap::no) << n[i];
}

TEST(ProcessProtocol, AProtocol1PluginIsToldItDoesNotTimeItself) {
  const auto n = names(3);
  try {
    time_process_plugin(kProtocol1, n, std::vector<TrianglePair>(n.size(), some_pair()), 3, 0.01);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("does not time itself"), std::string::npos) << e.what();
  }
}

TEST(ProcessProtocol, AnAddedPluginAcceptsDegeneratePairsOnlyWhenItsGreetingSaysSo) {
  EXPECT_TRUE(add_process_algorithm(kGreeter.command, "greeter", 5.0).accepts_degenerate);
  EXPECT_FALSE(add_process_algorithm(kProtocol1.command, "protocol-1", 5.0).accepts_degenerate);
  EXPECT_TRUE(process_features("greeter").timing);
  EXPECT_FALSE(process_features("protocol-1").timing);
}

}  // namespace
}  // namespace tritri
