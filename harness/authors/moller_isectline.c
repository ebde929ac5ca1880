/* Plug-in "orig-moller97-segment": Möller's tri_tri_intersect_with_isectline
 * (tritri_isectline.c), both its 0/1 answer and its segment. Where the routine reads an unset
 * interval (algorithms/moller97/README.md: one triangle's distances all snapped to 0), its
 * answer is whatever that memory held: `tritri diff` counts those cases as differences. */
#include "wrapper.h"

#include "tritri_isectline.c"

static int call(const double* pairs, size_t i, int* coplanar, double* p, double* q) {
  *coplanar = 0;
  return tri_tri_intersect_with_isectline(TRITRI_VERTEX(pairs, i, 0), TRITRI_VERTEX(pairs, i, 1),
                                          TRITRI_VERTEX(pairs, i, 2), TRITRI_VERTEX(pairs, i, 3),
                                          TRITRI_VERTEX(pairs, i, 4), TRITRI_VERTEX(pairs, i, 5), coplanar, p, q);
}

static void overlap(const double* pairs, size_t n, unsigned char* out) {
  size_t i;
  int coplanar;
  double p[3], q[3];
  for (i = 0; i < n; ++i) out[i] = call(pairs, i, &coplanar, p, q) ? TRITRI_YES : TRITRI_NO;
}

static void segment(const double* pairs, size_t n, tritri_segment* out) {
  size_t i;
  int coplanar;
  double p[3], q[3];
  for (i = 0; i < n; ++i) {
    const int meet = call(pairs, i, &coplanar, p, q);
    tritri_authors_segment(meet, coplanar, p, q, &out[i]);
  }
}

static const tritri_plugin kPlugin = {
    TRITRI_PLUGIN_ABI, "orig-moller97-segment", "jgt-code Volume_02/Number_2/Moller1997b/tritri_isectline.c",
    "the authors' code: tri_tri_intersect_with_isectline, float changed to double", 1, 1e-6,
    "|N·V + d|, unnormalised plane distance, snapped to 0 below it", 0, 0, overlap, 0, segment};

TRITRI_AUTHORS_EXPORT const tritri_plugin* tritri_plugin_entry(void) { return &kPlugin; }
