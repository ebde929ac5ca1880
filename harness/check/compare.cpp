#include "harness/check/compare.hpp"
#include "cases/util/input_error.hpp"

#include "cases/util/stats.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <numeric>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace tritri {
namespace {

using Json = nlohmann::json;

Json read_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open for reading");
  try {
    return Json::parse(in);
  } catch (const std::exception& e) {
    throw InputError(path + ": not valid JSON (" + e.what() + ")");
  }
}

enum class Kind { check, bench };

// The versions this comparison reads. A check result of another version, or a benchmark file
// whose tritri section names another, is refused rather than read with its counts as zeros.
// Plain Google Benchmark JSON (no tritri section) has no version of its own and is read as is.
// Both are documented with their keys: harness/README.md and harness/bench/README.md.
// A bench file of version 1 timed every benchmark in batch mode, under a name without the mode.
// Version 3 (tritri merge) added keys only: the tallies compare reads are version 2's.
constexpr const char* kCheckSchemas[] = {"tritri-check/2", "tritri-check/3"};
constexpr const char* kBenchSchemas[] = {"tritri-bench/1", "tritri-bench/2"};

// object[key], or an error naming the file and the key's path (`where` is the path up to it).
const Json& required(const Json& object, const char* key, const std::string& where, const std::string& path) {
  if (!object.is_object() || !object.contains(key))
    throw InputError(path + ": missing required key " + where + key);
  return object[key];
}

template <std::size_t N>
void expect_schema(const Json& schema, const char* const (&understood)[N], const std::string& where,
                   const std::string& path) {
  std::string names;
  for (const char* u : understood) {
    if (schema.is_string() && schema.get<std::string>() == u) return;
    names += (names.empty() ? "" : " or ") + std::string(u);
  }
  throw InputError(path + ": " + where + " is " + schema.dump() + "; tritri compare reads " + names);
}

Kind kind_of(const Json& doc, const std::string& path) {
  if (doc.is_object() && doc.contains("schema") && doc["schema"].is_string() &&
      doc["schema"].get<std::string>().rfind("tritri-check/", 0) == 0) {
    expect_schema(doc["schema"], kCheckSchemas, "schema", path);
    return Kind::check;
  }
  if (doc.is_object() && doc.contains("benchmarks") && doc["benchmarks"].is_array()) {
    if (doc.contains("tritri")) expect_schema(required(doc["tritri"], "schema", "tritri.", path), kBenchSchemas,
                                              "tritri.schema", path);
    return Kind::bench;
  }
  throw InputError(path + ": neither a 'tritri check --json' result nor a benchmark result");
}

// A `tritri bench` file from before the mode was an axis (tritri.schema tritri-bench/1)
// timed every benchmark in batch mode, under a name without the mode: named as now, it is compared
// with the batch-mode benchmarks of a newer file, and with nothing timed one pair per call.
std::string name_with_mode(const Json& doc, const std::string& name) {
  const bool before_modes = doc.contains("tritri") && doc["tritri"].value("schema", "") == kBenchSchemas[0];
  return before_modes ? name + "/batch" : name;
}

// Per benchmark, the time per item of every repetition, in seconds.
std::map<std::string, std::vector<double>> repetitions(const Json& doc, const std::string& path) {
  std::map<std::string, std::vector<double>> out;
  static const std::map<std::string, double> kUnit = {{"ns", 1e-9}, {"us", 1e-6}, {"ms", 1e-3}, {"s", 1.0}};
  std::size_t index = 0;
  for (const auto& b : doc["benchmarks"]) {
    const std::string where = "benchmarks[" + std::to_string(index++) + "].";
    if (b.value("run_type", "iteration") != "iteration") continue;
    if (b.contains("error_occurred") && b["error_occurred"].get<bool>()) continue;
    const std::string name = name_with_mode(doc, b.contains("run_name") ? b["run_name"].get<std::string>()
                                                                        : required(b, "name", where, path).get<std::string>());
    double seconds;
    if (b.contains("items_per_second") && b["items_per_second"].get<double>() > 0) {
      seconds = 1.0 / b["items_per_second"].get<double>();
    } else {
      const auto unit = kUnit.find(b.value("time_unit", "ns"));
      const double scale = unit == kUnit.end() ? 1e-9 : unit->second;
      seconds = required(b, "real_time", where, path).get<double>() * scale;
    }
    out[name].push_back(seconds);
  }
  return out;
}

