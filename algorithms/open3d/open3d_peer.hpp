// Open3D 0.16 as a peer: open3d::geometry::IntersectionTest::TriangleTriangle3d, from
// open3d/geometry/IntersectionTest.h (Debian libopen3d-dev).
//
// What the call does (read from Open3D 0.16.1's IntersectionTest.cpp): it centres the six
// points on their mean, divides each axis separately by that axis's standard deviation over
// the six points (+1e-12), and runs Möller's 1997 NoDivTriTriIsect on the result in double with
// its epsilon test on (|du|, |dv| < 1e-6 snapped to 0). The tolerance is therefore on the
// unnormalised plane distance of the rescaled pair: relative to the pair's spread, per axis.
// Touching counts (closed). Degenerate triangles are answered, never refused, but the answer
// depends on argument order (the coplanar projection follows the first normal).
#pragma once

#include "tritri/geometry.hpp"

namespace tritri::open3d_peer {

// Open3D's answer for the pair, called as TriangleTriangle3d(t1[0], t1[1], t1[2], t2[0], ...).
bool overlap(const TrianglePair& pair);

}  // namespace tritri::open3d_peer
