#include "cases/generator/corpus.hpp"

#include "cases/util/parallel.hpp"

#include "cases/util/atomic_file.hpp"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <iomanip>
#include <map>
#include <mutex>
#include <ostream>
#include <stdexcept>
#include <thread>

namespace tritri::corpus {

// Draws a construction until it is a proper pair in an exact frame. A construction that keeps
// failing is a bug in the family, not bad luck: say so.
Construction build_construction(const Family& family, const Config& config, Rng& rng) {
  for (int attempt = 0; attempt < 200; ++attempt) {
    Construction c = config.build(rng);
    std::optional<TrianglePair> moved;
    for (int f = 0; f < 16 && !moved; ++f) moved = apply_exactly(random_frame(rng, c.frame), c.pair);
    if (moved) c.pair = *moved;  // else the canonical frame, which is exact by construction
    if (!has_degenerate_triangle(c.pair)) return c;
  }
  throw std::logic_error(std::string("corpus: family ") + family.name + ", config " + config.name +
                         " builds only degenerate triangles");
}

namespace {

bool has_exact_variants(const Family& family) { return family.exact; }

// One base construction and all its variants.
std::vector<Case> generate_unit(const Family& family, std::size_t index, const CorpusOptions& options) {
  Rng rng(stream_seed(options.seed, family.name, index));
  const Config& config = family.configs[index % family.configs.size()];
  const Construction built = build_construction(family, config, rng);

  Case base;
  base.name = std::string(family.name) + "." + config.name + "." + std::to_string(index);
  base.pair = built.pair;
  base.labels.emplace_back("family", family.name);
  base.labels.emplace_back("config", config.name);
  if (config.expect) base.labels.emplace_back("expect", std::string(to_string(*config.expect)));
  for (const auto& label : built.labels) base.labels.push_back(label);

  const VariantPlan& plan = options.plan;
  std::vector<Case> out;
  add_symmetry_variants(base, plan.symmetry, rng, out);
  add_scale_variants(base, plan.scales, rng, out);
  if (has_exact_variants(family)) {
    add_translate_variants(base, plan.translations, rng, out);
    add_rotate_variants(base, plan.rotations, rng, out);
    if (plan.perturb) add_perturb_variants(base, rng, out);
  }
  return out;
}

std::vector<const Family*> chosen_families(const CorpusOptions& options) {
  std::vector<const Family*> chosen;
  if (options.families.empty()) {
    for (const auto& f : families()) chosen.push_back(&f);
    return chosen;
  }
  for (const auto& name : options.families) {
    const Family* f = find_family(name);
    if (!f) {
      std::string known;
      for (const auto& k : families()) known += (known.empty() ? "" : ", ") + std::string(k.name);
      throw std::invalid_argument("unknown family '" + name + "' (known: " + known + ")");
    }
    if (std::find(chosen.begin(), chosen.end(), f) == chosen.end()) chosen.push_back(f);
  }
  return chosen;
}

}  // namespace

CorpusOptions default_options(std::uint64_t seed) {
  CorpusOptions o;
  o.seed = seed;
  return o;
}

CorpusOptions quick_options(std::uint64_t seed) {
  CorpusOptions o;
  o.seed = seed;
  // Enough base cases for every config of the family with the most (collinear-edges, 10).
  o.per_family = 0;
  for (const auto& f : families()) o.per_family = std::max(o.per_family, f.configs.size());
  o.plan = {6, 1, 1, 1, true};
  return o;
}

std::size_t planned_size(const CorpusOptions& options) {
  std::size_t total = 0;
  const VariantPlan& p = options.plan;
  for (const Family* f : chosen_families(options)) {
    std::size_t each = std::size_t(std::min(p.symmetry, 72) + p.scales);
    if (f->exact) each += std::size_t(p.translations + p.rotations + (p.perturb ? 16 : 0));
    total += each * options.per_family;
  }
  return total;
}

std::vector<Case> generate_corpus(const CorpusOptions& options) {
  const auto chosen = chosen_families(options);
  std::vector<std::pair<const Family*, std::size_t>> units;
  for (const Family* f : chosen)
    for (std::size_t i = 0; i < options.per_family; ++i) units.emplace_back(f, i);

  // Each unit has its own random stream, so the threads may take them in any order.
  std::vector<std::vector<Case>> results(units.size());
  parallel_chunks(units.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) results[i] = generate_unit(*units[i].first, units[i].second, options);
  }, {.chunk = 1});

  std::vector<Case> all;
  all.reserve(planned_size(options));
  for (auto& r : results)
    for (auto& c : r) all.push_back(std::move(c));
  return all;
}

