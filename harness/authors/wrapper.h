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

/* The six vertices of pair i, as the originals' six triangle parameters. */
#define TRITRI_VERTICES(pairs, i)                                                                 \
  TRITRI_VERTEX(pairs, i, 0), TRITRI_VERTEX(pairs, i, 1), TRITRI_VERTEX(pairs, i, 2),              \
      TRITRI_VERTEX(pairs, i, 3), TRITRI_VERTEX(pairs, i, 4), TRITRI_VERTEX(pairs, i, 5)

/* The batch function `overlap` over a routine(six vertices) whose non-zero return means "meet".
 * A macro, not a function taking a pointer: the call stays direct, as in a port, and the
 * originals' parameter types (float changed to double, or double already) need not be spelled. */
#define TRITRI_AUTHORS_OVERLAP(routine)                                                           \
  static void overlap(const double* pairs, size_t n, unsigned char* out) {                        \
    size_t i;                                                                                     \
    for (i = 0; i < n; ++i) out[i] = routine(TRITRI_VERTICES(pairs, i)) ? TRITRI_YES : TRITRI_NO; \
  }

/* The batch functions `overlap` and `segment` over a routine(six vertices, int* coplanar,
 * double end1[3], double end2[3]) returning non-zero where the triangles meet. */
#define TRITRI_AUTHORS_SEGMENT(routine)                                                           \
  static int call(const double* pairs, size_t i, int* coplanar, double* p, double* q) {           \
    *coplanar = 0;                                                                                \
    return routine(TRITRI_VERTICES(pairs, i), coplanar, p, q);                                    \
  }                                                                                               \
  static void overlap(const double* pairs, size_t n, unsigned char* out) {                        \
    size_t i;                                                                                     \
    int coplanar;                                                                                 \
    double p[3], q[3];                                                                            \
    for (i = 0; i < n; ++i) out[i] = call(pairs, i, &coplanar, p, q) ? TRITRI_YES : TRITRI_NO;    \
  }                                                                                               \
  static void segment(const double* pairs, size_t n, tritri_segment* out) {                       \
    size_t i;                                                                                     \
    int coplanar;                                                                                 \
    double p[3], q[3];                                                                            \
    for (i = 0; i < n; ++i) {                                                                     \
      const int meet = call(pairs, i, &coplanar, p, q);                                           \
      tritri_authors_segment(meet, coplanar, p, q, &out[i]);                                      \
    }                                                                                             \
  }

#ifdef __cplusplus
#define TRITRI_AUTHORS_EXTERN_C extern "C"
#else
#define TRITRI_AUTHORS_EXTERN_C
#endif

/* The plug-in: closed triangles, an absolute tolerance (0 and NULL: none), the `overlap` the
 * wrapper defines and `segment_fn` (`segment`, or 0 where the routine gives no segment); and
 * the one exported symbol. */
#define TRITRI_AUTHORS_PLUGIN(name, citation, summary, tolerance, tolerance_quantity, segment_fn)  \
  static const tritri_plugin kPlugin = {TRITRI_PLUGIN_ABI, name, citation, summary, 1, tolerance, \
                                        tolerance_quantity, 0, 0, overlap, 0, segment_fn};        \
  TRITRI_AUTHORS_EXTERN_C TRITRI_AUTHORS_EXPORT const tritri_plugin* tritri_plugin_entry(void) {  \
    return &kPlugin;                                                                              \
  }

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
