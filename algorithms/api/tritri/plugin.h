/* tritri plug-in ABI, version 1: test your own triangle–triangle test without forking tritri.
 *
 * Build a shared library that exports one function, tritri_plugin_entry(), returning a pointer
 * to a static tritri_plugin that describes your algorithm and gives its batch functions. Then:
 *
 *     tritri check --plugin ./libmine.so cases/builtin.cases
 *
 * Every batch function receives `n` pairs as 18 doubles each, contiguous: T1's vertices a, b, c
 * then T2's, each as x, y, z. It writes one answer per pair to `out`. Set a level's function to
 * NULL if you do not answer that level. tritri runs plug-ins in a child process: a crash or a
 * hang is recorded against the case that caused it, and the run goes on.
 *
 * This header is C (and C++): include it from either. It has no dependencies. */
#ifndef TRITRI_PLUGIN_H
#define TRITRI_PLUGIN_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define TRITRI_PLUGIN_ABI 1

/* overlap level: one unsigned char per pair */
enum { TRITRI_NO = 0, TRITRI_YES = 1, TRITRI_OVERLAP_UNSUPPORTED = 2 };

/* relation level: Yu–He's nine codes, as in tritri's relation vocabulary */
enum {
  TRITRI_DISJOINT = 0,
  TRITRI_CROSS = 1,
  TRITRI_TOUCH_POINT = 2,
  TRITRI_TOUCH_SEGMENT = 3,
  TRITRI_COPLANAR_OVERLAP = -1,
  TRITRI_COPLANAR_DISJOINT = -2,
  TRITRI_COPLANAR_POINT = -3,
  TRITRI_COPLANAR_SEGMENT = -4,
  TRITRI_PARALLEL = -5,
  TRITRI_RELATION_DIMENSION_ONLY = -7, /* only `dimension` is given */
  TRITRI_RELATION_UNSUPPORTED = -8
};
/* dimension of the intersection */
enum { TRITRI_DIM_NONE = 0, TRITRI_DIM_POINT = 1, TRITRI_DIM_SEGMENT = 2, TRITRI_DIM_AREA = 3, TRITRI_DIM_UNKNOWN = -1 };

typedef struct {
  signed char relation;  /* a TRITRI_ relation code */
  signed char dimension; /* a TRITRI_DIM_ code (tritri derives it from `relation` when that is one of the nine) */
} tritri_relation;

/* segment level: the intersection where it is at most one-dimensional */
enum {
  TRITRI_SEGMENT_EMPTY = 0,
  TRITRI_SEGMENT_POINT = 1,   /* p (q == p) */
  TRITRI_SEGMENT_SEGMENT = 2, /* p to q */
  TRITRI_SEGMENT_AREA = 3,    /* coplanar, meeting in a region */
  TRITRI_SEGMENT_COPLANAR = 4, /* coplanar contact, intersection not computed */
  TRITRI_SEGMENT_UNSUPPORTED = 5
};
typedef struct {
  unsigned char kind;
  double p[3];
  double q[3];
} tritri_segment;

typedef struct {
  int abi;              /* TRITRI_PLUGIN_ABI */
  const char* name;     /* short and unique, e.g. "mine" */
  const char* citation; /* where it comes from */
  const char* summary;  /* one line: what it is */
  int closed;           /* 1: touching counts as intersecting; 0: open triangles */
  double tolerance;     /* 0 with tolerance_quantity NULL: no tolerance */
  const char* tolerance_quantity; /* what the tolerance is compared with */
  int tolerance_relative;         /* 1: relative; 0: absolute */
  int accepts_degenerate;         /* 1: pass zero-area triangles too */
  void (*overlap)(const double* pairs, size_t n, unsigned char* out);
  void (*relation)(const double* pairs, size_t n, tritri_relation* out);
  void (*segment)(const double* pairs, size_t n, tritri_segment* out);
} tritri_plugin;

/* The one symbol a plug-in exports. Declared here so that the compiler checks a plug-in's
 * definition against it. */
const tritri_plugin* tritri_plugin_entry(void);
typedef const tritri_plugin* (*tritri_plugin_entry_fn)(void);
#define TRITRI_PLUGIN_ENTRY "tritri_plugin_entry"

#ifdef __cplusplus
}
#endif

#endif /* TRITRI_PLUGIN_H */
