// The plug-in API: what an algorithm declares about itself and the batch entry points the
// harness calls.
//
// The harness never calls an algorithm per pair through a pointer: it hands over an array of
// pairs and an array of answers, so the only indirect call is one per batch and the per-pair
// kernel is inlined into the loop that the adapters below generate.
#pragma once

#include "tritri/answers.hpp"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace tritri {

// closed: touching (a shared boundary point) counts as intersecting. open: it does not.
enum class Boundary : std::uint8_t { closed, open };

struct Tolerance {
  double value = 0.0;    // 0 with an empty quantity: no tolerance, every comparison is exact-zero
  std::string quantity;  // what it is compared with, e.g. "|d|, unnormalised plane distance"
  bool relative = false;

  bool none() const { return quantity.empty(); }
};

using OverlapBatch = void (*)(const TrianglePair* pairs, std::size_t n, Overlap* out);
using RelationBatch = void (*)(const TrianglePair* pairs, std::size_t n, RelationAnswer* out);
using SegmentBatch = void (*)(const TrianglePair* pairs, std::size_t n, SegmentAnswer* out);

// A part of an algorithm timed on its own by `tritri bench` (the `stage` workload: Yu–He's
// Table 1 times the transform into the frame alone, the test in the frame alone, and both).
//   run      does the stage on a batch and returns a fold (`fold_answer`) of everything it
//            computed, so that none of it can be optimised away; timed.
//   prepare  maps a batch of pairs to the stage's input, not timed; nullptr: the pairs as they
//            are. E.g. the pairs already transformed into A's frame, for the test in the frame.
// Make both from per-pair functions with `stage_run<&fn>` and `stage_prepare<&fn>` (below).
using StageRunBatch = std::uint64_t (*)(const TrianglePair* pairs, std::size_t n);
using StagePrepareBatch = void (*)(const TrianglePair* pairs, std::size_t n, TrianglePair* out);

struct StageEntry {
  std::string name;  // one word, in the benchmark's name: "transform", "frame-test", "both"
  StageRunBatch run = nullptr;
  StagePrepareBatch prepare = nullptr;
};

struct Algorithm {
  std::string name;      // short, unique, used on the command line: "moller97"
  std::string citation;  // full reference
  std::string summary;   // one line: what this entry is (which variant, what it changes)
  Boundary boundary = Boundary::closed;
  Tolerance tolerance;
  bool accepts_degenerate = false;  // zero-area triangles; if false the harness never passes one

  OverlapBatch overlap = nullptr;  // a level is answered when its entry point is set
  RelationBatch relation = nullptr;
  SegmentBatch segment = nullptr;

  // The same port instantiated on float (each pair rounded to float inside the call), for the
  // stability report. Optional; set with the same adapters from the float kernel.
  OverlapBatch overlap_float = nullptr;
  RelationBatch relation_float = nullptr;
  SegmentBatch segment_float = nullptr;

  // The same port instantiated on the operation-counting scalar `Counted`
  // (tritri/counting.hpp), for the operation counts of `tritri bench`. Optional; e.g.
  //   a.overlap_counted = overlap_batch<&overlap<Counted, true>>;
  OverlapBatch overlap_counted = nullptr;
  RelationBatch relation_counted = nullptr;
  SegmentBatch segment_counted = nullptr;

  // Stages timed on their own by `tritri bench` (see StageEntry). Optional.
  std::vector<StageEntry> stages;

  std::string folder;  // filled in by the registry: the algorithm's folder under algorithms/

  // An algorithm in another process, spoken to over a line protocol (harness/process_plugin.hpp)
  // instead of through batch entry points: checked for correctness, never timed.
  struct Process {
    std::string command;
    bool relation = false;  // it answers the relation level as well as overlap
    double timeout_seconds = 5.0;
  };
  std::optional<Process> process;

  bool answers(Level level) const {
    switch (level) {
      case Level::overlap: return overlap != nullptr || process.has_value();
      case Level::relation: return relation != nullptr || (process && process->relation);
      case Level::segment: return segment != nullptr;
    }
    return false;
  }
  // It can be timed: its answers come from batch entry points in this process.
  bool timeable() const { return !process.has_value(); }
  std::string levels() const;  // "overlap,relation"
};

// Adapters from a per-pair kernel to a batch entry point. A kernel takes `const PairT<T>&` for
// its scalar T (a double pair is passed as is; any other T gets the pair rounded to T) and
// returns the level's answer type (bool is accepted for overlap).
namespace detail {
template <class F>
struct kernel_scalar;
template <class R, class T>
struct kernel_scalar<R (*)(const PairT<T>&)> {
  using type = T;
};

template <auto Kernel>
decltype(auto) call_kernel(const TrianglePair& pair) {
  using T = typename kernel_scalar<decltype(Kernel)>::type;
  if constexpr (std::is_same_v<T, double>) {
    return Kernel(pair);
  } else {
    return Kernel(cast<T>(pair));
  }
}
}  // namespace detail

template <auto Kernel>
void overlap_batch(const TrianglePair* pairs, std::size_t n, Overlap* out) {
  for (std::size_t i = 0; i < n; ++i) {
    const auto answer = detail::call_kernel<Kernel>(pairs[i]);
    if constexpr (std::is_same_v<std::decay_t<decltype(answer)>, bool>) {
      out[i] = answer ? Overlap::yes : Overlap::no;
    } else {
      out[i] = answer;
    }
  }
}

template <auto Kernel>
void relation_batch(const TrianglePair* pairs, std::size_t n, RelationAnswer* out) {
  for (std::size_t i = 0; i < n; ++i) out[i] = detail::call_kernel<Kernel>(pairs[i]);
}

template <auto Kernel>
void segment_batch(const TrianglePair* pairs, std::size_t n, SegmentAnswer* out) {
  for (std::size_t i = 0; i < n; ++i) out[i] = detail::call_kernel<Kernel>(pairs[i]);
}

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

// Adapters from per-pair functions to stage batches: `Fn` takes `const TrianglePair&`; for
// stage_prepare it returns a TrianglePair, for stage_run anything `fold_answer` accepts.
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

class Registry {
 public:
  // Called from each algorithm folder's registration function.
  void add(Algorithm algorithm);

  // A deque: pointers to entries stay valid when plug-ins are added later.
  const std::deque<Algorithm>& all() const { return algorithms_; }
  const Algorithm* find(std::string_view name) const;

  // Used by the generated registration code: the folder the next add() calls come from.
  void set_current_folder(std::string folder) { current_folder_ = std::move(folder); }

 private:
  std::deque<Algorithm> algorithms_;
  std::string current_folder_;
};

// Every built-in algorithm, registered once on first use, and any plug-in added since.
const Registry& registry();

// Adds an algorithm from outside the build (a loaded plug-in). Keeps the folder it was given.
const Algorithm& add_external_algorithm(Algorithm algorithm);

}  // namespace tritri
