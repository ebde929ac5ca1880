// The plug-in API: what an algorithm declares about itself and the batch entry points the
// harness calls.
//
// The harness never calls an algorithm per pair through a pointer: it hands over an array of
// pairs and an array of answers, so the only indirect call is one per batch and the per-pair
// kernel is inlined into the loop that the adapters below generate.
#pragma once

#include "tritri/answers.hpp"
#include "tritri/counting.hpp"

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
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

// The answer type of each level, and the batch entry point that produces it.
template <Level L>
struct LevelAnswer;
template <>
struct LevelAnswer<Level::overlap> {
  using type = Overlap;
};
template <>
struct LevelAnswer<Level::relation> {
  using type = RelationAnswer;
};
template <>
struct LevelAnswer<Level::segment> {
  using type = SegmentAnswer;
};
template <Level L>
using AnswerOf = typename LevelAnswer<L>::type;

template <class Answer>
using BatchFn = void (*)(const TrianglePair* pairs, std::size_t n, Answer* out);
using OverlapBatch = BatchFn<Overlap>;
using RelationBatch = BatchFn<RelationAnswer>;
using SegmentBatch = BatchFn<SegmentAnswer>;
template <Level L>
using LevelBatch = BatchFn<AnswerOf<L>>;

inline constexpr Level kLevels[] = {Level::overlap, Level::relation, Level::segment};

// The scalar type a port is instantiated on. `double` is the port itself (what check and bench
// judge and time); `float` rounds each pair to float inside the call (the stability report);
// `counted` is the operation-counting scalar of tritri/counting.hpp (bench's operation counts).
enum class Scalar : std::uint8_t { double_, float_, counted };
inline constexpr Scalar kScalars[] = {Scalar::double_, Scalar::float_, Scalar::counted};
std::string_view to_string(Scalar);  // "double", "float", "counted"

// Calls f(std::integral_constant<Level, L>{}) for each level: code that must handle each level
// with its own answer type writes one generic lambda instead of a switch.
template <class F>
void for_each_level(F&& f) {
  f(std::integral_constant<Level, Level::overlap>{});
  f(std::integral_constant<Level, Level::relation>{});
  f(std::integral_constant<Level, Level::segment>{});
}

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

// Where an algorithm's batches went, as named counts (e.g. the exact test: pairs left undecided by
// its SIMD filter, pairs decided by its exact engine). `tritri bench` resets them, runs each
// level once over each pool on the calling thread, untimed, and records what `read` returns.
using CounterList = std::vector<std::pair<std::string, std::uint64_t>>;
struct PathCounters {
  void (*reset)() = nullptr;
  CounterList (*read)() = nullptr;
  explicit operator bool() const { return reset && read; }
};

// What an algorithm says about itself, for registering it in one expression:
//   Algorithm a({.name = "moller97", .citation = kCitation, .summary = "...", .tolerance = snap});
struct Declaration {
  std::string name;
  std::string citation;
  std::string summary;
  Boundary boundary = Boundary::closed;
  Tolerance tolerance = {};
  bool accepts_degenerate = false;
};

struct Algorithm;
// One variant of a paper's entry: the paper's declaration under the variant's name and summary.
Algorithm variant(Declaration paper, std::string name, std::string summary);

struct Algorithm {
  Algorithm() = default;
  explicit Algorithm(Declaration d)
      : name(std::move(d.name)),
        citation(std::move(d.citation)),
        summary(std::move(d.summary)),
        boundary(d.boundary),
        tolerance(std::move(d.tolerance)),
        accepts_degenerate(d.accepts_degenerate) {}

  std::string name;      // short, unique, used on the command line: "moller97"
  std::string citation;  // full reference
  std::string summary;   // one line: what this entry is (which variant, what it changes)
  Boundary boundary = Boundary::closed;
  Tolerance tolerance;
  bool accepts_degenerate = false;  // zero-area triangles; if false the harness never passes one

  // How the harness reaches it: batch entry points in this process (timed), or another process
  // spoken to over a line protocol (harness/run/process_plugin.hpp: checked, never timed).
  enum class Kind : std::uint8_t { batch, process };
  Kind kind = Kind::batch;
  struct Process {
    std::string command;
    bool relation = false;  // it answers the relation level as well as overlap
    double timeout_seconds = 5.0;
  };
  Process process;  // Kind::process only

  // Stages timed on their own by `tritri bench` (see StageEntry). Optional.
  std::vector<StageEntry> stages;
  // Counts of the paths its batches took (see PathCounters). Optional.
  PathCounters counters;

  std::string folder;  // filled in by the registry: the algorithm's folder under algorithms/
  // "" for the project's build; the build variant's name ("v3fma") for an entry of a second build
  // of the same code (algorithms/api/build_variants.hpp). Variants double a run's time, so they
  // run when named (--algo NAME@v3fma), not by default.
  std::string build;

