// The paper workload: each paper's own benchmark driver, rebuilt as a pool, so that its speed
// claim can be measured under the set-up it was made in and each difference from our pools
// varied alone (issue #26; the report's part "The papers' tables" reads the results).
//
//   paper:NAME[/MODIFIER...]   NAME one of shen03, shen03-drawn, tropp06, yuhe13 (paper_*.cpp
//                              each say which driver they follow and how). The modifiers change one
//                              thing of the driver's set-up each:
//     /shuffled   the same pairs, shuffled once (the drivers stream them in an order that a
//                 branch predictor learns: outcome-sorted, or one triangle held fixed)
//     /n:N        N pairs in place of the driver's count
//     /r:R        the intersecting share R in place of the driver's
//     /ours       the pairs drawn from our ratio pools' candidates (workloads/ratio.hpp) in
//                 place of the paper's distribution, in the driver's shape
// Not every paper takes every modifier (a paper says which in its file); the scalar type is an
// axis of the algorithms (NAME@float, `tritri bench --float`) and the edge vectors Tropp's
// caller precomputes a stage of tropp06 (stage:edges-given), both timed on these pools.
//
// Pools keep the driver's order (label_pairs, not draw(): no scrambling of vertex or triangle
// order) and leave out the pairs the oracle finds degenerate. Not in the default set.
#pragma once

#include "harness/bench/workload.hpp"

#include <optional>
#include <string>
#include <vector>

namespace tritri::bench::paper {

struct Value {
  std::string name;  // "shen03"
  bool shuffled = false;
  std::optional<std::size_t> n;
  std::optional<double> r;
  bool ours = false;
  std::string text() const;  // canonical: "shen03/n:65536/r:0.50/shuffled/ours"
};

// Throws std::invalid_argument naming what it accepts.
Value parse_value(const std::string& text);

// A driver's pairs, in the order it streams them; `skipped`: why there are none (e.g. no
// --authors-code for data files); `about`: key=value text for the JSON context.
struct DriverPairs {
  std::vector<TrianglePair> pairs;
  std::string skipped;
  std::string about;
};

struct Driver {
  std::string name;       // "shen03"
  std::string modifiers;  // the modifiers it takes, e.g. "shuffled n r ours"
  DriverPairs (*build)(const Value& value, const WorkloadInput& input);
  // What the pools depend on beyond the value and the seed (the data files' content), for the
  // pool cache's key; "" when nothing.
  std::string (*identity)(const WorkloadInput& input) = nullptr;
};

const Driver& shen03_driver();
const Driver& shen03_drawn_driver();
const Driver& tropp06_driver();
const Driver& yuhe13_driver();

// ---- the pieces the drivers share ----

// A triangle of three points uniform in the unit cube, each coordinate from `rng`.
Triangle unit_cube_triangle(Rng& rng);
// Each coordinate rounded to float (the drivers that keep their triangles in float).
TrianglePair rounded_to_float(const TrianglePair& p);

// `yes` intersecting pairs, then `no` disjoint ones (an outcome-sorted driver's order), from
// `make`, labelled by the oracle in chunks until both classes are full; degenerate ones dropped.
std::vector<TrianglePair> yes_then_no(std::size_t yes, std::size_t no, Rng& rng, TrianglePair (*make)(Rng&),
                                      const std::string& what);
// The same from our ratio pools' candidates (the /ours modifier).
std::vector<TrianglePair> ours_yes_then_no(std::size_t yes, std::size_t no, const WorkloadInput& input);

}  // namespace tritri::bench::paper
