// TRITRI_FORCE_INLINE: for the few helpers of a port that GCC's -O2 heuristics leave out of
// line although each is called from one place per variant. The published codes the ports follow
// write these steps as macros, inlined by construction; a port that is to run as fast as its
// original needs the same (algorithms/moller97/README.md has the measurement).
// TRITRI_INLINE_LAMBDA goes after a lambda's parameter list, for the same reason: a lambda that
// a helper calls from two places is otherwise kept out of line, with everything it captures
// by reference in memory.
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define TRITRI_FORCE_INLINE [[gnu::always_inline]] inline
#define TRITRI_INLINE_LAMBDA __attribute__((always_inline))
#else
#define TRITRI_FORCE_INLINE inline
#define TRITRI_INLINE_LAMBDA
#endif
