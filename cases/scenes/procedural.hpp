// meshes generated in code, deterministic given their parameters and seed.
//
// Portability of the bits: the sphere, blob, thin shell, terrain and box use only + - * / and
// sqrt (correctly rounded in IEEE 754), so they give the same doubles on any conforming platform
// provided the compiler does not contract a*b+c into an FMA (build with -ffp-contract=off). The
// torus needs sin/cos, which are not correctly rounded everywhere; all generators except the box
// finally snap coordinates to multiples of 2^-20 (`kSnapBits`), which absorbs a last-bit libm
// difference except in the rare case where a value lies next to a rounding boundary. Snapped
// coordinates also make translations by multiples of 2^-20 exact (for |x| < 2^32).
#pragma once

#include <cstdint>

#include "cases/scenes/mesh.hpp"

namespace tritri::scenes {

constexpr int kSnapBits = 20;

// Geodesic sphere: an icosahedron subdivided `level` times, projected on the sphere.
// 20 * 4^level triangles (level 3: 1280, 4: 5120, 5: 20480).
Mesh make_sphere(int level, double radius);

// Ring torus around the z axis: major radius R, tube radius r, `nu` segments around z and `nv`
// around the tube; 2 * nu * nv triangles. With r > R it is a spindle torus, which intersects
// itself near the axis (used by the self-intersection scene).
Mesh make_torus(double R, double r, int nu, int nv);

// A sphere whose radius is modulated by smooth value noise: radius * (1 + amplitude * n(p)),
// n in [-1, 1], frequency in lattice cells per unit. Star-shaped, so never self-intersecting.
Mesh make_blob(int level, double radius, double amplitude, double frequency, std::uint64_t seed);

// Height field over the square [-size/2, size/2]^2 in z-up, n x n cells (2 n^2 triangles),
// heights height * fbm(x, y). Open surface (a sheet), diagonals alternate per cell.
Mesh make_terrain(int n, double size, double height, std::uint64_t seed);

// Closed thin-walled sphere: outer surface of radius `radius`, inner surface of radius
// radius - thickness with reversed orientation, as one mesh (two components).
Mesh make_thin_shell(int level, double radius, double thickness);

// Axis-aligned box [lo, hi] with each face divided into n x n squares (12 n^2 triangles), welded.
// Coordinates are lo + i * (hi - lo) / n; the constructor throws unless every one of them is
// exact (choose dyadic lo, hi and a power-of-two n), so that boxes stacked at a shared z have
// exactly coplanar faces.
Mesh make_box(const Vec3& lo, const Vec3& hi, int n);

// Concatenation of meshes (indices shifted), e.g. two interpenetrating parts of one "mesh".
Mesh concat(const Mesh& a, const Mesh& b, const std::string& name);

}  // namespace tritri::scenes
