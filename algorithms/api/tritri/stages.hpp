// Stages: parts of an algorithm timed on their own by `tritri bench`, and the checksum fold
// (fold_answer) that keeps what a timed loop computes from being optimised away.
//
// The stage workload times Yu–He's Table 1: the transform into the frame alone, the test in the
// frame alone, and both.
//   run      does the stage on a batch and returns a fold (`fold_answer`) of everything it
//            computed, so that none of it can be optimised away; timed.
//   prepare  maps a batch of pairs to the stage's input, not timed; nullptr: the pairs as they
//            are. E.g. the pairs already transformed into A's frame, for the test in the frame.
// Make both from per-pair functions with `stage_run<&fn>` and `stage_prepare<&fn>`: the function
// is a template argument, so it is inlined into the stage's loop.
#pragma once

#include "tritri/answers.hpp"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>

namespace tritri {

// Folds an answer (or any value a stage computes) into a 64-bit checksum term: cheap, and
// dependent on every bit the caller must not let the compiler drop.
inline std::uint64_t fold_answer(bool b) { return b ? 1u : 0u; }
inline std::uint64_t fold_answer(Overlap o) { return static_cast<std::uint8_t>(o); }
inline std::uint64_t fold_answer(double x) { return std::bit_cast<std::uint64_t>(x); }
inline std::uint64_t fold_answer(float x) { return std::bit_cast<std::uint32_t>(x); }
inline std::uint64_t fold_answer(int x) { return static_cast<std::uint64_t>(x); }
inline std::uint64_t fold_answer(const RelationAnswer& a) {
  return static_cast<std::uint8_t>(a.relation) * 16u + static_cast<std::uint8_t>(a.dimension);
}
inline std::uint64_t fold_answer(const Vec3<double>& v) {
  return fold_answer(v[0]) + fold_answer(v[1]) + fold_answer(v[2]);
}
inline std::uint64_t fold_answer(const SegmentAnswer& s) {
  return static_cast<std::uint8_t>(s.kind) + fold_answer(s.p) + fold_answer(s.q);
}
inline std::uint64_t fold_answer(const Triangle& t) {
  return fold_answer(t[0]) + fold_answer(t[1]) + fold_answer(t[2]);
}
inline std::uint64_t fold_answer(const TrianglePair& p) { return fold_answer(p.t1) + fold_answer(p.t2); }

using StageRunBatch = std::uint64_t (*)(const TrianglePair* pairs, std::size_t n);
using StagePrepareBatch = void (*)(const TrianglePair* pairs, std::size_t n, TrianglePair* out);

struct StageEntry {
  std::string name;  // one word, in the benchmark's name: "transform", "frame-test", "both"
  StageRunBatch run = nullptr;
  StagePrepareBatch prepare = nullptr;
};

// `Fn` takes `const TrianglePair&`; for stage_run it returns anything `fold_answer` accepts, for
// stage_prepare a TrianglePair.
template <auto Fn>
std::uint64_t stage_run(const TrianglePair* pairs, std::size_t n) {
  std::uint64_t sum = 0;
  for (std::size_t i = 0; i < n; ++i) sum += fold_answer(Fn(pairs[i]));
  return sum;
}

template <auto Fn>
void stage_prepare(const TrianglePair* pairs, std::size_t n, TrianglePair* out) {
  for (std::size_t i = 0; i < n; ++i) out[i] = Fn(pairs[i]);
}

}  // namespace tritri
