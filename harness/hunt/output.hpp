// What `tritri hunt` writes: the witnesses as a case file (one line a group, expect= the
// oracle's relation: paste-ready into a regression file), the JSON document (schema
// "tritri-hunt/1", harness/README.md), and the baseline it reads back (a previous hunt's JSON).
#pragma once

#include "harness/hunt/hunt.hpp"

#include <nlohmann/json_fwd.hpp>

#include <iosfwd>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace tritri::hunt {

// How the hunt was asked for, as the JSON records it.
struct HuntRun {
  std::uint64_t seed = 1;
  std::string level = "overlap";
  std::optional<double> seconds;       // the budget per algorithm
  std::optional<std::size_t> pairs;
  std::optional<double> shrink_seconds;  // the shrinking's budget per algorithm
  std::size_t batch = 0;
  std::vector<std::string> baselines;  // files
  // --shard K/N of a hunt in pairs: its pairs [first, end) of the whole run's total.
  struct Shard {
    std::size_t index = 0, count = 1, first = 0, end = 0, total = 0;
  };
  std::optional<Shard> shard;
};

// One case line per group, named hunt.ALGORITHM.N, labelled expect= (the oracle's relation),
// algorithm=, answered=, level=, plane=, shared=, scale=, transform=, count=.
void write_witnesses(std::ostream& out, const std::vector<HuntResult>& results, const HuntRun& run);

nlohmann::json hunt_json(const std::vector<HuntResult>& results, const HuntRun& run);

// The signatures each algorithm's groups had in a hunt JSON (a baseline): algorithm -> keys.
// Throws InputError naming the file when it is not such a document.
std::map<std::string, std::set<std::string>> read_hunt_baseline(const std::string& path);

// Groups that are not in the baseline.
std::size_t new_groups(const HuntResult& result);

}  // namespace tritri::hunt
