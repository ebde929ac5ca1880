// Hand-built triangles for the ports' own tests: small integers, exact in any arithmetic. In
// namespace tritri, so that a port's tests (in tritri::<port>) name them without more ado.
#pragma once

#include "tritri/geometry.hpp"

namespace tritri {

inline Triangle tri(Vec3<double> a, Vec3<double> b, Vec3<double> c) { return {{a, b, c}}; }

// The same triangle with its orientation flipped (its normal reversed).
inline Triangle reversed(const Triangle& t) { return tri(t[0], t[2], t[1]); }

// The triangle most hand-built pairs are placed against: in the plane z = 0, legs of 4 along x
// and y, counter-clockwise seen from +z.
inline const Triangle kFloor = tri({0, 0, 0}, {4, 0, 0}, {0, 4, 0});

}  // namespace tritri
