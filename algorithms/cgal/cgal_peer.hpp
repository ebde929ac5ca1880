// CGAL 5.5's CGAL::do_intersect(Triangle_3, Triangle_3) on the Epick kernel
// (Exact_predicates_inexact_constructions_kernel), as a timed peer.
//
// What it is: a sign-only test in the style of Guigue–Devillers 2003, every branch an
// orientation predicate evaluated with CGAL's filtered arithmetic (interval arithmetic first,
// exact multi-precision when the interval cannot decide), so every answer is exact for the
// double coordinates as given. Closed: touching counts. No tolerance.
//
// Degenerate (zero-area) triangles: do_intersect has the precondition that both triangles are
// non-degenerate; Release builds skip the check and then answer wrongly. Not accepted: the
// harness never passes one.
//
// This is not the oracle: the oracle uses Epeck and exact constructions, lives in its own
// library, and is the judge. This peer is timed like any algorithm. CGAL (and its
// -frounding-math) is linked PRIVATE into this folder's library; CGAL's headers are included in
// cgal_peer.cpp only.
#pragma once

#include "tritri/geometry.hpp"

namespace tritri::cgal_peer {

// CGAL's answer for the pair.
bool overlap(const TrianglePair& pair);

}  // namespace tritri::cgal_peer
