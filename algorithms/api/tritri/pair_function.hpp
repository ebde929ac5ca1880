// Temporary (superseded by the API reshape): a level's batch and one-pair entry points on double,
// both from one per-pair function on double, in one line, for the entries that wrap a library
// call or a plain function (the library peers, null).
#pragma once

#include "tritri/algorithm.hpp"

namespace tritri {

template <Level L, auto Fn>
void add_level_function(Algorithm& a) {
  a.set_batch<L>(Scalar::double_, &detail::kernel_batch<L, double, detail::FunctionKernel<Fn>>);
  a.set_one_pair<L>(&one_pair_of<L, Fn>);
}

}  // namespace tritri
