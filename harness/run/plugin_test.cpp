// Shared-library plug-ins load as algorithms, and the loader refuses what it cannot trust.
#include "harness/run/isolation.hpp"
#include "harness/run/plugin.hpp"
#include "harness/testing/tritri_runner.hpp"

#include <gtest/gtest.h>

namespace tritri {
namespace {

using testing_support::plugin_library;

std::string load_error(const std::string& path) {
  try {
    load_plugin(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(Plugin, LoadsAsAnAlgorithmWithWhatItDeclares) {
  const Algorithm& a = load_plugin(plugin_library("tritri_broken"));
  EXPECT_EQ(a.name, "broken");
  EXPECT_EQ(registry().find("broken"), &a);
  EXPECT_TRUE(a.answers(Level::overlap));
  EXPECT_FALSE(a.answers(Level::relation));
  EXPECT_EQ(a.boundary, Boundary::closed);
  EXPECT_TRUE(a.tolerance.none());
  // its batch function is called on tritri's own arrays
  const Triangle t{{Vec3<double>(0, 0, 0), Vec3<double>(1, 0, 0), Vec3<double>(0, 1, 0)}};
  const Triangle far{{Vec3<double>(5, 5, 5), Vec3<double>(6, 5, 5), Vec3<double>(5, 6, 5)}};
  TrianglePair pairs[2] = {{t, t}, {t, far}};
  Overlap out[2];
  a.batch<Level::overlap>()(pairs, 2, out);
  EXPECT_EQ(out[0], Overlap::yes);
  EXPECT_EQ(out[1], Overlap::no);
  // loading the same name twice is refused
  EXPECT_NE(load_error(plugin_library("tritri_broken")).find("already taken"), std::string::npos);
}

TEST(Plugin, ItsCrashesAndHangsAreContainedByIsolation) {
  const Algorithm* a = registry().find("broken");
  if (!a) a = &load_plugin(plugin_library("tritri_broken"));
  const Triangle t{{Vec3<double>(0, 0, 0), Vec3<double>(1, 0, 0), Vec3<double>(0, 1, 0)}};
  auto with = [&](double x) { return TrianglePair{t, Triangle{{Vec3<double>(x, 0, 0), Vec3<double>(1, 0, 0), Vec3<double>(0, 1, 0)}}}; };
  std::vector<TrianglePair> pairs;
  for (int i = 0; i < 40; ++i) pairs.push_back(with(i == 5 ? 13 : i == 20 ? 666 : i == 30 ? 99 : 0.5));
  SharedArray<Overlap> out(pairs.size());
  IsolationOptions options;
  options.stall_seconds = 0.3;
  options.chunk = 8;
  const auto faults = run_isolated(pairs.size(), [&](std::size_t b, std::size_t e) {
    a->batch<Level::overlap>()(pairs.data() + b, e - b, out.data() + b);
  }, options);
  ASSERT_EQ(faults.size(), 3u);
  EXPECT_EQ(faults[0].index, 5u);
  EXPECT_EQ(faults[0].detail, "SIGSEGV");
  EXPECT_EQ(faults[1].index, 20u);
  EXPECT_EQ(faults[1].fate, Fate::timeout);
  EXPECT_EQ(faults[2].index, 30u);
  EXPECT_EQ(faults[2].detail, "SIGABRT");
  EXPECT_EQ(out[0], Overlap::yes);
  EXPECT_EQ(out[39], Overlap::yes);
}

TEST(Plugin, RefusesWhatItCannotTrust) {
  EXPECT_NE(load_error("/nonexistent/libx.so").find("/nonexistent/libx.so"), std::string::npos);
  EXPECT_NE(load_error(plugin_library("tritri_broken_noentry")).find("does not export tritri_plugin_entry"), std::string::npos);
  EXPECT_NE(load_error(plugin_library("tritri_broken_abi")).find("plug-in ABI 42"), std::string::npos);
  EXPECT_NE(load_error(plugin_library("tritri_broken_nolevels")).find("answers no level"), std::string::npos);
}

}  // namespace
}  // namespace tritri

// Under AddressSanitizer the plug-in's deliberate segfault must kill its child as a signal.
extern "C" const char* __asan_default_options() { return "handle_segv=0:handle_abort=0"; }
