// Case files read a chunk at a time, so that a command's memory does not grow with the number of
// cases (a 10^7-case file is 3.5 GB of text). The cases are numbered across the files in order;
// a range of those numbers is what a shard of a campaign reads (`--shard K/N`, shard_range).
#pragma once

#include "cases/casefile.hpp"

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace tritri {

// Cases [first, end) of the whole input.
struct CaseRange {
  std::size_t first = 0;
  std::size_t end = std::numeric_limits<std::size_t>::max();
};

// Shard k of n (0 <= k < n) of `total` cases: a contiguous range, the n ranges tiling [0, total)
// in order, so the shards' results concatenated in order are the whole run's.
CaseRange shard_range(std::size_t k, std::size_t n, std::size_t total);

// The names read, as 64-bit hashes (8 bytes a case): membership and duplicates without keeping
// the names themselves.
class CaseNames {
 public:
  void add(std::string_view name);
  void seal();  // sorts; call before contains() and duplicate()
  bool contains(std::string_view name) const;
  // A hash that two names share, or 0 when the names are distinct (after seal()).
  std::uint64_t duplicate() const;
  static std::uint64_t hash(std::string_view name);

 private:
  std::vector<std::uint64_t> hashes_;
};

// Reads the cases of `range` from `files`, in order. Each line is parsed only when it is in the
// range; the lines before it are only counted. Errors are CaseFileError, as read_case_file's.
class CaseStream {
 public:
  CaseStream(std::vector<std::string> files, CaseRange range = {});

  // Up to `max` next cases into `out` (replacing its contents); false when none are left. At
  // the end, throws CaseFileError naming a case name used twice in the range, and UsageError-
  // style InputError when the files hold no case at all.
  bool next(std::vector<Case>& out, std::size_t max);
  std::size_t first() const { return first_; }  // the number in the input of the last chunk's first case
  // The names read: complete and sealed once next() has returned false; taken, not copied.
  CaseNames take_names() { return std::move(names_); }

 private:
  bool open_next_file();
  bool read(std::vector<Case>& out, std::size_t max);  // next() without the checks at the end
  void finish();

  std::vector<std::string> files_;
  CaseRange range_;
  std::size_t file_ = 0;  // the file being read is files_[file_ - 1]
  std::ifstream in_;
  int line_ = 0;
  std::size_t index_ = 0;  // the number of the next case line
  std::size_t first_ = 0;
  bool done_ = false;
  CaseNames names_;
};

// The number of cases in `files`: lines that are neither blank nor comments, unparsed.
std::size_t count_cases(const std::vector<std::string>& files);

}  // namespace tritri
