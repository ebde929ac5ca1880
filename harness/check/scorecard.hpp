// The robustness scorecard of `tritri check --scorecard`: per algorithm, how its answers change
// under transformations that cannot change the truth, what it answers on touching and
// degenerate probes, and how its float instantiation differs from double.
//
// Variants are made in memory from base cases (the check's own input, capped) and answered
// through the normal isolated path (answer_cases), so a crash is a fate, not the end of the run.
#pragma once

#include "cases/casefile.hpp"
#include "harness/run/isolation.hpp"
#include "tritri/algorithm.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace tritri {

// Bases whose overlap answer changed under at least one variant of one transformation.
struct Invariance {
  std::string transform;  // "swap", "vertex_order", "axis_permutation", "scale", "translation"
  std::size_t bases = 0;  // bases with an answer for the base and at least one variant
  std::size_t changed = 0;
};

// One exact probe, run in every symmetry variant (6 × 6 vertex orders × 2 argument orders).
struct Probe {
  std::string name;     // "shared_vertex", "zero_area_piercing", ...
  bool truth = false;   // the closed-set answer
  std::size_t yes = 0, no = 0, declined = 0, crashed = 0;  // over the 72 variants

  std::string verdict() const;  // "yes", "no", "mixed", "declined", "crash"
};

struct Scorecard {
  std::string algorithm;
  std::string declared_boundary;  // "closed" / "open"
  bool declared_degenerate = false;
  std::vector<Invariance> invariance;
  std::vector<Probe> touching;    // verdicts compared with declared_boundary
  std::vector<Probe> degenerate;  // called even when the algorithm does not accept them
  // Float instantiation against double on the bases: -1 when there is none.
  long float_differs = -1;
  std::size_t float_bases = 0;
};

struct ScorecardOptions {
  std::size_t max_bases = 400;  // bases taken evenly from the input
  std::uint64_t seed = 1;       // for the scale and translation exponents (tritri::Rng)
};

// The bases: input cases that are not variants of another (no subsuite= label, or the identity
// symmetry), at most options.max_bases of them, evenly spaced.
std::vector<Case> scorecard_bases(const std::vector<Case>& cases, const ScorecardOptions& options);
// Whether a case can be a base: no variant (no subsuite= label), or the identity symmetry.
bool is_scorecard_base(const Case& c);

Scorecard compute_scorecard(const Algorithm& algorithm, const std::vector<Case>& bases,
                            const ScorecardOptions& options, const IsolationOptions& isolation);

// One line per algorithm: the share changed per transformation, the touching verdicts, the
// degenerate verdicts, float against double.
void print_scorecards(std::ostream& out, const std::vector<Scorecard>& cards, std::size_t bases);

// The JSON array of harness/README.md's "scorecards".
nlohmann::json scorecards_json(const std::vector<Scorecard>& cards);

}  // namespace tritri
