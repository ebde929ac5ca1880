// For the bench's tests: the options of a small real run.
#pragma once

#include "harness/bench/bench.hpp"

#include <string>
#include <utility>
#include <vector>

namespace tritri::bench {

// The overlap level of `algorithms` on the ratio:0.50 pool of `pool` pairs, briefly timed, no
// operation counts; the JSON to `json` ("" for none).
inline Options small_run(std::vector<const Algorithm*> algorithms, std::size_t pool, int repetitions,
                         std::string json) {
  Options o = quick_options();
  o.algorithms = std::move(algorithms);
  o.levels = {Level::overlap};
  o.workloads = {"ratio:0.5"};
  o.pool_size = pool;
  o.repetitions = repetitions;
  o.min_time = 0.001;
  o.count_operations = false;
  o.json_path = std::move(json);
  return o;
}

}  // namespace tritri::bench
