#include "cases/case_stream.hpp"

#include "cases/util/random.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>

namespace tritri {
namespace {

bool is_case_line(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  return first != std::string::npos && text[first] != '#';
}

void open_case_file(std::ifstream& in, const std::string& path) {
  if (std::filesystem::is_directory(path)) throw CaseFileError(path, 0, "is a directory, not a case file");
  in.open(path);
  if (!in) throw CaseFileError(path, 0, "cannot open for reading");
}

}  // namespace

CaseRange shard_range(std::size_t k, std::size_t n, std::size_t total) {
  // (total * k) / n without overflow for any total below 2^64 / n.
  auto edge = [&](std::size_t j) { return static_cast<std::size_t>((static_cast<unsigned __int128>(total) * j) / n); };
  return {edge(k), edge(k + 1)};
}

std::uint64_t CaseNames::hash(std::string_view name) { return splitmix(fnv1a(name)) | 1; }  // never 0
void CaseNames::add(std::string_view name) { hashes_.push_back(hash(name)); }
void CaseNames::seal() { std::sort(hashes_.begin(), hashes_.end()); }
bool CaseNames::contains(std::string_view name) const {
  return std::binary_search(hashes_.begin(), hashes_.end(), hash(name));
}
std::uint64_t CaseNames::duplicate() const {
  const auto it = std::adjacent_find(hashes_.begin(), hashes_.end());
  return it == hashes_.end() ? 0 : *it;
}

CaseStream::CaseStream(std::vector<std::string> files, CaseRange range) : files_(std::move(files)), range_(range) {}

bool CaseStream::open_next_file() {
  if (in_.is_open()) in_.close();
  if (file_ == files_.size()) return false;
  in_.clear();
  open_case_file(in_, files_[file_++]);
  line_ = 0;
  return true;
}

bool CaseStream::next(std::vector<Case>& out, std::size_t max) {
  out.clear();
  if (done_) return false;
  if (!read(out, max)) finish();
  return !out.empty();
}

bool CaseStream::read(std::vector<Case>& out, std::size_t max) {
  out.clear();
  std::string text;
  while (out.size() < max && index_ < range_.end) {
    if (!in_.is_open() || !std::getline(in_, text)) {
      if (in_.is_open() && in_.bad()) throw CaseFileError(files_[file_ - 1], line_, "read error");
      if (!open_next_file()) break;
      continue;
    }
    ++line_;
    if (!is_case_line(text)) continue;
    if (index_++ < range_.first) continue;
    if (out.empty()) first_ = index_ - 1;
    out.push_back(parse_case_line(text, files_[file_ - 1], line_));
    names_.add(out.back().name);
  }
  return !out.empty();
}

// Names a case name used twice: the cases whose names share the duplicated hash are found by
// reading the range again (only on this error path, so the names need not be kept).
void CaseStream::finish() {
  done_ = true;
  if (index_ == 0) {
    std::string names;
    for (const auto& f : files_) names += (names.empty() ? "" : ", ") + f;
    throw InputError("no cases in " + names + " (every line is blank or a comment)");
  }
  names_.seal();
  const std::uint64_t twice = names_.duplicate();
  if (!twice) return;
  CaseStream again(files_, range_);
  std::vector<Case> chunk;
  std::optional<Case> earlier;
  while (again.read(chunk, 4096))
    for (Case& c : chunk) {
      if (CaseNames::hash(c.name) != twice) continue;
      if (!earlier) earlier = std::move(c);
      else if (earlier->name == c.name && earlier->source == c.source)
        throw CaseFileError(c.source, c.line, "duplicate case name '" + c.name + "'");
      else if (earlier->name == c.name)
        throw CaseFileError(c.source, c.line, "case name '" + c.name + "' is already used at " + earlier->source + ":" +
                                                  std::to_string(earlier->line));
    }
}

std::size_t count_cases(const std::vector<std::string>& files) {
  std::size_t n = 0;
  for (const auto& path : files) {
    std::ifstream in;
    open_case_file(in, path);
    std::string text;
    while (std::getline(in, text)) n += is_case_line(text);
    if (in.bad()) throw CaseFileError(path, 0, "read error");
  }
  return n;
}

}  // namespace tritri
