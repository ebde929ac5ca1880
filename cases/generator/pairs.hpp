// Random pairs of proper triangles for the conformance suites and the ports' tests, and the
// differential fuzzer's recipe that turns bytes into a near-singular pair. The other generators
// live beside this: shapes.hpp (the bench's pair shapes), exact_pairs.hpp (the exact test's),
// the corpus families (families_*.cpp) and their transformations (variants.hpp).
#pragma once

#include "tritri/geometry.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tritri::pairs {

// Proper triangles with coordinates uniform in [-1, 1]: general position (touching, coplanar
// and parallel pairs have probability zero).
std::vector<TrianglePair> random_pairs(std::uint64_t seed, std::size_t count);
// Proper triangles with integer coordinates in [-range, range]: vertices on planes, edges and
// vertices of the other triangle, coplanar pairs; exact in any arithmetic.
std::vector<TrianglePair> random_grid_pairs(std::uint64_t seed, std::size_t count, int range);
// Where a counting instantiation must answer exactly as double: random pairs, small-integer
// pairs (where the last bit decides) and the built-in cases.
std::vector<TrianglePair> counting_pairs();

// Bytes read one at a time; zeros once they run out.
struct ByteReader {
  const std::uint8_t* data;
  std::size_t size, at = 0;
  std::uint8_t byte() { return at < size ? data[at++] : 0; }
};

// The fuzzer's recipe: coordinates on a small integer grid (shared vertices, coplanar and
// collinear contact happen often), then optional tiny nudges, scales and offsets by powers of two
// and one arbitrary double.
TrianglePair recipe_pair(ByteReader& r);

}  // namespace tritri::pairs
