// CGAL's filtered do_intersect is exact: it agrees with the oracle on contact as well as in
// general position, which is all there is to test of it.
#include "harness/testing/tritri/testing.hpp"

TRITRI_ALGORITHM_CONFORMANCE(Cgal, "cgal", exact)
