// The type workload: pools of one intersection type each.
//
//   type:T    only pairs whose intersection, per the oracle, has dimension T: disjoint (none),
//             point, segment or area (Sabharwal–Leopold's Table 1). Contacts are constructed
//             exactly in dyadic coordinates, so a "point" pair really touches in one point.
#pragma once

#include "harness/bench/pools.hpp"

#include <string>

namespace tritri::bench {

// The four intersection types, in Sabharwal–Leopold's order.
inline constexpr Dimension kTypes[] = {Dimension::none, Dimension::point, Dimension::segment,
                                       Dimension::area};
std::string type_text(Dimension d);  // "disjoint", "point", "segment", "area"
Pool type_pool(Dimension type, const PoolOptions& options);

}  // namespace tritri::bench
