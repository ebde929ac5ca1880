// The one median and spread of tritri (bench tables, compare, segment errors).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace tritri {

// The middle value (the mean of the two middle ones for an even count); NaN when empty.
inline double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t k = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  const double upper = v[k];
  if (v.size() % 2) return upper;
  const double lower = *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k));
  return (lower + upper) / 2;
}

// max/min - 1 of repeated measurements; NaN with fewer than two.
inline double spread(const std::vector<double>& v) {
  if (v.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *hi / *lo - 1;
}

}  // namespace tritri