// The exact null distribution of U (the number of pairs (a, b) with a > b) for samples of
// sizes n and m without ties: every interleaving of the two samples is equally likely, and the
// largest element is either an a, which adds m to U, or a b, which adds nothing.
std::vector<double> u_distribution(std::size_t n, std::size_t m) {
  // count[i][j][u]: interleavings of i a's and j b's with U = u.
  const std::size_t max_u = n * m;
  std::vector<std::vector<std::vector<double>>> count(n + 1, std::vector<std::vector<double>>(m + 1));
  for (std::size_t i = 0; i <= n; ++i)
    for (std::size_t j = 0; j <= m; ++j) {
      count[i][j].assign(i * j + 1, 0.0);
      if (i == 0 || j == 0) {
        count[i][j][0] = 1.0;
        continue;
      }
      for (std::size_t u = 0; u <= (i - 1) * j; ++u) count[i][j][u + j] += count[i - 1][j][u];
      for (std::size_t u = 0; u <= i * (j - 1); ++u) count[i][j][u] += count[i][j - 1][u];
    }
  std::vector<double> p(max_u + 1);
  const double total = std::accumulate(count[n][m].begin(), count[n][m].end(), 0.0);
  for (std::size_t u = 0; u <= max_u; ++u) p[u] = count[n][m][u] / total;
  return p;
}

std::string signed_count(long long d) { return d > 0 ? "+" + std::to_string(d) : std::to_string(d); }

bool print_check_comparison(std::ostream& out, const Json& a, const Json& b, const std::string& a_path,
                            const std::string& b_path) {
  struct Counts {
    long long v[6] = {0, 0, 0, 0, 0, 0};
  };
  static const char* kFields[6] = {"false_positives", "false_negatives", "misclassified",
                                   "unsupported", "crashes", "timeouts"};
  static const char* kShort[6] = {"FP", "FN", "relation", "unsupported", "crash", "timeout"};
  auto tallies = [](const Json& doc, const std::string& path) {
    std::map<std::pair<std::string, std::string>, Counts> t;
    std::size_t index = 0;
    for (const auto& row : required(doc, "tallies", "", path)) {
      const std::string where = "tallies[" + std::to_string(index++) + "].";
      Counts c;
      for (int k = 0; k < 6; ++k)  // misclassified is null for an algorithm without the relation level
        if (const Json& v = required(row, kFields[k], where, path); v.is_number()) c.v[k] = v.get<long long>();
      t[{required(row, "algorithm", where, path).get<std::string>(),
         required(row, "family", where, path).get<std::string>()}] = c;
    }
    return t;
  };
  const auto ta = tallies(a, a_path), tb = tallies(b, b_path);
  bool worse = false;
  out << "correctness: B against A, per algorithm x family (only rows that changed)\n";
  std::size_t changed = 0;
  for (const auto& [key, cb] : tb) {
    auto it = ta.find(key);
    if (it == ta.end()) {
      out << "  " << key.first << " / " << key.second << ": only in B\n";
      continue;
    }
    std::string deltas;
    for (int k = 0; k < 6; ++k) {
      const long long d = cb.v[k] - it->second.v[k];
      if (d == 0) continue;
      if (d > 0) worse = true;
      deltas += std::string("  ") + kShort[k] + " " + std::to_string(it->second.v[k]) + " -> " +
                std::to_string(cb.v[k]) + " (" + signed_count(d) + ")";
    }
    if (!deltas.empty()) {
      ++changed;
      out << "  " << key.first << " / " << key.second << ":" << deltas << '\n';
    }
  }
  for (const auto& [key, ca] : ta)
    if (!tb.count(key)) out << "  " << key.first << " / " << key.second << ": only in A\n";
  if (changed == 0) out << "  no change in any error count\n";
  return worse;
}

}  // namespace

UTest mann_whitney(const std::vector<double>& a, const std::vector<double>& b) {
  UTest t;
  const std::size_t n = a.size(), m = b.size();
  if (n == 0 || m == 0) return t;
  // ranks of the pooled sample, ties sharing their mean rank
  std::vector<std::pair<double, int>> pooled;
  for (double x : a) pooled.push_back({x, 0});
  for (double x : b) pooled.push_back({x, 1});
  std::sort(pooled.begin(), pooled.end());
  double rank_sum_a = 0, tie_term = 0;
  bool ties = false;
  for (std::size_t i = 0; i < pooled.size();) {
    std::size_t j = i;
    while (j < pooled.size() && pooled[j].first == pooled[i].first) ++j;
    const double rank = 0.5 * static_cast<double>(i + 1 + j);  // mean of ranks i+1 .. j
    const double size = static_cast<double>(j - i);
    if (j - i > 1) ties = true;
    tie_term += size * size * size - size;
    for (std::size_t k = i; k < j; ++k)
      if (pooled[k].second == 0) rank_sum_a += rank;
    i = j;
  }
  const double dn = static_cast<double>(n), dm = static_cast<double>(m);
  const double u_a = rank_sum_a - dn * (dn + 1) / 2;
  t.u = std::min(u_a, dn * dm - u_a);
  if (!ties && n <= 30 && m <= 30) {
    const auto p = u_distribution(n, m);
    double tail = 0;
    for (std::size_t u = 0; u <= static_cast<std::size_t>(t.u); ++u) tail += p[u];
    t.p_value = std::min(1.0, 2 * tail);
    t.exact = true;
    return t;
  }
  const double mean = dn * dm / 2;
  const double variance = dn * dm / 12 * ((dn + dm + 1) - tie_term / ((dn + dm) * (dn + dm - 1)));
  if (variance <= 0) return t;
  const double z = (std::abs(u_a - mean) - 0.5) / std::sqrt(variance);  // continuity correction
  t.p_value = std::min(1.0, std::erfc(std::max(0.0, z) / std::sqrt(2.0)));
  return t;
}

