#include "harness/check/error_summary.hpp"

#include "cases/util/stats.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace tritri {
namespace {

constexpr int kShift = 52 - std::countr_zero(static_cast<unsigned>(ErrorSummary::kBinsPerOctave));

std::uint64_t key_of(double x) { return std::bit_cast<std::uint64_t>(x) >> kShift; }
double lower_edge(std::uint64_t key) { return std::bit_cast<double>(key << kShift); }

}  // namespace

void ErrorSummary::bin(double error, std::uint64_t n) { histogram_[key_of(error)] += n; }

void ErrorSummary::spill() {
  for (double e : sample_) bin(e, 1);
  sample_.clear();
  sample_.shrink_to_fit();
}

void ErrorSummary::add(double error) {
  if (!(error >= 0)) error = 0;  // a distance: never negative, and NaN would poison the order
  max_ = count_ ? std::max(max_, error) : error;
  ++count_;
  if (count_ <= kExactErrors) {
    sample_.insert(std::upper_bound(sample_.begin(), sample_.end(), error), error);
    return;
  }
  if (!sample_.empty()) spill();
  bin(error, 1);
}

void ErrorSummary::add(const ErrorSummary& other) {
  if (!other.count_) return;
  max_ = count_ ? std::max(max_, other.max_) : other.max_;
  count_ += other.count_;
  if (count_ <= kExactErrors) {
    std::vector<double> merged(sample_.size() + other.sample_.size());
    std::merge(sample_.begin(), sample_.end(), other.sample_.begin(), other.sample_.end(), merged.begin());
    sample_ = std::move(merged);
    return;
  }
  spill();
  for (double e : other.sample_) bin(e, 1);
  for (const auto& [key, n] : other.histogram_) histogram_[key] += n;
}

double ErrorSummary::median() const {
  if (!count_) return std::numeric_limits<double>::quiet_NaN();
  if (histogram_.empty()) return tritri::median(sample_);
  const std::uint64_t middle = count_ / 2;  // the upper middle, as median() takes it
  std::uint64_t seen = 0;
  for (const auto& [key, n] : histogram_) {
    seen += n;
    if (seen > middle) return lower_edge(key);
  }
  return lower_edge(histogram_.rbegin()->first);
}

double ErrorSummary::max() const { return count_ ? max_ : std::numeric_limits<double>::quiet_NaN(); }

nlohmann::json ErrorSummary::to_json() const {
  if (histogram_.empty()) return {{"sample", sample_}};
  nlohmann::json bins = nlohmann::json::array();
  for (const auto& [key, n] : histogram_) bins.push_back({lower_edge(key), n});
  return {{"histogram", bins}};
}

ErrorSummary ErrorSummary::from_json(const nlohmann::json& j, std::size_t count, double max) {
  ErrorSummary s;
  s.count_ = count;
  s.max_ = count ? max : 0;
  std::uint64_t total = 0;
  if (j.is_object() && j.contains("sample") && j["sample"].is_array()) {
    s.sample_ = j["sample"].get<std::vector<double>>();
    if (!std::is_sorted(s.sample_.begin(), s.sample_.end())) throw std::invalid_argument("errors.sample is not sorted");
    total = s.sample_.size();
  } else if (j.is_object() && j.contains("histogram") && j["histogram"].is_array()) {
    for (const auto& b : j["histogram"]) {
      if (!b.is_array() || b.size() != 2) throw std::invalid_argument("errors.histogram: a bin is not [edge, count]");
      const double edge = b[0].get<double>();
      if (lower_edge(key_of(edge)) != edge) throw std::invalid_argument("errors.histogram: " + b[0].dump() + " is no bin edge");
      s.histogram_[key_of(edge)] += b[1].get<std::uint64_t>();
      total += b[1].get<std::uint64_t>();
    }
  } else {
    throw std::invalid_argument("errors is neither {\"sample\"} nor {\"histogram\"}");
  }
  if (total != count) throw std::invalid_argument("errors hold " + std::to_string(total) + " errors, measured says " + std::to_string(count));
  return s;
}

}  // namespace tritri
