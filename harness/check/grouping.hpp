// `tritri check --group-by`: tallies per group of case labels instead of per family.
//
// The report's stability sweeps and symmetry test count the corpus by other labels than
// family= (by tilt, by scale exponent, by base construction), and a named suite is counted the
// way its paper counts it; grouping here lets `tritri check` do that counting on the corpus
// files as they are, with its own scoring.
#pragma once

#include "cases/casefile.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tritri {

// One grouping: label keys, each optionally fixed to a value ("subsuite=symmetry"). A case is in
// the grouping when it carries every key (with the fixed value, where one is given); its group
// is named by the keys and the case's values as they read in a case file: "subsuite=scale
// tilt=2^-30". The key "@base" stands for the case's name up to its last '.': the corpus names
// each variant base.suffix, so "@base" gathers the variants of one base construction.
struct Grouping {
  struct Key {
    std::string key;
    std::optional<std::string> value;
  };
  std::vector<Key> keys;
};

// "KEY[=VALUE][,KEY[=VALUE]]..."; throws std::invalid_argument on an empty key.
Grouping parse_grouping(std::string_view spec);

// The groups a case is tallied in: without groupings its family alone; else one group for each
// grouping it is in (none when it is in none).
std::vector<std::string> groups_of(const Case& c, const std::vector<Grouping>& groupings);

}  // namespace tritri
