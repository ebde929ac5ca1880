// Hostile input has a defined outcome: a clear error naming file, line and problem, or a
// labelled per-case outcome. Never a crash, never a silent wrong label.
#include "cases/util/atomic_file.hpp"
#include "harness/testing/tritri_runner.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace tritri {
namespace {

using testing_support::run_tritri;
using testing_support::scratch_file;

// The label row of `name` begins with `prefix` (the columns after it are checked elsewhere).
::testing::AssertionResult row_starts(const std::string& out, const std::string& name, const std::string& prefix);

std::string label_of(const std::string& out, const std::string& name) {
  const auto at = out.find("\n" + name + "\t");
  return at == std::string::npos ? "" : out.substr(at + 1, out.find('\n', at + 1) - at - 1);
}

::testing::AssertionResult row_starts(const std::string& out, const std::string& name, const std::string& prefix) {
  const std::string row = label_of(out, name);
  if (row.rfind(prefix, 0) == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "row '" << row << "' does not begin with '" << prefix << "'";
}

TEST(HostileInput, NaNAndInfinitiesAreRefusedWithFileAndLine) {
  for (const char* bad : {"nan", "-nan", "inf", "-inf", "infinity", "1e999"}) {
    const auto path = scratch_file("nonfinite.cases", std::string("# x\nc 0 0 0 1 0 0 0 1 0 0 0 1 1 0 ") + bad + " 0 1 1\n");
    const auto r = run_tritri("check " + path);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.out.find(path + ":2: coordinate 15 (T2.b.z)"), std::string::npos) << r.out;
  }
}

// Valid but hostile cases: extreme magnitudes, and zero-area triangles and repeated vertices.
const std::string kValidButHostile =
    "huge 0 0 0 1e300 0 0 0 1e300 0  1e299 1e299 -1e300 1e299 1e299 1e300 -1e300 1e299 0\n"
    "huge-apart 0 0 0 1e300 0 0 0 1e300 0  0 0 1e300 1e300 0 1e300 0 1e300 1e300\n"
    "tiny 0 0 0 1e-300 0 0 0 1e-300 0  1e-301 1e-301 -1e-300 1e-301 1e-301 1e-300 -1e-300 1e-301 0\n"
    "subnormal 0 0 0 4e-320 0 0 0 4e-320 0  0 0 5e-324 4e-320 0 5e-324 0 4e-320 5e-324\n"
    "max 0 0 0 1.7976931348623157e308 0 0 0 1.7976931348623157e308 0  0 0 1 1 0 1 0 1 1\n"
    "collinear-far 0 0 0 4 0 0 0 4 0  100 100 5 101 101 5 102 102 5\n"
    "collinear-through 0 0 0 4 0 0 0 4 0  1 1 -1 1 1 0 1 1 1\n"
    "repeated 0 0 0 4 0 0 0 4 0  1 1 0 1 1 0 2 2 1\n"
    "one-point 0 0 0 4 0 0 0 4 0  1 1 0 1 1 0 1 1 0\n"
    "both 0 0 0 0 0 0 0 0 0  0 0 0 0 0 0 0 0 0\n";

TEST(HostileInput, ExtremeMagnitudesAreJudgedExactlyAndEveryAlgorithmAnswers) {
  const auto path = scratch_file("valid-but-hostile.cases", kValidButHostile);
  auto r = run_tritri("label " + path);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(row_starts(r.out, "huge", "huge\t1\tcross"));
  EXPECT_EQ(label_of(r.out, "huge-apart"), "huge-apart\t0\tparallel\tnone\t0\t1e+300\tplane2");
  EXPECT_TRUE(row_starts(r.out, "tiny", "tiny\t1\tcross"));
  EXPECT_EQ(label_of(r.out, "subnormal"), "subnormal\t0\tparallel\tnone\t0\t5e-324\tplane2");
  r = run_tritri("check --quiet " + path);
  EXPECT_EQ(r.status, 0) << r.out;  // wrong answers are data; nothing crashed
}

TEST(HostileInput, ZeroAreaTrianglesAndRepeatedVerticesAreLabelledDegenerate) {
  const auto path = scratch_file("valid-but-hostile.cases", kValidButHostile);
  auto r = run_tritri("label " + path);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(label_of(r.out, "collinear-far"), "collinear-far\t0\tdegenerate\tnone\t0\t-\tdegenerate");
  EXPECT_TRUE(row_starts(r.out, "collinear-through", "collinear-through\t1\tdegenerate\tpoint"));
  EXPECT_TRUE(row_starts(r.out, "repeated", "repeated\t1\tdegenerate\tpoint"));
  EXPECT_TRUE(row_starts(r.out, "one-point", "one-point\t1\tdegenerate\tpoint"));
  EXPECT_TRUE(row_starts(r.out, "both", "both\t1\tdegenerate\tpoint"));
  // algorithms that do not accept zero-area triangles are not called: the case is unsupported
  r = run_tritri("answer --algo moller97 " + path);
  EXPECT_NE(r.out.find("collinear-far\tunsupported\t-\t-"), std::string::npos) << r.out;
}

TEST(HostileInput, TruncatedAndMalformedLinesNameTheirLine) {
  auto path = scratch_file("truncated.cases", "a 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 1\nb 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0");
  auto r = run_tritri("label " + path);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find(path + ":2: expected a name and 18 coordinates, found 16"), std::string::npos) << r.out;
  // a complete last line without its newline is fine
  path = scratch_file("no-newline.cases", "a 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 1");
  EXPECT_EQ(run_tritri("label " + path).status, 0);
  // binary junk
  path = scratch_file("junk.cases", std::string("\x7f" "ELF\x01\x02\x00\x00 1 2 3\n", 14));
  r = run_tritri("label " + path);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find(path + ":1:"), std::string::npos) << r.out;
}

