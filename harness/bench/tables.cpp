#include "harness/bench/report.hpp"

#include "cases/util/stats.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace tritri::bench {
namespace {

std::string pad(const std::string& s, std::size_t width, bool left = false) {
  if (s.size() >= width) return s;
  return left ? s + std::string(width - s.size(), ' ') : std::string(width - s.size(), ' ') + s;
}

// A row of the tables: algo/level/mode for times (the modes of a test one under the other),
// algo/level for what does not depend on the mode (operation counts).
std::string row_of(const Entry& e, bool with_mode) {
  return with_mode ? e.row() + "/" + std::string(to_string(*e.mode)) : e.row();
}

// One table per workload (and one for the stages): pools as columns, algorithm/level as rows.
struct Table {
  std::string group;
  std::vector<const Pool*> pools;  // the columns
  std::vector<std::string> rows;   // row_of, in registration order
};

std::vector<Table> tables_of(const EntryList& entries, bool with_mode) {
  std::vector<Table> tables;
  for (const auto& e : entries) {
    const std::string group = e->stage ? "stage" : e->pool->workload;
    auto it = std::find_if(tables.begin(), tables.end(), [&](const Table& t) { return t.group == group; });
    if (it == tables.end()) it = tables.insert(tables.end(), Table{group, {}, {}});
    if (std::find(it->pools.begin(), it->pools.end(), e->pool) == it->pools.end()) it->pools.push_back(e->pool);
    const std::string row = row_of(*e, with_mode);
    if (std::find(it->rows.begin(), it->rows.end(), row) == it->rows.end()) it->rows.push_back(row);
  }
  return tables;
}

std::string column_title(const Pool* p, const std::string& group) {
  return group == "ratio" || group == "stage" || group == "size" ? p->value : p->value.substr(0, 11);
}

const Entry* find_entry(const EntryList& entries, const std::string& row, const Pool* p, bool with_mode) {
  auto it = std::find_if(entries.begin(), entries.end(),
                         [&](const auto& e) { return e->pool == p && row_of(*e, with_mode) == row; });
  return it == entries.end() ? nullptr : it->get();
}

std::string time_cell(const Entry* e, const Summary& summary) {
  if (!e || e->ns_per_pair.empty()) return "";
  const double t = median(e->ns_per_pair);
  std::string cell = fixed(t, t < 100 ? 2 : 1);
  if (const double r = summary.relative(*e); std::isfinite(r)) cell += " (" + fixed(r, 2) + ")";
  return cell + (e->score.wrong && !e->floor ? "!" : " ");
}

// A table per workload: a row per algorithm/level/mode, a column per pool.
void print_time_tables(const EntryList& timed, const Summary& summary, std::ostream& out) {
  for (const Table& table : tables_of(timed, true)) {
    // Stages run on the ratio:0.50 pool (the stage workload) and on the paper drivers' pools.
    out << '\n' << table.group << (table.group == "stage" ? " (columns: ratio:VALUE or paper:VALUE pools)" : "") << '\n';
    out << pad("algorithm/level/mode", 34, true);
    for (const Pool* p : table.pools) out << pad(column_title(p, table.group), 14);
    out << '\n';
    for (const auto& row : table.rows) {
      out << pad(row, 34, true);
      for (const Pool* p : table.pools) out << pad(time_cell(find_entry(timed, row, p, true), summary), 14);
      out << '\n';
    }
  }
}

void print_times(const EntryList& timed, const Summary& summary, int repetitions, std::ostream& out) {
  out << "\nns per pair: median of " << repetitions << " repetitions, CPU time; rows algorithm/level/mode (call: one\n"
      << "pair per out-of-line call; batch: the pool in batches). In brackets: relative to " << summary.reference_row
      << "\nin the same mode on the same pool (--reference).\n"
      << "'!': wrong answers on that pool (see the warnings); floor and null are not tests.\n";
  print_time_tables(timed, summary, out);
}

void print_operations(const EntryList& timed, std::ostream& out) {
  if (std::none_of(timed.begin(), timed.end(), [](const auto& e) { return e->ops.has_value(); })) return;
  out << "\noperations per pair (the counting instantiation; 'div' includes nothing else, 'cmp' every comparison)\n";
  for (const Table& table : tables_of(timed, false)) {
    if (table.group == "stage") continue;
    out << '\n' << table.group << '\n' << pad("algorithm/level  op", 34, true);
    for (const Pool* p : table.pools) out << pad(column_title(p, table.group), 12);
    out << '\n';
    for (const auto& row : table.rows) {
      for (int op = 0; op < 4; ++op) {
        bool any = false;
        std::string line = pad(row + "  " + std::array{"add", "mul", "div", "cmp"}[op], 34, true);
        for (const Pool* p : table.pools) {
          const Entry* e = find_entry(timed, row, p, false);
          std::string cell;
          if (e && e->ops) {
            const OpCounts& c = *e->ops;
            const std::uint64_t v = std::array{c.add, c.mul, c.div, c.cmp}[op];
            cell = fixed(static_cast<double>(v) / static_cast<double>(p->size()), 1);
            any = true;
          }
          line += pad(cell, 12);
        }
        if (any) out << line << '\n';
      }
    }
  }
}

std::string column_of(const FloorShare& fs) { return fs.floor + "/" + std::string(to_string(fs.mode)); }

// The floors' shares: columns floor/mode, rows the tests, in the order first measured.
struct ShareTable {
  std::vector<std::string> columns, rows;
  explicit ShareTable(const Summary& summary) {
    for (const FloorShare& fs : summary.floor_shares) {
      if (std::find(columns.begin(), columns.end(), column_of(fs)) == columns.end()) columns.push_back(column_of(fs));
      if (std::find(rows.begin(), rows.end(), fs.row) == rows.end()) rows.push_back(fs.row);
    }
  }
};

// The worst share of each floor among the published tests in each mode.
void print_floor_lines(const Summary& summary, std::ostream& out) {
  for (const std::string& column : ShareTable(summary).columns) {
    const FloorShare* worst = nullptr;
    for (const FloorShare& fs : summary.floor_shares)
      if (fs.published && column_of(fs) == column &&
          (!worst || fs.share_full > worst->share_full))
        worst = &fs;
    if (!worst) continue;
    out << "\nharness: floor '" << worst->floor << "' in " << to_string(worst->mode) << " mode at most "
        << fixed(100 * worst->share_full, 1) << "% of a published test's time per pair on the full-size pools (limit "
        << fixed(100 * kFloorShareLimit, 0) << "%), worst on " << worst->where_full;
  }
  out << '\n';
}

// Every test's share of each floor in each mode.
void print_floor_table(const Summary& summary, std::ostream& out) {
  const auto [columns, rows] = ShareTable(summary);
  if (rows.empty()) return;
  out << "\nfloors' share of each test's time, worst full-size pool, same mode ('*': not a published test)\n"
      << pad("algorithm/level", 34, true);
  for (const std::string& column : columns) out << pad(column, 14);
  out << '\n';
  for (const std::string& row : rows) {
    std::string line = pad(row, 34, true);
    bool published = true;
    for (const std::string& column : columns) {
      std::string cell;
      for (const FloorShare& fs : summary.floor_shares)
        if (fs.row == row && column_of(fs) == column)
          cell = fixed(100 * fs.share_full, 1) + "%", published = fs.published;
      line += pad(cell, 14);
    }
    out << line << (published ? "" : " *") << '\n';
  }
}

}  // namespace

