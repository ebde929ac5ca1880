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
 * -fvisibility=hidden and exports only tritri_plugin_entry (TRITRI_AUTHORS_EXPORT).
 *
 * TRITRI_AUTHORS_FLOAT (scripts/authors-code defines it for the originals written in float,
 * built as published, unchanged): the routine takes `float v[3]`, so each pair is rounded to
 * float into a local array first (as a port's NAME@float instantiation rounds it inside the
 * call), and the plug-in's name gets "@float", its port's float instantiation's suffix. A
 * float original's summary ends with TRITRI_AUTHORS_AS_BUILT, which says which build it is. */
#ifndef TRITRI_AUTHORS_WRAPPER_H
#define TRITRI_AUTHORS_WRAPPER_H

#include "tritri/plugin.h"

#include <stddef.h>

#define TRITRI_AUTHORS_EXPORT __attribute__((visibility("default")))

#ifdef TRITRI_AUTHORS_FLOAT
typedef float tritri_authors_real;
#define TRITRI_AUTHORS_NAME(name) name "@float"
#define TRITRI_AUTHORS_AS_BUILT ", built as published in float (each pair rounded to float)"
#else
typedef double tritri_authors_real;
#define TRITRI_AUTHORS_NAME(name) name
#define TRITRI_AUTHORS_AS_BUILT ", float changed to double"
#endif

/* Pair i's 18 coordinates as the routine's scalar: in place for double (no copy per pair, as the
 * ports read the pair in place too), rounded into `local` for float. Non-const: the originals'
 * signatures. */
static inline tritri_authors_real* tritri_authors_pair(const double* pairs, size_t i, tritri_authors_real* local) {
#ifdef TRITRI_AUTHORS_FLOAT
  int k;
  for (k = 0; k < 18; ++k) local[k] = (float)pairs[18 * i + k];
  return local;
#else
  (void)local;
  return (double*)(pairs + 18 * i);
#endif
}

/* The six vertices of a pair's 18 coordinates, as the originals' six triangle parameters. */
#define TRITRI_VERTICES(x) (x), (x) + 3, (x) + 6, (x) + 9, (x) + 12, (x) + 15

/* The batch function `overlap` over a routine(six vertices) whose non-zero return means "meet".
 * A macro, not a function taking a pointer: the call stays direct, as in a port, and the
 * originals' parameter types (float changed to double, or double already) need not be spelled. */
#define TRITRI_AUTHORS_OVERLAP(routine)                                                           \
  static void overlap(const double* pairs, size_t n, unsigned char* out) {                        \
    size_t i;                                                                                     \
    tritri_authors_real local[18];                                                                \
    for (i = 0; i < n; ++i) {                                                                     \
      tritri_authors_real* x = tritri_authors_pair(pairs, i, local);                              \
      out[i] = routine(TRITRI_VERTICES(x)) ? TRITRI_YES : TRITRI_NO;                              \
    }                                                                                             \
  }

/* The batch functions `overlap` and `segment` over a routine(six vertices, int* coplanar,
 * double end1[3], double end2[3]) returning non-zero where the triangles meet. */
#define TRITRI_AUTHORS_SEGMENT(routine)                                                           \
  static int call(const double* pairs, size_t i, int* coplanar, tritri_authors_real* p,          \
                  tritri_authors_real* q) {                                                       \
    tritri_authors_real local[18];                                                                \
    tritri_authors_real* x = tritri_authors_pair(pairs, i, local);                                \
    *coplanar = 0;                                                                                \
    return routine(TRITRI_VERTICES(x), coplanar, p, q);                                           \
  }                                                                                               \
  static void overlap(const double* pairs, size_t n, unsigned char* out) {                        \
    size_t i;                                                                                     \
    int coplanar;                                                                                 \
    tritri_authors_real p[3], q[3];                                                               \
    for (i = 0; i < n; ++i) out[i] = call(pairs, i, &coplanar, p, q) ? TRITRI_YES : TRITRI_NO;    \
  }                                                                                               \
  static void segment(const double* pairs, size_t n, tritri_segment* out) {                       \
    size_t i;                                                                                     \
    int coplanar;                                                                                 \
    tritri_authors_real p[3], q[3];                                                               \
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
  static const tritri_plugin kPlugin = {TRITRI_PLUGIN_ABI, TRITRI_AUTHORS_NAME(name), citation,   \
                                        summary, 1, tolerance,                                    \
                                        tolerance_quantity, 0, 0, overlap, 0, segment_fn};        \
  TRITRI_AUTHORS_EXTERN_C TRITRI_AUTHORS_EXPORT const tritri_plugin* tritri_plugin_entry(void) {  \
    return &kPlugin;                                                                              \
  }

/* A segment answer as the ports give it (harness/README.md, segment level): coplanar contact
 * without a segment, empty, a point when both ends are equal, else the segment. */
static inline void tritri_authors_segment(int meet, int coplanar, const tritri_authors_real* p, const tritri_authors_real* q,
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
