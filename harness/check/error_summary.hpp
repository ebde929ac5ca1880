// The segment level's errors, summarised so that summaries of parts of a run add up to exactly
// the summary of the whole run (`tritri merge`, harness/check/merge.hpp) in memory that does not
// grow with the number of cases.
//
// Up to kExactErrors errors are kept, sorted: the median is then the exact one. Beyond that the
// errors are counted in a histogram of kBinsPerOctave bins per power of two (a bin is the
// double's sign, exponent and top mantissa bits), and the median is the lower edge of the bin
// holding it: within a factor 1 + 1/kBinsPerOctave of the true one. Either form is a function
// of the multiset of errors alone, so it does not depend on how the cases were split.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tritri {

class ErrorSummary {
 public:
  static constexpr std::size_t kExactErrors = 512;
  static constexpr int kBinsPerOctave = 64;

  void add(double error);
  void add(const ErrorSummary& other);

  std::size_t count() const { return count_; }
  double median() const;  // NaN when empty
  double max() const;     // NaN when empty; always exact
  const std::vector<double>& sample() const { return sample_; }  // sorted; empty once binned

  // {"sample": [...]} or {"histogram": [[lower edge, count], ...]}: what merge reads back.
  nlohmann::json to_json() const;
  // Throws std::invalid_argument naming what is malformed.
  static ErrorSummary from_json(const nlohmann::json& j, std::size_t count, double max);

 private:
  void bin(double error, std::uint64_t n);
  void spill();  // the sample becomes histogram counts

  std::size_t count_ = 0;
  double max_ = 0;
  std::vector<double> sample_;
  std::map<std::uint64_t, std::uint64_t> histogram_;  // bin key -> errors
};

}  // namespace tritri