void attach_oracle_labels(std::vector<Case>& cases, const std::vector<OracleRecord>& records) {
  for (std::size_t i = 0; i < cases.size(); ++i) cases[i].set_label("oracle", to_string(records[i].relation));
}

void print_counts(std::ostream& out, const std::vector<Case>& cases, const std::vector<OracleRecord>& records) {
  std::vector<std::string> order;
  std::map<std::string, std::map<Relation, std::size_t>> counts;
  std::map<Relation, std::size_t> totals;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string family = cases[i].family();
    if (!counts.count(family)) order.push_back(family);
    ++counts[family][records[i].relation];
    ++totals[records[i].relation];
  }
  std::vector<Relation> columns(std::begin(kAllRelations), std::end(kAllRelations));
  if (totals.count(Relation::degenerate)) columns.push_back(Relation::degenerate);

  std::size_t first = 6;
  for (const auto& f : order) first = std::max(first, f.size());
  out << std::left << std::setw(int(first)) << "family" << std::right;
  for (Relation r : columns) out << ' ' << std::setw(std::max<int>(7, int(to_string(r).size()))) << to_string(r);
  out << ' ' << std::setw(8) << "total" << '\n';
  auto row = [&](const std::string& name, const std::map<Relation, std::size_t>& c) {
    out << std::left << std::setw(int(first)) << name << std::right;
    std::size_t sum = 0;
    for (Relation r : columns) {
      const auto it = c.find(r);
      const std::size_t n = it == c.end() ? 0 : it->second;
      sum += n;
      out << ' ' << std::setw(std::max<int>(7, int(to_string(r).size())));
      if (n) out << n;
      else out << '.';
    }
    out << ' ' << std::setw(8) << sum << '\n';
  };
  for (const auto& f : order) row(f, counts[f]);
  row("total", totals);
}

std::vector<std::string> write_corpus(const std::string& dir, const std::vector<Case>& cases,
                                      const std::string& provenance) {
  std::filesystem::create_directories(dir);
  std::vector<std::string> order;
  std::map<std::string, std::vector<const Case*>> by_family;
  for (const auto& c : cases) {
    const std::string family = c.family();
    if (!by_family.count(family)) order.push_back(family);
    by_family[family].push_back(&c);
  }
  std::vector<std::string> paths;
  for (const auto& family : order) {
    const std::string path = (std::filesystem::path(dir) / (family + ".cases")).string();
    const Family* f = find_family(family);
    write_file_atomically(path, [&](std::ostream& out) {
      out << "# tritri corpus, family " << family << (f ? std::string(": ") + f->summary : "") << ".\n"
          << "# Generated by " << provenance << "; regenerate rather than edit.\n"
          << "# Labels: family, config (the construction), expect (the relation the construction\n"
          << "# guarantees, on exact cases only), subsuite (symmetry, scale, translate, rotate,\n"
          << "# perturb), transform (which one), oracle (CGAL's relation for these coordinates).\n"
          << "# name  T1: ax ay az bx by bz cx cy cz  T2: px py pz qx qy qz rx ry rz  [labels]\n";
      for (const Case* c : by_family[family]) out << format_case(*c) << '\n';
    });
    paths.push_back(path);
  }
  return paths;
}

}  // namespace tritri::corpus
