// `tritri compare A.json B.json`: what changed between two runs.
//
// Two check results (schema tritri-check/*): per algorithm × family, the change in each error
// count. Two benchmark results (Google Benchmark's JSON): per benchmark, the ratio of B's median
// time per item to A's, and whether the difference is significant by a two-sided Mann–Whitney U
// test over the repetitions (as Google Benchmark's own comparison tool does); then the
// geometric mean of the ratios.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace tritri {

struct UTest {
  double u = 0;        // the smaller of U_a and U_b
  double p_value = 1;  // two-sided
  bool exact = false;  // from the exact distribution (small samples, no ties), else normal approximation
};

// Two-sided Mann–Whitney U test of `a` against `b`.
UTest mann_whitney(const std::vector<double>& a, const std::vector<double>& b);

struct TimeComparison {
  std::string name;
  std::size_t repetitions_a = 0, repetitions_b = 0;
  double median_a = 0, median_b = 0;  // seconds per item (or per iteration without item counts)
  double ratio = 1;                   // median_b / median_a
  UTest test;
  bool significant = false;  // p < alpha
  bool counts = false;       // significant and beyond min_change: a real slowdown or speed-up
};

struct CompareOptions {
  double alpha = 0.05;          // significance level
  // A significant change smaller than this (as a fraction of A's median) does not count: runs
  // minutes apart drift by a percent or so, and nine repetitions are enough to detect that.
  double min_change = 0.02;
  std::size_t min_repetitions = 3;  // fewer on either side: no test, never significant
};

// Throws InputError naming the file if it is not a result tritri can compare.
std::vector<TimeComparison> compare_benchmarks(const std::string& a_path, const std::string& b_path,
                                               const CompareOptions& options);

// Prints the comparison of two result files of either kind; returns true if anything changed
// for the worse (a new error, or a significant slowdown).
bool print_comparison(std::ostream& out, const std::string& a_path, const std::string& b_path,
                      const CompareOptions& options);

}  // namespace tritri