  // The batch entry point of level L on scalar S; nullptr when it has none.
  template <Level L>
  LevelBatch<L> batch(Scalar s = Scalar::double_) const {
    return reinterpret_cast<LevelBatch<L>>(table_[index(L)][index(s)]);
  }
  template <Level L>
  void set_batch(Scalar s, LevelBatch<L> fn) {
    table_[index(L)][index(s)] = reinterpret_cast<Erased>(fn);
  }
  bool has_batch(Level l, Scalar s = Scalar::double_) const { return table_[index(l)][index(s)] != nullptr; }
  bool has_scalar(Scalar s) const {
    for (Level l : kLevels)
      if (has_batch(l, s)) return true;
    return false;
  }

  // It answers `level` (through a batch entry point on double, or as a process).
  bool answers(Level level) const {
    if (kind == Kind::process) return level == Level::overlap || (level == Level::relation && process.relation);
    return has_batch(level);
  }
  // It can be timed: its answers come from batch entry points in this process.
  bool timeable() const { return kind == Kind::batch; }
  std::string levels() const;  // "overlap,relation"

  // The same algorithm answering through its instantiation on `s` in place of double, named
  // NAME@float (or @counted), with no stages; nullopt when it has no such instantiation.
  std::optional<Algorithm> on_scalar(Scalar s) const;

 private:
  using Erased = void (*)();
  static constexpr std::size_t index(Level l) { return static_cast<std::size_t>(l); }
  static constexpr std::size_t index(Scalar s) { return static_cast<std::size_t>(s); }
  std::array<std::array<Erased, 3>, 3> table_{};  // [level][scalar]
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

template <class T, class Kernel>
decltype(auto) call_on(const Kernel& kernel, const TrianglePair& pair) {
  if constexpr (std::is_same_v<T, double>) {
    return kernel(pair);
  } else {
    return kernel(cast<T>(pair));
  }
}

template <class Answer, class Result>
Answer to_answer(Result&& r) {
  if constexpr (std::is_same_v<Answer, Overlap> && std::is_same_v<std::decay_t<Result>, bool>) {
    return r ? Overlap::yes : Overlap::no;
  } else {
    return r;
  }
}

// The batch loop of level L over a stateless kernel object (a function wrapper or a lambda),
// instantiated on scalar T: the kernel is inlined into it.
template <Level L, class T, class Kernel>
void kernel_batch(const TrianglePair* pairs, std::size_t n, AnswerOf<L>* out) {
  const Kernel kernel{};
  for (std::size_t i = 0; i < n; ++i) out[i] = to_answer<AnswerOf<L>>(call_on<T>(kernel, pairs[i]));
}

template <auto Fn>
struct FunctionKernel {
  template <class P>
  decltype(auto) operator()(const P& pair) const {
    return Fn(pair);
  }
};

}  // namespace detail

// A level's batch entry point from a per-pair function of one scalar type.
template <auto Kernel>
void overlap_batch(const TrianglePair* pairs, std::size_t n, Overlap* out) {
  using T = typename detail::kernel_scalar<decltype(Kernel)>::type;
  detail::kernel_batch<Level::overlap, T, detail::FunctionKernel<Kernel>>(pairs, n, out);
}
template <auto Kernel>
void relation_batch(const TrianglePair* pairs, std::size_t n, RelationAnswer* out) {
  using T = typename detail::kernel_scalar<decltype(Kernel)>::type;
  detail::kernel_batch<Level::relation, T, detail::FunctionKernel<Kernel>>(pairs, n, out);
}
template <auto Kernel>
void segment_batch(const TrianglePair* pairs, std::size_t n, SegmentAnswer* out) {
  using T = typename detail::kernel_scalar<decltype(Kernel)>::type;
  detail::kernel_batch<Level::segment, T, detail::FunctionKernel<Kernel>>(pairs, n, out);
}

// Registers level L of a port templated on its scalar, in one line: `Kernel` is a stateless
// generic lambda taking `const PairT<T>&`, e.g.
//   add_level<Level::overlap>(a, []<class T>(const PairT<T>& p) { return overlap<T, true>(p); });
// It is instantiated on double, float and the counting scalar (tritri/counting.hpp).
template <Level L, class Kernel>
void add_level(Algorithm& a, Kernel) {
  a.set_batch<L>(Scalar::double_, &detail::kernel_batch<L, double, Kernel>);
  a.set_batch<L>(Scalar::float_, &detail::kernel_batch<L, float, Kernel>);
  a.set_batch<L>(Scalar::counted, &detail::kernel_batch<L, Counted, Kernel>);
}
// The same on double alone, for tests that call a library on double (FCL, CGAL).
template <Level L, class Kernel>
void add_level_double(Algorithm& a, Kernel) {
  a.set_batch<L>(Scalar::double_, &detail::kernel_batch<L, double, Kernel>);
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
