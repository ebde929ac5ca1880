// Checks on triangle pairs shared by exact's unit tests: the 2-D grid by its definition, boxes
// apart, a triangle proper in (x, y), and every answer against a judge (the tests pass the
// oracle's labelling, from the cases layer: this header stays on the algorithms layer).
#pragma once

#include "algorithms/exact/exact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace tritri::exact_checks {

// The 2-D grid on the pair's (x, y) coordinates, from its definition: m = max |coordinate| in
// [2^-500, 2^500), q = floor(log2 m) - 24, every coordinate an integer multiple of 2^q.
inline bool grid2_reference(const TrianglePair& p) {
  double m = 0.0;
  for (const Triangle* t : {&p.t1, &p.t2})
    for (const auto& v : t->v) m = std::max({m, std::fabs(v[0]), std::fabs(v[1])});
  if (!(m >= 0x1p-500 && m < 0x1p500)) return false;
  const int q = std::ilogb(m) - 24;
  for (const Triangle* t : {&p.t1, &p.t2})
    for (const auto& v : t->v)
      for (int k = 0; k < 2; ++k) {
        const double units = std::ldexp(v[k], -q);
        if (units != std::trunc(units)) return false;
      }
  return true;
}

// The triangles' boxes are apart (pass 1's and the one-pair filter's box exit takes the pair).
inline bool boxes_apart(const TrianglePair& p) {
  const double* c = reinterpret_cast<const double*>(&p);
  return exact::detail::boxes_apart(exact::detail::box_of(c), exact::detail::box_of(c + 9));
}

// The triangle's orientation in (x, y) is non-zero (exact for small coordinates on a grid).
inline bool proper_in_xy(const Triangle& t) {
  return (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[1][1] - t[0][1]) * (t[2][0] - t[0][0]) != 0.0;
}

// Every answer the judge's (`label(pair)`: a record with relation, dimension and overlap, as the
// oracle's): both levels, one pair per call and in batches.
template <class Label>
void expect_oracle(const std::vector<TrianglePair>& pairs, const char* what, Label label) {
  std::vector<Overlap> ov(pairs.size());
  std::vector<RelationAnswer> rel(pairs.size());
  exact::overlap_batch(pairs.data(), pairs.size(), ov.data());
  exact::relation_batch(pairs.data(), pairs.size(), rel.data());
  for (std::size_t n = 0; n < pairs.size(); ++n) {
    const auto o = label(pairs[n]);
    const RelationAnswer a = exact::relation(pairs[n]);
    ASSERT_EQ(a.relation, o.relation) << what << " #" << n << ": " << to_string(a.relation) << " vs "
                                      << to_string(o.relation);
    ASSERT_EQ(a.dimension, o.dimension) << what << " #" << n;
    ASSERT_EQ(exact::overlap(pairs[n]) == Overlap::yes, o.overlap) << what << " #" << n;
    ASSERT_EQ(ov[n] == Overlap::yes, o.overlap) << what << " batch #" << n;
    ASSERT_EQ(rel[n].relation, o.relation) << what << " batch #" << n;
  }
}

}  // namespace tritri::exact_checks
