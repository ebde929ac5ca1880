#include "args.hpp"
#include "commands.hpp"

#include <map>

namespace tritri::cli {

std::vector<Case> load_cases(const std::vector<std::string>& files) {
  if (files.empty()) throw UsageError("no case file given (the built-in cases are cases/builtin.cases)");
  std::vector<Case> all;
  std::map<std::string, std::pair<std::string, int>> seen;
  for (const auto& file : files) {
    for (auto& c : read_case_file(file)) {
      auto [it, inserted] = seen.emplace(c.name, std::pair{c.source, c.line});
      if (!inserted)
        throw CaseFileError(c.source, c.line,
                            "case name '" + c.name + "' is already used at " + it->second.first + ":" +
                                std::to_string(it->second.second));
      all.push_back(std::move(c));
    }
  }
  if (all.empty()) {
    std::string names;
    for (const auto& f : files) names += (names.empty() ? "" : ", ") + f;
    throw UsageError("no cases in " + names + " (every line is blank or a comment)");
  }
  return all;
}

std::string vec_text(const Vec3<double>& v) {
  return format_double(v.x()) + "," + format_double(v.y()) + "," + format_double(v.z());
}

std::string segment_text(const SegmentAnswer& s) {
  switch (s.kind) {
    case SegmentKind::point: return vec_text(s.p);
    case SegmentKind::segment: return vec_text(s.p) + ";" + vec_text(s.q);
    default: return std::string(to_string(s.kind));
  }
}

}  // namespace tritri::cli
