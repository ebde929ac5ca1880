#include "algorithms/exact/exact.hpp"

#include "tritri/algorithm.hpp"

namespace tritri {
namespace {

// The scalar path on its own (every pair through the exact classification, no SIMD pass), so
// that `tritri bench` times the two paths separately.
void overlap_scalar_batch(const TrianglePair* pairs, std::size_t n, Overlap* out) {
  exactsimd::overlap_batch_with(exactsimd::Isa::scalar, pairs, n, out);
}
void relation_scalar_batch(const TrianglePair* pairs, std::size_t n, RelationAnswer* out) {
  exactsimd::relation_batch_with(exactsimd::Isa::scalar, pairs, n, out);
}

// The bench records, per pool, how far each pair got: the share the SIMD filter could not decide
// is the cost of exactness (README.md, "Measurements").
// The instruction set the batches ran on is named by a counter "isa:NAME" of 1.
template <bool kSimd>
CounterList path_counts() {
  const exactsimd::Stats& s = exactsimd::stats();
  const exactsimd::Isa isa = kSimd ? exactsimd::active_isa() : exactsimd::Isa::scalar;
  return {{"pairs", s.pairs}, {"undecided_by_simd", s.pending}, {"to_scalar", s.scalar},
          {"grid", s.grid},   {"filtered", s.filtered},         {"declined", s.declined},
          {std::string("isa:") + exactsimd::to_string(isa), 1}};
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
  simd.set_batch<Level::overlap>(Scalar::double_, &exactsimd::overlap_batch);
  simd.set_batch<Level::relation>(Scalar::double_, &exactsimd::relation_batch);
  simd.counters = {&exactsimd::reset_stats, &path_counts<true>};
  registry.add(std::move(simd));
  Algorithm scalar = variant(paper, "exact-scalar",
      "the same answers from the scalar path alone: every pair through the filtered exact classification");
  scalar.set_batch<Level::overlap>(Scalar::double_, &overlap_scalar_batch);
  scalar.set_batch<Level::relation>(Scalar::double_, &relation_scalar_batch);
  scalar.counters = {&exactsimd::reset_stats, &path_counts<false>};
  registry.add(std::move(scalar));
}

}  // namespace tritri
