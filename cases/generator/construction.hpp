// What a family builds: one base configuration, in a canonical frame where the singularity is
// easy to state, plus the kind of exact frame it may be moved into.
#pragma once

#include "cases/util/random.hpp"
#include "tritri/answers.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tritri::corpus {

using V3 = Vec3<double>;

inline V3 v3(double x, double y, double z) { return V3(x, y, z); }

// A swept label's value, as the report reads it back (reports/tritri_report/groups.py): "2^k".
inline std::string power_of_two(int k) { return "2^" + std::to_string(k); }

// Affine bijections preserve every relation in the vocabulary (incidence, coplanarity,
// parallelism, relative interiors), so a canonical construction can be moved by any of them
// without changing its answer, as long as the arithmetic stays exact: see apply_exactly().
enum class FrameKind {
  general,  // any integer 3x3 matrix with non-zero determinant, integer translation
  planar,   // an integer 2x2 map of x and y; z untouched (keeps exact tilts z = s·y exact)
  axis,     // signed axis permutations and integer translations only (keeps walls and ulps)
  none,     // coordinates stay as built (random pairs)
};

struct Construction {
  Construction(const TrianglePair& p) : pair(p) {}  // implicit: builders return {pair}

  TrianglePair pair;
  FrameKind frame = FrameKind::general;
  std::vector<std::pair<std::string, std::string>> labels;  // config-specific, e.g. tilt=2^-30
};

// One sub-variant of a family: its name, the relation its construction guarantees (none when
// only the oracle can tell), and how to build an instance.
struct Config {
  const char* name;
  std::optional<Relation> expect;
  Construction (*build)(Rng&);
};

struct Family {
  const char* name;
  const char* summary;
  std::vector<Config> configs;
  // Relations the family is meant to produce beyond its configs' expect= (from configs that
  // only the oracle can judge, e.g. random pairs).
  std::vector<Relation> also_produces = {};
  // The coordinates are exactly singular as built, so rounding transformations (rotation,
  // perturbation) make sense on it.
  bool exact = true;
};

// The 16 families, in the order of cases/README.md.
const std::vector<Family>& families();
const Family* find_family(std::string_view name);

// Every relation `family` is meant to produce: its configs' expectations and also_produces.
std::vector<Relation> relations_meant(const Family& family);

// x·m + t for the frame, or nullopt when any step rounds (then another frame is drawn).
struct Frame {
  double m[3][3];
  double t[3];
};
Frame random_frame(Rng& rng, FrameKind kind);
std::optional<TrianglePair> apply_exactly(const Frame& frame, const TrianglePair& pair);

}  // namespace tritri::corpus
