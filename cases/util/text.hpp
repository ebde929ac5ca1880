// Text helpers: the one tokenizer of tritri (case files, the process-plug-in protocol, baseline
// files) and the one way hashes are written.
#pragma once

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace tritri {

// A 64-bit hash as 16 lower-case hex digits, the way hashes appear in names and JSON.
inline std::string hex64(std::uint64_t x) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(x));
  return buf;
}

// A positive count written in at most `max_digits` decimal digits ("4096"); 0 for anything else
// (empty, a sign, a letter, too many digits), which every caller reports as its own usage error.
inline std::size_t positive_count(std::string_view text, std::size_t max_digits) {
  if (text.empty() || text.size() > max_digits) return 0;
  std::size_t n = 0;
  for (char c : text) {
    if (c < '0' || c > '9') return 0;
    n = n * 10 + static_cast<std::size_t>(c - '0');
  }
  return n;
}

// Fields of `text` split at `separator`, empty fields kept: "a\t\tb" is {"a", "", "b"}.
inline std::vector<std::string_view> split_fields(std::string_view text, char separator) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (;;) {
    const std::size_t at = text.find(separator, start);
    fields.push_back(text.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start));
    if (at == std::string_view::npos) return fields;
    start = at + 1;
  }
}

// Words of `text` separated by runs of white space; none empty.
inline std::vector<std::string_view> split_words(std::string_view text) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    const std::size_t start = i;
    while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i > start) words.push_back(text.substr(start, i - start));
  }
  return words;
}

}  // namespace tritri
