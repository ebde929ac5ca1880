// FCL's test answers every built-in relation and random pairs as the oracle does, touching
// counting as meeting; on small integers, singular pairs included, it is exact.
#include "harness/testing/tritri/testing.hpp"

TRITRI_ALGORITHM_CONFORMANCE(Fcl, "fcl", exact)
