#include "algorithms/exact/exact.hpp"

#include "tritri/add_level.hpp"

namespace tritri {
namespace {

// The scalar path on its own (every pair through the exact classification, no SIMD pass), so
// that `tritri bench` times the two paths separately.
void overlap_scalar_batch(const TrianglePair* pairs, std::size_t n, Overlap* out) {
  exact::overlap_batch_with(exact::Isa::scalar, pairs, n, out);
}
void relation_scalar_batch(const TrianglePair* pairs, std::size_t n, RelationAnswer* out) {
  exact::relation_batch_with(exact::Isa::scalar, pairs, n, out);
}

// The bench records, per pool, how far each pair got: the share the SIMD filter could not decide
// is the cost of exactness (MEASUREMENTS.md, "Measurements: the 9-repetition bench").
// The instruction set the batches ran on is named by a counter "isa:NAME" of 1.
template <bool kSimd>
CounterList path_counts() {
  const exact::Stats& s = exact::stats();
  const exact::Isa isa = kSimd ? exact::active_isa() : exact::Isa::scalar;
  return {{"pairs", s.pairs}, {"undecided_by_simd", s.pending}, {"to_scalar", s.scalar},
          {"filter", s.filter}, {"shared", s.shared},          {"grid", s.grid},
          {"filtered", s.filtered}, {"declined", s.declined}, {"one_pair_route", s.direct},
          {std::string("isa:") + exact::to_string(isa), 1}};
}

}  // namespace

void register_exact(Registry& registry) {
  // Closed, no tolerance: every answer is the oracle's (README.md proves it), zero-area triangles
  // included, answered {Relation::degenerate, dimension} as the oracle labels them. Double only:
  // the error bounds are derived for double, so there is no float or counting instantiation.
  const Declaration paper{.citation = "this project (tritri): algorithms/exact/README.md",
                          .accepts_degenerate = true};
  Algorithm simd = variant(paper, "exact",
      "exact overlap and relation: SIMD lanes of orientation signs with semi-static error bounds, "
      "a grid pass, then an exact scalar classification (integer engine)");
  add_level<Level::overlap>(simd, &exact::overlap_batch, &exact::overlap);
  add_level<Level::relation>(simd, &exact::relation_batch, &exact::relation);
  simd.counters = {&exact::reset_stats, &path_counts<true>};
  registry.add(std::move(simd));
  Algorithm scalar = variant(paper, "exact-scalar",
      "the same answers from the scalar path alone: every pair through the one-pair filter, then the exact "
      "classification");
  // The one-pair API is the scalar path already: both entries share it.
  add_level<Level::overlap>(scalar, &overlap_scalar_batch, &exact::overlap);
  add_level<Level::relation>(scalar, &relation_scalar_batch, &exact::relation);
  scalar.counters = {&exact::reset_stats, &path_counts<false>};
  registry.add(std::move(scalar));
}

}  // namespace tritri
