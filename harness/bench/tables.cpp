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

// One table per workload (and one for the stages): pools as columns, algorithm/level as rows.
struct Table {
  std::string group;
  std::vector<const Pool*> pools;  // the columns
  std::vector<std::string> rows;   // algo/level, in registration order
};

std::vector<Table> tables_of(const EntryList& entries) {
  std::vector<Table> tables;
  for (const auto& e : entries) {
    const std::string group = e->stage ? "stage" : e->pool->workload;
    auto it = std::find_if(tables.begin(), tables.end(), [&](const Table& t) { return t.group == group; });
    if (it == tables.end()) it = tables.insert(tables.end(), Table{group, {}, {}});
    if (std::find(it->pools.begin(), it->pools.end(), e->pool) == it->pools.end()) it->pools.push_back(e->pool);
    if (std::find(it->rows.begin(), it->rows.end(), e->row()) == it->rows.end()) it->rows.push_back(e->row());
  }
  return tables;
}

std::string column_title(const Pool* p, const std::string& group) {
  return group == "ratio" || group == "stage" || group == "size" ? p->value : p->value.substr(0, 11);
}

const Entry* find_entry(const EntryList& entries, const std::string& row, const Pool* p) {
  auto it = std::find_if(entries.begin(), entries.end(), [&](const auto& e) { return e->row() == row && e->pool == p; });
  return it == entries.end() ? nullptr : it->get();
}

std::string time_cell(const Entry* e, const Summary& summary) {
  if (!e || e->ns_per_pair.empty()) return "";
  const double t = median(e->ns_per_pair);
  std::string cell = fixed(t, t < 100 ? 2 : 1);
  if (const double r = summary.relative(*e); std::isfinite(r)) cell += " (" + fixed(r, 2) + ")";
  return cell + (e->score.wrong && !e->floor ? "!" : " ");
}

void print_times(const EntryList& timed, const Summary& summary, int repetitions, std::ostream& out) {
  out << "\nns per pair: median of " << repetitions << " repetitions, CPU time. In brackets: relative to "
      << summary.reference_row << " on the same pool (--reference).\n"
      << "'!': wrong answers on that pool (see the warnings); floor and null are not tests.\n";
  for (const Table& table : tables_of(timed)) {
    out << '\n' << table.group << (table.group == "stage" ? " (pool ratio:0.50)" : "") << '\n';
    out << pad("algorithm/level", 34, true);
    for (const Pool* p : table.pools) out << pad(column_title(p, table.group), 14);
    out << '\n';
    for (const auto& row : table.rows) {
      out << pad(row, 34, true);
      for (const Pool* p : table.pools) out << pad(time_cell(find_entry(timed, row, p), summary), 14);
      out << '\n';
    }
  }
}

void print_operations(const EntryList& timed, std::ostream& out) {
  if (std::none_of(timed.begin(), timed.end(), [](const auto& e) { return e->ops.has_value(); })) return;
  out << "\noperations per pair (the counting instantiation; 'div' includes nothing else, 'cmp' every comparison)\n";
  for (const Table& table : tables_of(timed)) {
    if (table.group == "stage") continue;
    out << '\n' << table.group << '\n' << pad("algorithm/level  op", 34, true);
    for (const Pool* p : table.pools) out << pad(column_title(p, table.group), 12);
    out << '\n';
    for (const auto& row : table.rows) {
      for (int op = 0; op < 4; ++op) {
        bool any = false;
        std::string line = pad(row + "  " + std::array{"add", "mul", "div", "cmp"}[op], 34, true);
        for (const Pool* p : table.pools) {
          const Entry* e = find_entry(timed, row, p);
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

void print_harness(const Summary& summary, std::ostream& out) {
  for (const auto& fs : summary.floor_shares) {
    out << "\nharness: floor '" << fs.name << "' at most " << fixed(100 * fs.share_full, 1)
        << "% of the fastest algorithm's time per pair on the full-size pools (limit 10%), worst on "
        << fs.where_full;
    if (fs.where != fs.where_full)
      out << "\n         on every pool, small ones included: " << fixed(100 * fs.share, 1) << "%, on " << fs.where;
  }
  out << '\n';
  out << "harness: repetition spread (max/min - 1) median " << fixed(100 * median(summary.spreads), 1) << "%, worst "
      << fixed(100 * summary.worst_spread, 1) << "% on " << summary.spread_where << " (limit 5% on a quiet machine)\n";
  if (summary.warnings.empty()) return;
  out << "\nwarnings:\n";
  const std::size_t limit = 40;
  for (std::size_t i = 0; i < summary.warnings.size() && i < limit; ++i) out << "  " << summary.warnings[i] << '\n';
  if (summary.warnings.size() > limit) out << "  ... and " << summary.warnings.size() - limit << " more\n";
}

}  // namespace tritri::bench
