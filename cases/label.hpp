// The one labeller: the oracle's verdict on many pairs, on every core.
//
// Two records: the full OracleRecord (cases/oracle/oracle.hpp: separation, the exact
// intersection, ...) for case files, and the compact Truth kept beside the millions of pairs of
// bench pools, which is everything a judge of answers needs.
#pragma once

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"

#include <cstddef>
#include <functional>
#include <vector>

namespace tritri {

struct Truth {
  bool overlap = false;
  bool degenerate = false;                 // a triangle has zero area
  Relation relation = Relation::disjoint;  // Relation::degenerate when `degenerate`
  Dimension dimension = Dimension::none;
  Stage stage = Stage::interval;
};

Truth truth_of(const OracleRecord& record);

// Reports (done, total) as labelling goes; may be empty.
using LabelProgress = std::function<void(std::size_t, std::size_t)>;

// The full records of `cases`. An oracle failure names the case (file, line, name).
std::vector<OracleRecord> label_cases(const std::vector<Case>& cases, const LabelProgress& progress = {});

// The compact records of `pairs`.
std::vector<Truth> label_pairs(const std::vector<TrianglePair>& pairs, const LabelProgress& progress = {});

}  // namespace tritri