std::string fixed(double x, int decimals) {
  if (!std::isfinite(x)) return "-";
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << x;
  return s.str();
}

void print_pools(const std::vector<PlannedPool>& pools, std::ostream& out) {
  out << "pools:\n";
  for (const auto& planned : pools) {
    const Pool& p = planned.pool;
    out << "  " << pad(p.name(), 22, true) << pad(std::to_string(p.size()), 7) << " pairs, "
        << pad(std::to_string(p.intersecting()), 6) << " intersecting; stages: " << p.stage_mix_text() << '\n';
  }
}

void print_tables(const EntryList& timed, const Summary& summary, int repetitions, std::ostream& out) {
  print_times(timed, summary, repetitions, out);
  print_operations(timed, out);
}

void print_self_timed(const EntryList& self_timed, const Summary& summary, std::ostream& out) {
  if (self_timed.empty()) return;
  out << "\ntimed in-process by the plug-in: ns per pair, the median of its repetitions of its own loop over\n"
      << "the pool, on its runtime's monotonic clock (harness/run/process_plugin.hpp, '#time'), not Google\n"
      << "Benchmark's CPU time; one pair per call of the test, as 'call' mode. In brackets: relative to\n"
      << summary.reference_row << " in call mode on the same pool. '!': wrong answers on that pool.\n";
  print_time_tables(self_timed, summary, out);
}

void print_harness(const Summary& summary, std::ostream& out) {
  print_floor_lines(summary, out);
  out << "harness: repetition spread (max/min - 1) median " << fixed(100 * median(summary.spreads), 1) << "%, worst "
      << fixed(100 * summary.worst_spread, 1) << "% on " << summary.spread_where << " (limit 5% on a quiet machine)\n";
  print_floor_table(summary, out);
  if (summary.warnings.empty()) return;
  out << "\nwarnings:\n";
  const std::size_t limit = 40;
  for (std::size_t i = 0; i < summary.warnings.size() && i < limit; ++i) out << "  " << summary.warnings[i] << '\n';
  if (summary.warnings.size() > limit) out << "  ... and " << summary.warnings.size() - limit << " more\n";
}

}  // namespace tritri::bench
