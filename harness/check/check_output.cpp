#include "harness/check/check_output.hpp"
#include "cases/util/input_error.hpp"

#include "harness/check/baseline_file.hpp"

#include "cases/util/text.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <ostream>
#include <sstream>

namespace tritri {
namespace {


std::string short_number(double x) {
  if (std::isnan(x)) return "-";
  std::ostringstream s;
  s << std::setprecision(2) << x;
  return s.str();
}

template <class Row>
void for_each_tally(const CheckResult& result, Row row) {
  for (const Algorithm* a : result.algorithms)
    for (const auto& group : result.groups) {
      auto it = result.tallies.find({a->name, group});
      if (it != result.tallies.end()) row(*a, group, it->second);
    }
}

// Whether any of the checked algorithms answers `level`.
bool any_answers(const CheckResult& result, Level level) {
  return std::any_of(result.algorithms.begin(), result.algorithms.end(),
                     [level](const Algorithm* a) { return a->answers(level); });
}

// The widths of the tables' algorithm and group (family) columns: the longest name, at least the header's.
std::pair<std::size_t, std::size_t> column_widths(const CheckResult& result) {
  std::size_t name_width = 9, group_width = 6;
  for (const Algorithm* a : result.algorithms) name_width = std::max(name_width, a->name.size());
  for (const auto& g : result.groups) group_width = std::max(group_width, g.size());
  return {name_width, group_width};
}

}  // namespace

void print_confusion(std::ostream& out, const CheckResult& result, bool all_cells) {
  if (!any_answers(result, Level::relation)) return;
  const auto widths = column_widths(result);
  const std::size_t name_width = widths.first, group_width = widths.second;
  out << "\nrelation confusion (answered->oracle cases; "
      << (all_cells ? "every cell" : "wrong cells only, --confusion for all") << ")\n";
  for_each_tally(result, [&](const Algorithm& a, const std::string& group, const Tally& t) {
    if (!a.answers(Level::relation)) return;
    std::string cells;
    for (const auto& [key, count] : t.confusion) {
      if (!all_cells && key.first == key.second) continue;
      if (!cells.empty()) cells += ", ";
      cells += key.first + "->" + key.second + " " + std::to_string(count);
    }
    if (cells.empty()) return;
    out << std::left << std::setw(static_cast<int>(name_width)) << a.name << "  "
        << std::setw(static_cast<int>(group_width)) << group << "  " << cells << '\n';
  });
}

void print_segment_errors(std::ostream& out, const CheckResult& result) {
  if (!any_answers(result, Level::segment)) return;
  const auto widths = column_widths(result);
  const std::size_t name_width = widths.first, group_width = widths.second;
  out << "\nsegment error (Hausdorff distance to the exact intersection / pair's bounding-box diagonal)\n";
  auto row = [&](const std::string& algorithm, const std::string& group, const std::string& answered,
                 const std::string& measured, const std::string& median, const std::string& max,
                 const std::string& kind, const std::string& not_computed) {
    out << std::left << std::setw(static_cast<int>(name_width)) << algorithm << "  "
        << std::setw(static_cast<int>(group_width)) << group << std::right << std::setw(9) << answered
        << std::setw(9) << measured << std::setw(10) << median << std::setw(10) << max << std::setw(15)
        << kind << std::setw(14) << not_computed << '\n';
  };
  row("algorithm", "family", "answered", "measured", "median", "max", "kind-mismatch", "not-computed");
  for (const Algorithm* a : result.algorithms) {
    if (!a->answers(Level::segment)) continue;
    SegmentTally total;
    for (const auto& group : result.groups) {
      auto it = result.tallies.find({a->name, group});
      if (it == result.tallies.end()) continue;
      const SegmentTally& s = it->second.segment;
      add_tally(total, s);
      row(a->name, group, std::to_string(s.answered), std::to_string(s.errors.count()),
          short_number(s.median_error()), short_number(s.max_error()), std::to_string(s.kind_mismatches),
          std::to_string(s.not_computed));
    }
    if (result.groups.size() > 1)
      row(a->name, "(all)", std::to_string(total.answered), std::to_string(total.errors.count()),
          short_number(total.median_error()), short_number(total.max_error()),
          std::to_string(total.kind_mismatches), std::to_string(total.not_computed));
  }
}

void print_check_table(std::ostream& out, const CheckResult& result) {
  const auto widths = column_widths(result);
  const std::size_t name_width = widths.first, group_width = widths.second;
  auto row = [&](const std::string& algorithm, const std::string& group, const std::string& cases,
                 const std::string& fp, const std::string& fn, const std::string& rel,
                 const std::string& unsupported, const std::string& crash, const std::string& timeout) {
    out << std::left << std::setw(static_cast<int>(name_width)) << algorithm << "  "
        << std::setw(static_cast<int>(group_width)) << group << std::right << std::setw(8) << cases
        << std::setw(7) << fp << std::setw(7) << fn << std::setw(10) << rel << std::setw(13)
        << unsupported << std::setw(7) << crash << std::setw(9) << timeout << '\n';
  };
  row("algorithm", "family", "cases", "FP", "FN", "relation", "unsupported", "crash", "timeout");
  for (const Algorithm* a : result.algorithms) {
    Tally total;
    for (const auto& group : result.groups) {
      auto it = result.tallies.find({a->name, group});
      if (it == result.tallies.end()) continue;
      const Tally& t = it->second;
      add_tally(total, t);
      row(a->name, group, std::to_string(t.cases), std::to_string(t.false_positives),
          std::to_string(t.false_negatives), a->answers(Level::relation) ? std::to_string(t.misclassified) : "-",
          std::to_string(t.unsupported), std::to_string(t.crashes), std::to_string(t.timeouts));
    }
    if (result.groups.size() > 1)
      row(a->name, "(all)", std::to_string(total.cases), std::to_string(total.false_positives),
          std::to_string(total.false_negatives), a->answers(Level::relation) ? std::to_string(total.misclassified) : "-",
          std::to_string(total.unsupported), std::to_string(total.crashes), std::to_string(total.timeouts));
  }
}

bool is_complete(const CheckResult& result) { return result.stopped.empty(); }

bool report_incomplete(std::ostream& out, const CheckResult& result) {
  for (const StoppedRun& run : result.stopped) print_stopped(out, run);
  return !is_complete(result);
}

void print_failures(std::ostream& out, const CheckResult& result, std::size_t limit) {
  std::size_t shown = 0;
  for (const Failure& f : result.failures) {
    if (shown == limit) {
      out << "# ... " << (result.failures.size() - shown)
          << " more disagreements (raise --max-failures, or see --json)\n";
      break;
    }
    const Case& c = *f.subject;
    if (f.detail.empty())
      out << "# " << f.algorithm << ' ' << to_string(f.level) << ": answered " << f.answer << ", oracle "
          << f.expected << "   (" << c.source << ':' << c.line << ")\n";
    else
      out << "# " << f.algorithm << ": " << f.answer << " (" << f.detail << ") on this case   (" << c.source
          << ':' << c.line << ")\n";
    out << format_case(c, NumberStyle::g17) << '\n';
    out << format_case(c, NumberStyle::hex) << '\n';
    ++shown;
  }
}

nlohmann::json corpus_json(const CorpusIdentity& corpus) {
  nlohmann::json files = nlohmann::json::array();
  for (const CorpusFile& f : corpus.files)
    files.push_back({{"path", f.path}, {"bytes", f.bytes}, {"hash", f.hash}, {"generated_by", f.generated_by}});
  return {{"hash", corpus.hash}, {"generated_by", corpus.generated_by}, {"files", files}};
}

void write_check_json(std::ostream& out, const CheckResult& result, const CheckJsonContext& context) {
  dump_check_json(out, check_json(result, context));
}

// Streamed (std::setw: the indent of dump(1)), so a long failure list is not held twice, as a
// document and as one string.
void dump_check_json(std::ostream& out, const nlohmann::json& doc) { out << std::setw(1) << doc << '\n'; }

std::vector<Failure> capped_failures(const std::vector<Failure>& failures, std::size_t cap) {
  std::vector<Failure> kept;
  std::map<std::tuple<std::string, std::string, Level>, std::size_t> seen;
  for (const Failure& f : failures)
    if (seen[{f.algorithm, f.subject->family(), f.level}]++ < cap) kept.push_back(f);
  return kept;
}

Baseline read_baseline(const std::string& path) {
  std::istringstream in(read_possibly_gzipped(path));
  Baseline rows;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    auto fields = split_fields(line, '\t');
    if (fields.size() != 5)
      throw InputError(path + ":" + std::to_string(number) + ": expected 5 tab-separated fields "
                               "(algorithm case level answer oracle), found " +
                               std::to_string(fields.size()));
    if (fields[0] == "algorithm" && fields[1] == "case") continue;  // header
    rows.insert({std::string(fields[0]), std::string(fields[1]), std::string(fields[2]), std::string(fields[3]),
                 std::string(fields[4])});
  }
  return rows;
}

