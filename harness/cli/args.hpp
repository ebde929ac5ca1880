// A small command-line parser: options are declared up front, so a misspelt option is an error
// rather than a silently ignored word.
#pragma once

#include "cases/util/input_error.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace tritri::cli {

// A usage error: printed with the command's name and a pointer to --help; exit status 2, as for
// every InputError.
struct UsageError : InputError {
  using InputError::InputError;
};

// What a command accepts. Every command also accepts --help.
struct OptionSpec {
  std::set<std::string> valued = {};  // one value per flag: --json OUT or --json=OUT; repeatable, values() has all
  std::set<std::string> lists = {};   // a list, in any mix of the forms kListsHelp gives
  std::set<std::string> word_lists = {};  // a list whose items may hold commas (--group-by KEY,KEY): not split
  std::set<std::string> flags = {};       // no value
  bool operands = true;  // the command takes operands (files): a list then takes one word per flag
};

OptionSpec merged(OptionSpec a, const OptionSpec& b);

// The one description of list options, printed in the --help of every command that has one.
extern const char* const kListsHelp;

class Args {
 public:
  Args(int argc, char** argv, const OptionSpec& spec);

  bool help() const { return flag("--help"); }
  bool flag(const std::string& name) const { return flags_.count(name) > 0; }
  // Every value given, in order; a list option's items one by one.
  std::vector<std::string> values(const std::string& name) const;
  std::optional<std::string> value(const std::string& name) const;  // the last one given
  const std::vector<std::string>& positional() const { return positional_; }

  // Reads an option as a non-negative count, with a clear error for anything else.
  std::size_t count(const std::string& name, std::size_t fallback) const;
  // Reads an option as a number of seconds > 0 (--timeout, --min-time); nullopt when not given.
  std::optional<double> seconds(const std::string& name) const;
  // Reads an option as a random seed: a whole number >= 0, decimal or 0x hex.
  std::uint64_t seed(const std::string& name, std::uint64_t fallback) const;

 private:
  void add_value(const OptionSpec& spec, const std::string& name, const std::string& value);

  std::vector<std::string> positional_;
  std::multimap<std::string, std::string> values_;
  std::set<std::string> flags_;
};

}  // namespace tritri::cli
