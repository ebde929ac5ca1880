#include "cases/casefile.hpp"

#include "cases/util/text.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <istream>
#include <ostream>
#include <set>

namespace tritri {
namespace {


constexpr const char* kCoordinateNames[18] = {
    "T1.a.x", "T1.a.y", "T1.a.z", "T1.b.x", "T1.b.y", "T1.b.z", "T1.c.x", "T1.c.y", "T1.c.z",
    "T2.a.x", "T2.a.y", "T2.a.z", "T2.b.x", "T2.b.y", "T2.b.z", "T2.c.x", "T2.c.y", "T2.c.z"};

double parse_coordinate(std::string_view token, int index, const std::string& file, int line) {
  const std::string text(token);
  const std::string where = std::string("coordinate ") + std::to_string(index + 1) + " (" +
                            kCoordinateNames[index] + ") '" + text + "'";
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0') throw CaseFileError(file, line, where + " is not a number");
  if (std::isnan(value)) throw CaseFileError(file, line, where + " is NaN");
  if (std::isinf(value)) {
    const bool written_as_infinity = text.find_first_of("iI") != std::string::npos;
    throw CaseFileError(file, line,
                        where + (written_as_infinity ? " is infinite" : " overflows a double"));
  }
  // ERANGE on a finite result is underflow to a subnormal or zero: the nearest double is the
  // value the text denotes, which is what we keep.
  return value;
}

}  // namespace

CaseFileError::CaseFileError(std::string file, int line, std::string problem)
    : InputError(file + ":" + std::to_string(line) + ": " + problem),
      file_(std::move(file)),
      line_(line),
      problem_(std::move(problem)) {}

std::optional<std::string_view> Case::label(std::string_view key) const {
  for (const auto& [k, v] : labels)
    if (k == key) return std::string_view(v);
  return std::nullopt;
}

void Case::set_label(std::string_view key, std::string_view value) {
  for (auto& [k, v] : labels)
    if (k == key) {
      v = value;
      return;
    }
  labels.emplace_back(key, value);
}

std::string Case::family() const {
  if (auto f = label("family")) return std::string(*f);
  if (source.empty()) return "cases";
  return std::filesystem::path(source).stem().string();
}

Case parse_case_line(std::string_view text, const std::string& file, int line) {
  const auto tokens = split_words(text);
  std::size_t numbers = 0;
  while (1 + numbers < tokens.size() && tokens[1 + numbers].find('=') == std::string_view::npos)
    ++numbers;
  if (numbers != 18)
    throw CaseFileError(file, line,
                        "expected a name and 18 coordinates, found " + std::to_string(numbers) +
                            " coordinate" + (numbers == 1 ? "" : "s") + " after the name");
  if (tokens[0].find('=') != std::string_view::npos)
    throw CaseFileError(file, line, "the name '" + std::string(tokens[0]) + "' contains '='");

  Case c;
  c.name = tokens[0];
  c.source = file;
  c.line = line;
  double xyz[18];
  for (int i = 0; i < 18; ++i) xyz[i] = parse_coordinate(tokens[1 + i], i, file, line);
  for (int v = 0; v < 3; ++v) {
    c.pair.t1[v] = {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]};
    c.pair.t2[v] = {xyz[9 + 3 * v], xyz[9 + 3 * v + 1], xyz[9 + 3 * v + 2]};
  }
  for (std::size_t i = 19; i < tokens.size(); ++i) {
    const auto eq = tokens[i].find('=');
    if (eq == std::string_view::npos)
      throw CaseFileError(file, line, "label '" + std::string(tokens[i]) + "' is not key=value");
    if (eq == 0) throw CaseFileError(file, line, "label '" + std::string(tokens[i]) + "' has no key");
    c.labels.emplace_back(tokens[i].substr(0, eq), tokens[i].substr(eq + 1));
  }
  return c;
}

std::vector<Case> read_cases(std::istream& in, const std::string& file_name) {
  std::vector<Case> cases;
  std::string text;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos || text[first] == '#') continue;
    cases.push_back(parse_case_line(text, file_name, line));
  }
  if (in.bad()) throw CaseFileError(file_name, line, "read error");
  return cases;
}

std::vector<Case> read_case_file(const std::string& path) {
  if (std::filesystem::is_directory(path)) throw CaseFileError(path, 0, "is a directory, not a case file");
  std::ifstream in(path);
  if (!in) throw CaseFileError(path, 0, "cannot open for reading");
  auto cases = read_cases(in, path);
  std::set<std::string_view> seen;
  for (const auto& c : cases)
    if (!seen.insert(c.name).second)
      throw CaseFileError(path, c.line, "duplicate case name '" + c.name + "'");
  return cases;
}

std::string format_double(double x) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

std::string format_hex(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%a", x);
  return buffer;
}

std::string format_g17(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string format_case(const Case& c, NumberStyle style) {
  std::string out = c.name;
  auto put = [&](double x) {
    out += ' ';
    out += style == NumberStyle::hex ? format_hex(x)
           : style == NumberStyle::g17 ? format_g17(x)
                                       : format_double(x);
  };
  for (const auto* t : {&c.pair.t1, &c.pair.t2})
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 3; ++k) put((*t)[v][k]);
  for (const auto& [k, v] : c.labels) out += ' ' + k + '=' + v;
  return out;
}

void write_cases(std::ostream& out, const std::vector<Case>& cases) {
  for (const auto& c : cases) out << format_case(c) << '\n';
}

}  // namespace tritri
