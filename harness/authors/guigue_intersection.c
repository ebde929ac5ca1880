/* Plug-in "orig-guigue03-segment": Guigue and Devillers' tri_tri_intersection_test_3d
 * (tri_tri_intersect.c), its 0/1 answer and its segment (source, target). */
#include "wrapper.h"

#include "tri_tri_intersect.c"

static int call(const double* pairs, size_t i, int* coplanar, double* source, double* target) {
  *coplanar = 0;
  return tri_tri_intersection_test_3d(TRITRI_VERTEX(pairs, i, 0), TRITRI_VERTEX(pairs, i, 1),
                                      TRITRI_VERTEX(pairs, i, 2), TRITRI_VERTEX(pairs, i, 3),
                                      TRITRI_VERTEX(pairs, i, 4), TRITRI_VERTEX(pairs, i, 5), coplanar, source,
                                      target);
}

static void overlap(const double* pairs, size_t n, unsigned char* out) {
  size_t i;
  int coplanar;
  double s[3], t[3];
  for (i = 0; i < n; ++i) out[i] = call(pairs, i, &coplanar, s, t) ? TRITRI_YES : TRITRI_NO;
}

static void segment(const double* pairs, size_t n, tritri_segment* out) {
  size_t i;
  int coplanar;
  double s[3], t[3];
  for (i = 0; i < n; ++i) {
    const int meet = call(pairs, i, &coplanar, s, t);
    tritri_authors_segment(meet, coplanar, s, t, &out[i]);
  }
}

static const tritri_plugin kPlugin = {
    TRITRI_PLUGIN_ABI, "orig-guigue03-segment", "jgt-code Volume_08/Number_1/Guigue2003/tri_tri_intersect.c",
    "the authors' code: tri_tri_intersection_test_3d", 1, 0.0, 0, 0, 0, overlap, 0, segment};

TRITRI_AUTHORS_EXPORT const tritri_plugin* tritri_plugin_entry(void) { return &kPlugin; }
