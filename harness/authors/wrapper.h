/* What every authors'-code wrapper shares: how a tritri batch reaches an original routine.
 *
 * A batch is n pairs of 18 doubles (plugin.h). The originals take `double v[3]` parameters (after
 * the float->double copy that scripts/authors-code makes) and never write to them, so the
 * wrappers pass pointers into the batch itself: no copy per pair, as the ports read the pair in
 * place too. The segment variants' coplanar flag is set by the originals on some paths only (the
 * callers initialise it, as their readme files say): the wrappers set it to 0 first.
 *
 * Each wrapper #includes the one source file it wraps (the copy in the build directory), so the
 * original's static helpers and macros stay private to its plug-in; every plug-in is built with
 * -fvisibility=hidden and exports only tritri_plugin_entry (TRITRI_AUTHORS_EXPORT). */
#ifndef TRITRI_AUTHORS_WRAPPER_H
#define TRITRI_AUTHORS_WRAPPER_H

#include "tritri/plugin.h"

#include <stddef.h>

#define TRITRI_AUTHORS_EXPORT __attribute__((visibility("default")))

/* Vertex k (0..5: T1's a, b, c, then T2's) of pair i. Non-const: the originals' signatures. */
#define TRITRI_VERTEX(pairs, i, k) ((double*)((pairs) + 18 * (i) + 3 * (k)))

/* A segment answer as the ports give it (harness/README.md, segment level): coplanar contact
 * without a segment, empty, a point when both ends are equal, else the segment. */
static inline void tritri_authors_segment(int meet, int coplanar, const double* p, const double* q,
                                          tritri_segment* out) {
  int i;
  if (!meet) {
    out->kind = TRITRI_SEGMENT_EMPTY;
    return;
  }
  if (coplanar) {
    out->kind = TRITRI_SEGMENT_COPLANAR;
    return;
  }
  for (i = 0; i < 3; ++i) {
    out->p[i] = p[i];
    out->q[i] = q[i];
  }
  out->kind = (p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) ? TRITRI_SEGMENT_POINT : TRITRI_SEGMENT_SEGMENT;
}

#endif
