// Case files: one triangle pair per line, plain text, so any tool in any language can read and
// write them.
//
//   # comments and blank lines are ignored
//   name ax ay az bx by bz cx cy cz px py pz qx qy qz rx ry rz [key=value ...]
//
// The 18 numbers are anything strtod reads (decimal, exponent, hex float). NaN and infinities are
// rejected. Labels follow as key=value tokens; unknown keys are kept. The reader stops at the
// first bad line with the file, the line and what is wrong; the writer emits the shortest decimal
// that reads back to the same bits, so a written file round-trips exactly.
#pragma once

#include "tritri/geometry.hpp"

#include "cases/util/input_error.hpp"

#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tritri {

struct Case {
  std::string name;
  TrianglePair pair;
  std::vector<std::pair<std::string, std::string>> labels;  // in file order
  std::string source;  // file it came from ("" when built in memory)
  int line = 0;        // 1-based line in that file

  std::optional<std::string_view> label(std::string_view key) const;
  void set_label(std::string_view key, std::string_view value);
  // The family= label, else the stem of the file the case came from.
  std::string family() const;
};

class CaseFileError : public InputError {
 public:
  CaseFileError(std::string file, int line, std::string problem);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_;
  int line_;
  std::string problem_;
};

// Parses one non-comment line. Throws CaseFileError (with `file` and `line`) on a bad line.
Case parse_case_line(std::string_view text, const std::string& file, int line);

std::vector<Case> read_cases(std::istream& in, const std::string& file_name);
std::vector<Case> read_case_file(const std::string& path);  // also rejects duplicate names

// cases/builtin.cases, compiled into the library.
std::vector<Case> builtin_cases();

// Shortest decimal that strtod reads back to exactly `x` ("-0" for negative zero).
std::string format_double(double x);
// C99 hex float, e.g. 0x1.8p+1.
std::string format_hex(double x);
// "%.17g".
std::string format_g17(double x);

enum class NumberStyle { shortest, g17, hex };
std::string format_case(const Case& c, NumberStyle style = NumberStyle::shortest);
void write_cases(std::ostream& out, const std::vector<Case>& cases);

}  // namespace tritri
