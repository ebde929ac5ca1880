// Registering a level: add_level makes an algorithm's entry points for one level from a per-pair
// kernel, generating the batch loops with the kernel inlined into each.
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

}  // namespace tritri
