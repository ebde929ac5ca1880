// The entry points through which the harness calls an algorithm, in typed storage (no casts):
// per level, a batch entry per scalar type and a one-pair entry on double.
//
// The harness never calls an algorithm per pair through a pointer when it judges or times it: it
// hands over an array of pairs and an array of answers, so the only indirect call is one per
// batch and the per-pair kernel is inlined into the batch loop (tritri/add_level.hpp). The
// one-pair entry is for timing what a caller of one pair at a time pays.
#pragma once

#include "tritri/levels.hpp"

#include <array>
#include <cstddef>
#include <tuple>

namespace tritri {

template <Level L>
using BatchFn = void (*)(const TrianglePair* pairs, std::size_t n, AnswerOf<L>* out);
template <Level L>
using PairFn = AnswerOf<L> (*)(const TrianglePair&);

using OverlapBatch = BatchFn<Level::overlap>;
using RelationBatch = BatchFn<Level::relation>;
using SegmentBatch = BatchFn<Level::segment>;

class EntryPoints {
 public:
  // The batch entry point of level L on scalar S; nullptr when it has none.
  template <Level L>
  BatchFn<L> batch(Scalar s = Scalar::double_) const {
    return of<L>().batch[index(s)];
  }
  template <Level L>
  void set_batch(Scalar s, BatchFn<L> fn) {
    of<L>().batch[index(s)] = fn;
  }
  // The one-pair entry point of level L, on double; nullptr when it has none.
  template <Level L>
  PairFn<L> one_pair() const {
    return of<L>().one_pair;
  }
  template <Level L>
  void set_one_pair(PairFn<L> fn) {
    of<L>().one_pair = fn;
  }

  bool has_batch(Level l, Scalar s = Scalar::double_) const;
  bool has_scalar(Scalar s) const;  // a batch entry on `s` at some level

  // The batch entries of scalar `s` in place of double's, and no others (the one-pair entries
  // are double's own).
  EntryPoints with_scalar_as_double(Scalar s) const;

 private:
  template <Level L>
  struct OfLevel {
    std::array<BatchFn<L>, kScalarCount> batch{};
    PairFn<L> one_pair = nullptr;
  };
  static constexpr std::size_t index(Level l) { return static_cast<std::size_t>(l); }
  static constexpr std::size_t index(Scalar s) { return static_cast<std::size_t>(s); }
  template <Level L>
  OfLevel<L>& of() {
    return std::get<index(L)>(levels_);
  }
  template <Level L>
  const OfLevel<L>& of() const {
    return std::get<index(L)>(levels_);
  }

  std::tuple<OfLevel<Level::overlap>, OfLevel<Level::relation>, OfLevel<Level::segment>> levels_;
};

}  // namespace tritri
