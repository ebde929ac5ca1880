// The judge of cases: the truth about each pair, decided exactly and as cheaply as possible.
//
// `exact` (algorithms/exact: orientation signs with semi-static filters and an exact fallback,
// for every finite double input the oracle's answers) decides overlap and relation; the CGAL
// oracle (oracle.hpp) judges what `exact` declines, the exact intersection where it is asked for
// (the segment level), and a seeded sample of every run, as a cross-check of the two exact
// tests: a disagreement there throws JudgeDisagreement, never a silent answer. The sample is
// drawn per case from the seed and the case's place in the whole input, so the shards of a run
// cross-check exactly the cases one run would. JudgeKind::oracle asks CGAL for every case.
#pragma once

#include "cases/casefile.hpp"
#include "cases/oracle/oracle.hpp"

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace tritri {

enum class JudgeKind : std::uint8_t { exact_first, oracle };
const char* to_string(JudgeKind kind);  // "exact-first", "oracle"
JudgeKind judge_kind_of(const std::string& word);  // throws std::invalid_argument

struct JudgeOptions {
  JudgeKind kind = JudgeKind::exact_first;
  // The exact intersection is wanted (an algorithm answers the segment level): the oracle's
  // record for every case `exact` finds meeting in a point or a segment.
  bool geometry = false;
  std::uint64_t seed = 1;           // which cases the oracle cross-checks
  std::uint64_t sample_one_in = 64; // about one case in this many; 0: none
};

// How many cases each judge decided, and how many the oracle cross-checked (a sum over shards).
struct JudgeCounts {
  std::uint64_t exact = 0;          // overlap and relation from `exact`
  std::uint64_t oracle = 0;         // the whole record from the oracle
  std::uint64_t cross_checked = 0;  // decided by `exact`, confirmed by the oracle
  void add(const JudgeCounts& o) { exact += o.exact, oracle += o.oracle, cross_checked += o.cross_checked; }
};

class JudgeDisagreement : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The records of `cases`, cases[i] being case first_index + i of the whole input. A record from
// `exact` holds overlap, relation, dimension and degenerate (separation NaN, no intersection
// points, stage and planes as a default record); one from the oracle holds everything. An
// oracle failure names the case (file, line, name), as label_cases does.
std::vector<OracleRecord> judge_cases(const std::vector<Case>& cases, std::size_t first_index,
                                      const JudgeOptions& options, JudgeCounts& counts);

// Whether case `index` of a run seeded `seed` is in the oracle's cross-check sample.
bool cross_checked(std::uint64_t seed, std::uint64_t sample_one_in, std::size_t index);

}  // namespace tritri