Baseline baseline_of(const CheckResult& result) {
  Baseline rows;
  for (const Failure& f : result.failures)
    rows.insert({f.algorithm, f.subject->name, std::string(to_string(f.level)), f.answer, f.expected});
  return rows;
}

void write_baseline(std::ostream& out, const Baseline& baseline) {
  out << "# tritri baseline: disagreements with the oracle that are known and recorded.\n"
         "# Written by `tritri check --write-baseline`; compared by `tritri check --baseline`.\n"
         "algorithm\tcase\tlevel\tanswer\toracle\n";
  for (const auto& [a, c, l, ans, exp] : baseline)
    out << a << '\t' << c << '\t' << l << '\t' << ans << '\t' << exp << '\n';
}

BaselineComparison compare_with_baseline(const Baseline& recorded, const CheckResult& result) {
  std::set<std::string> algorithms;
  for (const Algorithm* a : result.algorithms) algorithms.insert(a->name);
  const Baseline current = baseline_of(result);
  BaselineComparison comparison;
  for (const auto& row : current)
    if (!recorded.count(row)) comparison.new_failures.push_back(row);
  for (const auto& row : recorded)
    if (algorithms.count(std::get<0>(row)) && result.names.contains(std::get<1>(row)) && !current.count(row))
      comparison.fixed.push_back(row);
  return comparison;
}

}  // namespace tritri