TEST(HostileInput, AnEmptyFileIsAClearErrorNotAnEmptyTable) {
  const auto path = scratch_file("empty.cases", "");
  const auto r = run_tritri("check " + path);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("no cases in " + path), std::string::npos) << r.out;
}

TEST(HostileInput, AVeryLongLineIsRefusedQuickly) {
  std::string line = "long";
  for (int i = 0; i < 200000; ++i) line += " 1.5";
  const auto path = scratch_file("long.cases", line + "\n");
  const auto r = run_tritri("label " + path);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find(path + ":1: expected a name and 18 coordinates, found 200000"), std::string::npos)
      << r.out.substr(0, 300);
}

TEST(HostileInput, UnknownNamesAndUnwritablePathsAreClearErrors) {
  const std::string builtin = std::string(TRITRI_SOURCE_DIR) + "/cases/builtin.cases";
  auto r = run_tritri("answer --algo no-such-algorithm " + builtin);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("unknown algorithm 'no-such-algorithm' (known: moller97"), std::string::npos) << r.out;
  r = run_tritri("check --write-baseline /proc/forbidden/b.tsv " + builtin);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("cannot write '/proc/forbidden/b.tsv'"), std::string::npos) << r.out;
  r = run_tritri("check --baseline /nonexistent/b.tsv " + builtin);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("/nonexistent/b.tsv"), std::string::npos) << r.out;
}

TEST(AtomicOutput, AFailedWriteLeavesTheOldFileWholeAndNoTemporary) {
  const std::string path = std::string(TRITRI_BINARY_DIR) + "/atomic.txt";
  write_file_atomically(path, [](std::ostream& out) { out << "complete\n"; });
  EXPECT_THROW(write_file_atomically(path, [](std::ostream& out) {
                 out << "half";
                 throw std::runtime_error("interrupted");
               }),
               std::runtime_error);
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(text, "complete\n");
  for (const auto& entry : std::filesystem::directory_iterator(TRITRI_BINARY_DIR))
    EXPECT_EQ(entry.path().filename().string().find("atomic.txt.tmp"), std::string::npos) << entry.path();
}

}  // namespace
}  // namespace tritri
