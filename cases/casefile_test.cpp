// Case files round-trip bit for bit, and every kind of bad line is refused with its file, line
// and problem.
#include "cases/casefile.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>

namespace tritri {
namespace {

std::string line_of(const std::vector<double>& xyz, const std::string& labels = "") {
  std::string out = "c";
  for (double x : xyz) out += " " + format_double(x);
  return out + labels;
}

TEST(CaseFile, RoundTripsAwkwardDoublesBitForBit) {
  using L = std::numeric_limits<double>;
  const std::vector<double> values = {
      0.0, -0.0, 1.0 / 3.0, 0.1, -2.5e-300, L::denorm_min(), -L::denorm_min(), L::min(),
      std::nextafter(L::min(), 0.0), L::max(), -L::max(), L::epsilon(), 1e300, 123456789.123456789,
      std::nextafter(1.0, 2.0), std::ldexp(1.0, -1074 + 3), 0x1.fffffffffffffp-1, 9007199254740993.0};
  for (std::size_t start = 0; start < values.size(); ++start) {
    std::vector<double> xyz;
    for (std::size_t k = 0; k < 18; ++k) xyz.push_back(values[(start + k) % values.size()]);
    Case c = parse_case_line(line_of(xyz, " family=x"), "mem", 1);
    std::ostringstream written;
    write_cases(written, {c});
    std::istringstream in(written.str());
    const auto back = read_cases(in, "mem");
    ASSERT_EQ(back.size(), 1u);
    for (int t = 0; t < 2; ++t)
      for (int v = 0; v < 3; ++v)
        for (int k = 0; k < 3; ++k) {
          const double want = xyz[static_cast<std::size_t>(9 * t + 3 * v + k)];
          const double got = (t == 0 ? back[0].pair.t1 : back[0].pair.t2)[v][k];
          EXPECT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(want))
              << format_hex(want) << " came back as " << format_hex(got);
        }
  }
}

TEST(CaseFile, ReadsHexFloatsExponentsAndLabels) {
  const auto c = parse_case_line(
      "  h 0x1p-1 1e0 -0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0x1.8p1  family=f expect=cross extra=kept  ", "f", 7);
  EXPECT_EQ(c.name, "h");
  EXPECT_EQ(c.pair.t1[0].x(), 0.5);
  EXPECT_EQ(c.pair.t1[0].y(), 1.0);
  EXPECT_TRUE(std::signbit(c.pair.t1[0].z()));
  EXPECT_EQ(c.pair.t2[2].z(), 3.0);
  EXPECT_EQ(c.label("family"), "f");
  EXPECT_EQ(c.label("extra"), "kept");
  EXPECT_EQ(c.family(), "f");
  EXPECT_EQ(c.line, 7);
  // the shortest decimal is what gets written
  EXPECT_EQ(format_double(0.1), "0.1");
  EXPECT_EQ(format_double(-0.0), "-0");
  EXPECT_EQ(format_hex(3.0), "0x1.8p+1");
}

TEST(CaseFile, SkipsCommentsAndBlankLinesAndCountsLines) {
  std::istringstream in("# header\n\n   \n  # indented comment\r\na 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 1\n");
  const auto cases = read_cases(in, "x.cases");
  ASSERT_EQ(cases.size(), 1u);
  EXPECT_EQ(cases[0].line, 5);
  EXPECT_EQ(cases[0].family(), "x");  // no family= label: the file's stem
}

struct BadLine {
  const char* text;
  const char* problem;  // a fragment the error must contain
};

class MalformedLine : public testing::TestWithParam<BadLine> {};

TEST_P(MalformedLine, IsRefusedWithFileLineAndProblem) {
  std::istringstream in(std::string("# fine\nok 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 1\n") + GetParam().text + "\n");
  try {
    read_cases(in, "bad.cases");
    FAIL() << "accepted: " << GetParam().text;
  } catch (const CaseFileError& e) {
    EXPECT_EQ(e.file(), "bad.cases");
    EXPECT_EQ(e.line(), 3);
    EXPECT_NE(std::string(e.what()).find("bad.cases:3: "), std::string::npos) << e.what();
    EXPECT_NE(e.problem().find(GetParam().problem), std::string::npos) << e.problem();
  }
}

INSTANTIATE_TEST_SUITE_P(
    EveryKind, MalformedLine,
    testing::Values(BadLine{"short 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1", "found 17 coordinates"},
                    BadLine{"long 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 1 1", "found 19 coordinates"},
                    BadLine{"nameonly", "found 0 coordinates"},
                    BadLine{"word 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 one", "'one' is not a number"},
                    BadLine{"junk 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 1.5x", "'1.5x' is not a number"},
                    BadLine{"nan 0 0 0 1 0 0 0 1 0 nan 0 1 1 0 1 0 1 1", "is NaN"},
                    BadLine{"inf 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 -inf", "is infinite"},
                    BadLine{"big 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 1e400", "overflows a double"},
                    BadLine{"lab 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 1 =x", "has no key"},
                    BadLine{"k=v 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 1", "contains '='"}));

TEST(CaseFile, NamesTheCoordinateThatIsWrong) {
  try {
    parse_case_line("w 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 zz", "f", 1);
    FAIL();
  } catch (const CaseFileError& e) {
    EXPECT_NE(e.problem().find("coordinate 18 (T2.c.z)"), std::string::npos) << e.problem();
  }
}

TEST(CaseFile, KeepsSubnormalInputInsteadOfCallingItAnError) {
  const auto c = parse_case_line("s 4.9e-324 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 1", "f", 1);
  EXPECT_EQ(c.pair.t1[0].x(), std::numeric_limits<double>::denorm_min());
}

TEST(CaseFile, RefusesMissingFilesDirectoriesAndDuplicateNames) {
  EXPECT_THROW(read_case_file("/nonexistent/x.cases"), CaseFileError);
  EXPECT_THROW(read_case_file(TRITRI_SOURCE_DIR), CaseFileError);
  const std::string path = std::string(TRITRI_BINARY_DIR) + "/dup.cases";
  {
    std::ofstream out(path);
    out << "a 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 1\na 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 1\n";
  }
  try {
    read_case_file(path);
    FAIL();
  } catch (const CaseFileError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(e.problem().find("duplicate"), std::string::npos);
  }
}

TEST(CaseFile, AnEmptyFileHasNoCases) {
  std::istringstream in("");
  EXPECT_TRUE(read_cases(in, "empty").empty());
}

}  // namespace
}  // namespace tritri
