// The transformation sub-suites (the subsuite= label). Each takes a base case and appends its
// transformed copies. Exact transformations keep expect=; rounding ones drop it, since the
// oracle alone knows the truth of the rounded input.
#pragma once

#include "cases/casefile.hpp"
#include "cases/util/random.hpp"

#include <optional>
#include <vector>

namespace tritri::corpus {

struct VariantPlan {
  int symmetry = 72;  // how many of the 72 symmetry variants (the identity is always one)
  int scales = 2;     // scalings by 2^k, k in [-40, 40]
  int translations = 2;
  int rotations = 2;
  bool perturb = true;  // delta in 1e-16, 1e-14, ..., 1e-2, both directions: 16 cases
};

// Every coordinate times 2^k, or nullopt when one overflows, reaches the subnormals or rounds.
std::optional<TrianglePair> scaled_exactly(TrianglePair pair, int k);
// Every vertex plus `offset`, or nullopt when a sum rounds (TwoSum).
std::optional<TrianglePair> translated_exactly(TrianglePair pair, const Vec3<double>& offset);

// All 6 vertex orders of T1 × all 6 of T2 × both argument orders; the identity first.
void add_symmetry_variants(const Case& base, int count, Rng& rng, std::vector<Case>& out);
// Scaling by 2^k: exact unless it overflows or reaches subnormals, and then k is redrawn.
void add_scale_variants(const Case& base, int count, Rng& rng, std::vector<Case>& out);
// Translation by 2^k·(s1, s2, s3), s in {-1, 0, 1}: kept only where every sum is exact.
void add_translate_variants(const Case& base, int count, Rng& rng, std::vector<Case>& out);
// A uniformly random rotation about the origin, rounded to double.
void add_rotate_variants(const Case& base, int count, Rng& rng, std::vector<Case>& out);
// T2's first vertex (where constructions put the singular one) moved by ±delta × the pair's
// size along one random direction per base case.
void add_perturb_variants(const Case& base, Rng& rng, std::vector<Case>& out);

}  // namespace tritri::corpus
