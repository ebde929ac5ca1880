// The plug-in API: what an algorithm declares about itself and the batch entry points the
// harness calls.
//
// The harness never calls an algorithm per pair through a pointer: it hands over an array of
// pairs and an array of answers, so the only indirect call is one per batch and the per-pair
// kernel is inlined into the loop that the adapters below generate.
#pragma once

#include "tritri/answers.hpp"

#include <cstddef>
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

  std::string folder;  // filled in by the registry: the algorithm's folder under algorithms/

  bool answers(Level level) const {
    switch (level) {
      case Level::overlap: return overlap != nullptr;
      case Level::relation: return relation != nullptr;
      case Level::segment: return segment != nullptr;
    }
    return false;
  }
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

class Registry {
 public:
  // Called from each algorithm folder's registration function.
  void add(Algorithm algorithm);

  const std::vector<Algorithm>& all() const { return algorithms_; }
  const Algorithm* find(std::string_view name) const;

  // Used by the generated registration code: the folder the next add() calls come from.
  void set_current_folder(std::string folder) { current_folder_ = std::move(folder); }

 private:
  std::vector<Algorithm> algorithms_;
  std::string current_folder_;
};

// Every built-in algorithm, registered once on first use.
const Registry& registry();

}  // namespace tritri
