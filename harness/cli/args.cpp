#include "harness/cli/args.hpp"

#include <cerrno>
#include <cmath>
#include <algorithm>
#include <cstdlib>

namespace tritri::cli {

OptionSpec merged(OptionSpec a, const OptionSpec& b) {
  a.valued.insert(b.valued.begin(), b.valued.end());
  a.lists.insert(b.lists.begin(), b.lists.end());
  a.word_lists.insert(b.word_lists.begin(), b.word_lists.end());
  a.flags.insert(b.flags.begin(), b.flags.end());
  return a;
}

const char* const kListsHelp =
    "An option shown with '...' takes a list: a comma list (--algo a,b), the option repeated\n"
    "(--algo a --algo b), and, in a command that takes no FILE operands, several values after\n"
    "one flag up to the next option (--cases corpus/*.cases). --group-by's items hold commas\n"
    "themselves, so it is not split on them.\n";

namespace {

bool is_option(const std::string& word) { return word.size() > 1 && word[0] == '-' && word != "-"; }

}  // namespace

void Args::add_value(const OptionSpec& spec, const std::string& name, const std::string& value) {
  if (!spec.lists.count(name)) {
    values_.emplace(name, value);
    return;
  }
  std::size_t start = 0;
  while (start <= value.size()) {
    const std::size_t comma = std::min(value.find(',', start), value.size());
    if (comma > start) values_.emplace(name, value.substr(start, comma - start));
    start = comma + 1;
  }
}

Args::Args(int argc, char** argv, const OptionSpec& spec) {
  bool only_positional = false;
  for (int i = 0; i < argc; ++i) {
    std::string word = argv[i];
    if (only_positional || word.size() < 2 || word.rfind("--", 0) != 0) {
      if (!only_positional && is_option(word)) throw UsageError("unknown option '" + word + "'");
      positional_.push_back(word);
      continue;
    }
    if (word == "--") {
      only_positional = true;
      continue;
    }
    std::string name = word, value;
    bool has_value = false;
    if (auto eq = word.find('='); eq != std::string::npos) {
      name = word.substr(0, eq);
      value = word.substr(eq + 1);
      has_value = true;
    }
    const bool list = spec.lists.count(name) || spec.word_lists.count(name);
    if (name == "--help" || spec.flags.count(name)) {
      if (has_value) throw UsageError("option '" + name + "' takes no value");
      flags_.insert(name);
    } else if (list || spec.valued.count(name)) {
      if (!has_value) {
        if (i + 1 >= argc) throw UsageError("option '" + name + "' needs a value");
        value = argv[++i];
      }
      add_value(spec, name, value);
      // Without operands, the words up to the next option are more items of the list.
      while (list && !spec.operands && i + 1 < argc && !is_option(argv[i + 1])) add_value(spec, name, argv[++i]);
    } else {
      throw UsageError("unknown option '" + name + "'");
    }
  }
}

std::vector<std::string> Args::values(const std::string& name) const {
  std::vector<std::string> out;
  auto [begin, end] = values_.equal_range(name);
  for (auto it = begin; it != end; ++it) out.push_back(it->second);
  return out;
}

std::optional<std::string> Args::value(const std::string& name) const {
  auto all = values(name);
  if (all.empty()) return std::nullopt;
  return all.back();
}

std::size_t Args::count(const std::string& name, std::size_t fallback) const {
  auto text = value(name);
  if (!text) return fallback;
  errno = 0;
  char* end = nullptr;
  const long long n = std::strtoll(text->c_str(), &end, 10);
  if (text->empty() || *end != '\0' || errno != 0 || n < 0)
    throw UsageError("option '" + name + "' takes a whole number >= 0, not '" + *text + "'");
  return static_cast<std::size_t>(n);
}

std::optional<double> Args::seconds(const std::string& name) const {
  auto text = value(name);
  if (!text) return std::nullopt;
  char* end = nullptr;
  const double s = std::strtod(text->c_str(), &end);
  if (end == text->c_str() || *end != '\0' || !(s > 0) || !std::isfinite(s))
    throw UsageError("option '" + name + "' takes a number of seconds > 0, not '" + *text + "'");
  return s;
}

std::uint64_t Args::seed(const std::string& name, std::uint64_t fallback) const {
  auto text = value(name);
  if (!text) return fallback;
  std::size_t used = 0;
  unsigned long long seed = 0;
  try {
    seed = std::stoull(*text, &used, 0);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text->size() || (*text)[0] == '-')
    throw UsageError("option '" + name + "' takes a whole number >= 0 (decimal or 0x hex), not '" + *text + "'");
  return seed;
}

}  // namespace tritri::cli