std::vector<TimeComparison> compare_benchmarks(const std::string& a_path, const std::string& b_path,
                                               const CompareOptions& options) {
  const Json a = read_json(a_path), b = read_json(b_path);
  if (kind_of(a, a_path) != Kind::bench) throw InputError(a_path + ": not a benchmark result");
  if (kind_of(b, b_path) != Kind::bench) throw InputError(b_path + ": not a benchmark result");
  const auto ra = repetitions(a, a_path), rb = repetitions(b, b_path);
  std::vector<TimeComparison> out;
  for (const auto& [name, times_b] : rb) {
    auto it = ra.find(name);
    if (it == ra.end()) continue;
    TimeComparison c;
    c.name = name;
    c.repetitions_a = it->second.size();
    c.repetitions_b = times_b.size();
    c.median_a = median(it->second);
    c.median_b = median(times_b);
    c.ratio = c.median_a > 0 ? c.median_b / c.median_a : 1.0;
    if (c.repetitions_a >= options.min_repetitions && c.repetitions_b >= options.min_repetitions) {
      c.test = mann_whitney(it->second, times_b);
      c.significant = c.test.p_value < options.alpha;
      c.counts = c.significant && std::abs(c.ratio - 1) >= options.min_change;
    }
    out.push_back(c);
  }
  return out;
}

bool print_comparison(std::ostream& out, const std::string& a_path, const std::string& b_path,
                      const CompareOptions& options) {
  const Json a = read_json(a_path), b = read_json(b_path);
  const Kind ka = kind_of(a, a_path), kb = kind_of(b, b_path);
  if (ka != kb) throw InputError("cannot compare a check result with a benchmark result");
  if (ka == Kind::check) return print_check_comparison(out, a, b, a_path, b_path);

  const auto rows = compare_benchmarks(a_path, b_path, options);
  if (rows.empty()) {
    out << "no benchmark is in both files\n";
    return false;
  }
  std::size_t width = 9;
  for (const auto& r : rows) width = std::max(width, r.name.size());
  out << std::left << std::setw(static_cast<int>(width)) << "benchmark" << std::right << std::setw(12)
      << "A ns/item" << std::setw(12) << "B ns/item" << std::setw(9) << "B/A" << std::setw(11) << "p-value"
      << "  verdict\n";
  bool worse = false;
  double log_sum = 0;
  for (const auto& r : rows) {
    log_sum += std::log(r.ratio);
    std::string verdict = "-";
    if (r.repetitions_a < options.min_repetitions || r.repetitions_b < options.min_repetitions)
      verdict = "too few repetitions to test";
    else if (r.counts)
      verdict = r.ratio > 1 ? "slower (significant)" : "faster (significant)";
    else if (r.significant)
      verdict = "significant but within " + std::to_string(static_cast<int>(std::lround(100 * options.min_change))) + "%";
    else
      verdict = "no significant change";
    if (r.counts && r.ratio > 1) worse = true;
    std::ostringstream p;
    if (r.repetitions_a >= options.min_repetitions && r.repetitions_b >= options.min_repetitions)
      p << std::setprecision(3) << r.test.p_value;
    else
      p << "-";
    out << std::left << std::setw(static_cast<int>(width)) << r.name << std::right << std::fixed
        << std::setprecision(2) << std::setw(12) << r.median_a * 1e9 << std::setw(12) << r.median_b * 1e9
        << std::setprecision(3) << std::setw(9) << r.ratio << std::setw(11) << p.str() << "  " << verdict
        << '\n';
    out.unsetf(std::ios::fixed);
  }
  out << "geometric mean of B/A over " << rows.size() << " benchmarks: " << std::fixed << std::setprecision(3)
      << std::exp(log_sum / static_cast<double>(rows.size())) << '\n';
  out.unsetf(std::ios::fixed);
  return worse;
}

}  // namespace tritri
