#include "harness/check/scorecard.hpp"

#include "harness/check/check.hpp"
#include "cases/generator/variants.hpp"
#include "cases/util/random.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <iomanip>
#include <ostream>
#include <numeric>

namespace tritri {
namespace {

enum Transform : int { identity, swap, vertex_order, axis_permutation, scale, translation, kTransforms };
constexpr const char* kTransformNames[] = {"identity", "swap", "vertex_order", "axis_permutation", "scale",
                                           "translation"};

struct Tagged {
  std::vector<Case> cases;
  std::vector<std::pair<std::size_t, Transform>> tags;  // (base, transform) per case
  void add(Case c, std::size_t base, Transform t) {
    cases.push_back(std::move(c));
    tags.emplace_back(base, t);
  }
};

// The symmetry variants that matter here: the identity, the argument swap alone, and the 35
// other vertex orders with the arguments in place (the mixed ones add nothing separate).
void add_symmetries(const Case& base, std::size_t b, Rng& rng, Tagged& out) {
  std::vector<Case> all;
  corpus::add_symmetry_variants(base, 72, rng, all);
  for (Case& c : all) {
    const bool ab = c.name.ends_with("-ab");
    const bool orders_kept = c.name.ends_with("sym-012-012-ab") || c.name.ends_with("sym-012-012-ba");
    if (orders_kept) out.add(std::move(c), b, ab ? identity : swap);
    else if (ab) out.add(std::move(c), b, vertex_order);
  }
}

// The 47 non-identity signed permutations of the axes: each coordinate is moved or negated,
// which is exact in floating point.
void add_axis_permutations(const Case& base, std::size_t b, Tagged& out) {
  constexpr std::array<std::array<int, 3>, 6> perms = {{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (std::size_t p = 0; p < perms.size(); ++p)
    for (int signs = 0; signs < 8; ++signs) {
      if (p == 0 && signs == 0) continue;
      Case c = base;
      for (Triangle* t : {&c.pair.t1, &c.pair.t2})
        for (auto& v : t->v) {
          const Vec3<double> old = v;
          for (int i = 0; i < 3; ++i) v[i] = (signs >> i & 1 ? -1.0 : 1.0) * old[perms[p][i]];
        }
      out.add(std::move(c), b, axis_permutation);
    }
}

Tagged invariance_cases(const std::vector<Case>& bases, std::uint64_t seed) {
  Rng rng(seed);
  Tagged out;
  for (std::size_t b = 0; b < bases.size(); ++b) {
    add_symmetries(bases[b], b, rng, out);
    add_axis_permutations(bases[b], b, out);
    std::vector<Case> more;
    corpus::add_scale_variants(bases[b], 2, rng, more);
    for (Case& c : more) out.add(std::move(c), b, scale);
    more.clear();
    corpus::add_translate_variants(bases[b], 2, rng, more);
    for (Case& c : more) out.add(std::move(c), b, translation);
  }
  return out;
}

// Every answer with its overlap filled in as the judge reads it (an algorithm that answers only the
// relation is scored by what its relation decides).
std::vector<Answers> answers_for_overlap(const Algorithm& algorithm, const std::vector<Case>& cases,
                                         const IsolationOptions& isolation) {
  std::vector<Answers> answers = answer_cases(algorithm, cases, isolation);
  for (Answers& a : answers)
    if (!a.declined && a.fate == Fate::ok) a.overlap = overlap_of(algorithm, a);
  return answers;
}

// An answer as one token: the overlap value, or a fault; -1 when the harness declined the case.
int token(const Answers& a) {
  if (a.declined) return -1;
  if (a.fate != Fate::ok) return 10 + static_cast<int>(a.fate);
  return static_cast<int>(a.overlap);
}

std::vector<Invariance> tally_invariance(const Tagged& tagged, const std::vector<Answers>& answers,
                                         std::size_t base_count) {
  std::vector<int> base_token(base_count, -1);
  for (std::size_t i = 0; i < tagged.cases.size(); ++i)
    if (tagged.tags[i].second == identity) base_token[tagged.tags[i].first] = token(answers[i]);
  // [base][transform]: 0 no variant answered, 1 all agreed, 2 at least one changed.
  std::vector<std::array<int, kTransforms>> state(base_count, std::array<int, kTransforms>{});
  for (std::size_t i = 0; i < tagged.cases.size(); ++i) {
    const auto [b, t] = tagged.tags[i];
    const int v = token(answers[i]);
    if (t == identity || v < 0 || base_token[b] < 0) continue;
    state[b][t] = std::max(state[b][t], v == base_token[b] ? 1 : 2);
  }
  std::vector<Invariance> out;
  for (int t = swap; t < kTransforms; ++t) {
    Invariance inv{kTransformNames[t]};
    for (const auto& s : state) {
      inv.bases += s[t] > 0;
      inv.changed += s[t] == 2;
    }
    out.push_back(inv);
  }
  return out;
}

}  // namespace

namespace {

struct ProbeSpec {
  const char* name;
  bool truth;
  Triangle second;  // against the floor (0,0,0) (4,0,0) (0,4,0)
};

Triangle tri(Vec3<double> a, Vec3<double> b, Vec3<double> c) { return {{a, b, c}}; }

// Exact configurations with a known closed-set answer: all four touch the floor.
const std::vector<ProbeSpec>& touching_specs() {
  static const std::vector<ProbeSpec> specs = {
      {"shared_vertex", true, tri({0, 0, 0}, {-1, -2, 3}, {-2, -1, 3})},
      {"shared_edge", true, tri({0, 0, 0}, {4, 0, 0}, {1, -1, 2})},
      {"vertex_on_face", true, tri({1, 1, 0}, {1, 2, 3}, {2, 1, 3})},
      {"coplanar_shared_edge", true, tri({0, 0, 0}, {4, 0, 0}, {0, -4, 0})},
  };
  return specs;
}

const std::vector<ProbeSpec>& degenerate_specs() {
  static const std::vector<ProbeSpec> specs = {
      {"zero_area_piercing", true, tri({1, 1, -1}, {1, 1, 1}, {1, 1, 3})},
      {"zero_area_apart", false, tri({10, 10, -1}, {10, 10, 1}, {10, 10, 3})},
      {"repeated_vertex_on_face", true, tri({1, 1, 0}, {1, 1, 0}, {2, 1, 3})},
      {"single_point_on_face", true, tri({1, 1, 0}, {1, 1, 0}, {1, 1, 0})},
  };
  return specs;
}

// Every probe in its 72 symmetry variants, answered by `algorithm`.
std::vector<Probe> run_probes(const Algorithm& algorithm, const std::vector<ProbeSpec>& specs,
                              const IsolationOptions& isolation) {
  const Triangle floor = tri({0, 0, 0}, {4, 0, 0}, {0, 4, 0});
  Rng rng(0);  // the full set of 72 is drawn: the generator is not consulted
  std::vector<Case> cases;
  for (const ProbeSpec& s : specs) {
    Case base;
    base.name = s.name;
    base.pair = {floor, s.second};
    corpus::add_symmetry_variants(base, 72, rng, cases);
  }
  const std::vector<Answers> answers = answers_for_overlap(algorithm, cases, isolation);
  std::vector<Probe> out;
  for (std::size_t p = 0; p < specs.size(); ++p) {
    Probe probe{specs[p].name, specs[p].truth};
    for (std::size_t i = 72 * p; i < 72 * (p + 1); ++i) {
      const Answers& a = answers[i];
      if (a.declined || a.overlap == Overlap::unsupported) ++probe.declined;
      else if (a.fate != Fate::ok) ++probe.crashed;
      else if (a.overlap == Overlap::yes) ++probe.yes;
      else ++probe.no;
    }
    out.push_back(probe);
  }
  return out;
}

}  // namespace

std::string Probe::verdict() const {
  if (crashed > 0) return "crash";
  if (yes > 0 && no == 0 && declined == 0) return "yes";
  if (no > 0 && yes == 0 && declined == 0) return "no";
  if (yes == 0 && no == 0) return "declined";
  return "mixed";
}

bool is_scorecard_base(const Case& c) {
  const auto subsuite = c.label("subsuite");
  return !subsuite || (*subsuite == "symmetry" && c.label("transform") == "sym-012-012-ab");
}

std::vector<Case> scorecard_bases(const std::vector<Case>& cases, const ScorecardOptions& options) {
  std::vector<const Case*> candidates;
  for (const Case& c : cases)
    if (is_scorecard_base(c)) candidates.push_back(&c);
  std::vector<Case> bases;
  const std::size_t n = candidates.size(), take = std::min(n, options.max_bases);
  for (std::size_t k = 0; k < take; ++k) bases.push_back(*candidates[k * n / take]);
  return bases;
}

Scorecard compute_scorecard(const Algorithm& algorithm, const std::vector<Case>& bases,
                            const ScorecardOptions& options, const IsolationOptions& isolation) {
  Scorecard card;
  card.algorithm = algorithm.name;
  card.declared_boundary = algorithm.boundary == Boundary::closed ? "closed" : "open";
  card.declared_degenerate = algorithm.accepts_degenerate;
  const Tagged tagged = invariance_cases(bases, options.seed);
  const std::vector<Answers> answers = answers_for_overlap(algorithm, tagged.cases, isolation);
  card.invariance = tally_invariance(tagged, answers, bases.size());
  card.touching = run_probes(algorithm, touching_specs(), isolation);
  // What the algorithm does with degenerate input when it is called anyway, as a user would.
  Algorithm unguarded = algorithm;
  unguarded.accepts_degenerate = true;
  card.degenerate = run_probes(unguarded, degenerate_specs(), isolation);
  if (auto on_float = algorithm.on_scalar(Scalar::float_)) {
    const std::vector<Answers> floats = answers_for_overlap(*on_float, bases, isolation);
    const std::vector<Answers> doubles = answers_for_overlap(algorithm, bases, isolation);
    card.float_differs = 0;
    for (std::size_t i = 0; i < bases.size(); ++i) {
      if (token(doubles[i]) < 0) continue;
      ++card.float_bases;
      card.float_differs += token(floats[i]) != token(doubles[i]);
    }
  }
  return card;
}

namespace {

nlohmann::json probes_json(const std::vector<Probe>& probes, const char* expected) {
  nlohmann::json out = nlohmann::json::array();
  for (const Probe& p : probes) {
    nlohmann::json j = {{"probe", p.name}, {"truth", p.truth}, {"yes", p.yes}, {"no", p.no},
                        {"declined", p.declined}, {"crashed", p.crashed}, {"verdict", p.verdict()}};
    if (expected) j["as_declared"] = p.verdict() == expected;
    out.push_back(std::move(j));
  }
  return out;
}

double share(std::size_t part, std::size_t whole) { return whole ? double(part) / double(whole) : 0.0; }

}  // namespace

void print_scorecards(std::ostream& out, const std::vector<Scorecard>& cards, std::size_t bases) {
  out << "\nscorecard (" << bases << " base cases): % of bases whose answer changes under\n"
      << "swap / vertex order / axis permutation / 2^k scale / translation;"
      << " touching and degenerate probe verdicts; float differs (% of bases)\n";
  for (const Scorecard& c : cards) {
    out << std::left << std::setw(22) << c.algorithm << std::right << std::fixed << std::setprecision(1);
    for (const Invariance& i : c.invariance) out << std::setw(6) << 100 * share(i.changed, i.bases);
    out << "  touch";
    for (const Probe& p : c.touching) out << ' ' << p.verdict();
    out << "  degenerate";
    for (const Probe& p : c.degenerate) out << ' ' << p.verdict();
    if (c.float_differs >= 0) out << "  float " << 100 * share(std::size_t(c.float_differs), c.float_bases);
    out << '\n';
  }
  out << std::defaultfloat;
}

nlohmann::json scorecards_json(const std::vector<Scorecard>& cards) {
  nlohmann::json out = nlohmann::json::array();
  for (const Scorecard& c : cards) {
    nlohmann::json invariance = nlohmann::json::object();
    for (const Invariance& i : c.invariance)
      invariance[i.transform] = {{"bases", i.bases}, {"changed", i.changed}, {"share", share(i.changed, i.bases)}};
    nlohmann::json on_float = nullptr;
    if (c.float_differs >= 0)
      on_float = {{"bases", c.float_bases},
                  {"differs", c.float_differs},
                  {"share", share(std::size_t(c.float_differs), c.float_bases)}};
    out.push_back({{"algorithm", c.algorithm},
                   {"declared", {{"boundary", c.declared_boundary}, {"accepts_degenerate", c.declared_degenerate}}},
                   {"invariance", invariance},
                   {"touching", probes_json(c.touching, c.declared_boundary == "closed" ? "yes" : "no")},
                   {"degenerate", probes_json(c.degenerate, nullptr)},
                   {"float", on_float}});
  }
  return out;
}

}  // namespace tritri
