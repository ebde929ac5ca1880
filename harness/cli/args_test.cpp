// The command-line parser: every list option takes its items in each documented form
// (kListsHelp), alone and mixed, and a one-value option stays one value.
#include "harness/cli/args.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using tritri::cli::Args;
using tritri::cli::OptionSpec;
using tritri::cli::UsageError;
using Words = std::vector<std::string>;

Args parse(Words words, const OptionSpec& spec) {
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  return Args(static_cast<int>(argv.size()), argv.data(), spec);
}

const OptionSpec kWithFiles = {.valued = {"--json"}, .lists = {"--algo"}, .word_lists = {"--group-by"},
                               .flags = {"--quiet"}};
OptionSpec without_files() {
  OptionSpec s = kWithFiles;
  s.operands = false;
  return s;
}

TEST(Args, AListTakesACommaList) {
  const Args a = parse({"--algo", "a,b,,c", "f.cases"}, kWithFiles);
  EXPECT_EQ(a.values("--algo"), (Words{"a", "b", "c"}));
  EXPECT_EQ(a.positional(), (Words{"f.cases"}));
  EXPECT_EQ(parse({"--algo=a,b"}, kWithFiles).values("--algo"), (Words{"a", "b"}));
}

TEST(Args, AListTakesRepeatedFlags) {
  const Args a = parse({"--algo", "a", "--quiet", "--algo", "b,c", "f.cases"}, kWithFiles);
  EXPECT_EQ(a.values("--algo"), (Words{"a", "b", "c"}));
  EXPECT_TRUE(a.flag("--quiet"));
}

TEST(Args, WithoutOperandsAListTakesTheWordsUpToTheNextOption) {
  const Args a = parse({"--algo", "a", "b,c", "d", "--quiet", "--algo", "e"}, without_files());
  EXPECT_EQ(a.values("--algo"), (Words{"a", "b", "c", "d", "e"}));
  EXPECT_TRUE(a.positional().empty());
  EXPECT_EQ(parse({"--algo", "a", "b", "--", "x"}, without_files()).positional(), (Words{"x"}));
}

TEST(Args, WithOperandsTheWordsAfterAListAreTheOperands) {
  const Args a = parse({"--algo", "a", "f.cases", "g.cases"}, kWithFiles);
  EXPECT_EQ(a.values("--algo"), (Words{"a"}));
  EXPECT_EQ(a.positional(), (Words{"f.cases", "g.cases"}));
}

TEST(Args, AWordListKeepsItsCommas) {
  const Args a = parse({"--group-by", "subsuite,tilt", "--group-by", "@base"}, kWithFiles);
  EXPECT_EQ(a.values("--group-by"), (Words{"subsuite,tilt", "@base"}));
  EXPECT_EQ(parse({"--group-by", "k,l", "m"}, without_files()).values("--group-by"), (Words{"k,l", "m"}));
}

TEST(Args, AOneValueOptionTakesOneWordAndKeepsItsCommas) {
  const Args a = parse({"--json", "a,b.json", "x"}, without_files());
  EXPECT_EQ(a.value("--json"), "a,b.json");
  EXPECT_EQ(a.positional(), (Words{"x"}));
}

TEST(Args, NumbersAreCheckedWithTheOptionNamed) {
  const OptionSpec spec = {.valued = {"--timeout", "--seed"}};
  EXPECT_EQ(parse({"--timeout", "0.5"}, spec).seconds("--timeout"), 0.5);
  EXPECT_FALSE(parse({}, spec).seconds("--timeout"));
  for (const char* bad : {"0", "-1", "x", "1s", "nan", "inf", ""}) {
    try {
      (void)parse({"--timeout", bad}, spec).seconds("--timeout");
      ADD_FAILURE() << bad;
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("'--timeout' takes a number of seconds > 0"), std::string::npos);
    }
  }
  EXPECT_EQ(parse({"--seed", "0x10"}, spec).seed("--seed", 1), 16u);
  EXPECT_EQ(parse({}, spec).seed("--seed", 7), 7u);
  EXPECT_THROW((void)parse({"--seed", "-3"}, spec).seed("--seed", 1), UsageError);
}

TEST(Args, AMisspeltOptionOrAMissingValueIsAnError) {
  EXPECT_THROW(parse({"--algoo", "a"}, kWithFiles), UsageError);
  EXPECT_THROW(parse({"--algo"}, kWithFiles), UsageError);
  EXPECT_THROW(parse({"--quiet=1"}, kWithFiles), UsageError);
}

}  // namespace
