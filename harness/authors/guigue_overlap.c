/* Plug-in "orig-guigue03": Guigue and Devillers' tri_tri_overlap_test_3d
 * (Volume_08/Number_1/Guigue2003/tri_tri_intersect.c; double already, USE_EPSILON_TEST as
 * shipped: off). */
#include "wrapper.h"

#include "tri_tri_intersect.c"

static void overlap(const double* pairs, size_t n, unsigned char* out) {
  size_t i;
  for (i = 0; i < n; ++i)
    out[i] = tri_tri_overlap_test_3d(TRITRI_VERTEX(pairs, i, 0), TRITRI_VERTEX(pairs, i, 1), TRITRI_VERTEX(pairs, i, 2),
                                     TRITRI_VERTEX(pairs, i, 3), TRITRI_VERTEX(pairs, i, 4), TRITRI_VERTEX(pairs, i, 5))
                 ? TRITRI_YES
                 : TRITRI_NO;
}

static const tritri_plugin kPlugin = {
    TRITRI_PLUGIN_ABI, "orig-guigue03", "jgt-code Volume_08/Number_1/Guigue2003/tri_tri_intersect.c",
    "the authors' code: tri_tri_overlap_test_3d", 1, 0.0, 0, 0, 0, overlap, 0, 0};

TRITRI_AUTHORS_EXPORT const tritri_plugin* tritri_plugin_entry(void) { return &kPlugin; }
