// Where `tritri hunt` looks for an algorithm's failures: candidates drawn afresh from the pair
// generators (cases/generator: corpus constructions, the bench's shapes, small-integer and dyadic
// grids, perturbations), walks bisected in doubles down to the last representable steps on each
// side of a decision, and each base candidate also under one of the exact transformations the
// scorecard applies (harness/check/scorecard.hpp) or rounded to float.
#pragma once

#include "cases/generator/exact_pairs.hpp"
#include "cases/util/random.hpp"
#include "tritri/geometry.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

namespace tritri::hunt {

// What was done to a base candidate. `none` is a base candidate itself.
enum class Transform : std::uint8_t {
  none, swap, vertex_order, axis_permutation, scale, translation, to_float, kCount
};
std::string_view to_string(Transform t);

enum class Source : std::uint8_t { corpus, shapes, grid, dyadic, perturbed, walk, kCount };
std::string_view to_string(Source s);

struct Candidate {
  TrianglePair pair;
  std::uint32_t base = 0;  // index in the batch of the base candidate it was made from (itself for a base)
  Transform transform = Transform::none;
  Source source = Source::corpus;
};

// The overlap decision of exact pairs, in batch: what walks bisect on.
using OverlapDecider = std::function<std::vector<bool>(const std::vector<TrianglePair>&)>;

// Batch `index` of the search for `seed`: `size` candidates (about half of them transformed
// copies of the others), the same for the same (seed, index, size) on every machine.
std::vector<Candidate> search_batch(std::uint64_t seed, std::uint64_t index, std::size_t size,
                                    const OverlapDecider& decide);

// `count` walks (walk.cpp): a pair on a decision (touching, or a corpus construction) moved along
// a direction until the decision flips, then bisected on the bit patterns of the step down to two
// adjacent doubles; both sides of each walk's last step are candidates.
std::vector<TrianglePair> walk_pairs(exact_pairs::GenRng& rng, std::size_t count, const OverlapDecider& decide);

// `pair` under transformation `t` with parameters drawn from `rng`: exactly the same geometry up
// to an affine bijection (all but to_float), or nullopt when this draw would round (a scale that
// overflows, a translation that is not exact).
std::optional<TrianglePair> transformed(const TrianglePair& pair, Transform t, Rng& rng);

}  // namespace tritri::hunt
