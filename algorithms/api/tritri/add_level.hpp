// Registering a level, in one call: add_level makes an algorithm's entry points for one level
// (its batch loops, kernel inlined, and its one-pair entry) from a per-pair kernel, or takes them.
#pragma once

#include "tritri/algorithm.hpp"
#include "tritri/counting.hpp"

#include <cstddef>
#include <type_traits>

namespace tritri {

// A kernel takes `const PairT<T>&` for its scalar T (a double pair is passed as is; any other T
// gets the pair rounded to T) and returns the level's answer type (bool is accepted for overlap).
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

// The one-pair entry: an out-of-line function that runs the same kernel on one pair.
template <Level L, class Kernel>
AnswerOf<L> kernel_one_pair(const TrianglePair& pair) {
  return to_answer<AnswerOf<L>>(Kernel{}(pair));
}

// The kernel takes pairs of scalar T (a generic kernel may be constrained, e.g. to floating point).
template <class Kernel, class T>
inline constexpr bool kTakes = std::is_invocable_v<const Kernel&, const PairT<T>&>;

template <auto Fn>
struct FunctionKernel {
  template <class P>
  decltype(auto) operator()(const P& pair) const {
    return Fn(pair);
  }
};

}  // namespace detail

// A level's batch entry point from a per-pair function of one scalar type: for the harness's
// stand-ins (its tests' fakes, the timing floor), which set it with set_batch and need no
// one-pair entry. An algorithm registers its levels with add_level (below).
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

// Registers level L from a per-pair kernel: a stateless lambda taking `const PairT<T>&`. A port
// is generic over its scalar, e.g.
//   add_level<Level::overlap>(a, []<class T>(const PairT<T>& p) { return overlap<T, true>(p); });
// and gets a batch entry on double, float and the counting scalar (tritri/counting.hpp), each
// scalar the kernel accepts (`[]<std::floating_point T>`: not the counting one); a kernel that
// calls a library takes `const TrianglePair&` and gets double alone. The one-pair entry runs the
// kernel on one double pair.
template <Level L, class Kernel>
void add_level(Algorithm& a, Kernel) {
  static_assert(detail::kTakes<Kernel, double>, "add_level: the kernel must take const PairT<double>&");
  a.set_batch<L>(Scalar::double_, &detail::kernel_batch<L, double, Kernel>);
  if constexpr (detail::kTakes<Kernel, float>) a.set_batch<L>(Scalar::float_, &detail::kernel_batch<L, float, Kernel>);
  if constexpr (detail::kTakes<Kernel, Counted>)
    a.set_batch<L>(Scalar::counted, &detail::kernel_batch<L, Counted, Kernel>);
  a.set_one_pair<L>(&detail::kernel_one_pair<L, Kernel>);
}

// Registers level L from a hand-written batch (on double) and the one-pair function that answers
// as it does.
template <Level L>
void add_level(Algorithm& a, BatchFn<L> batch, PairFn<L> one_pair) {
  a.set_batch<L>(Scalar::double_, batch);
  a.set_one_pair<L>(one_pair);
}

}  // namespace tritri
