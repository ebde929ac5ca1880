/* Plug-in "orig-moller97": Möller's tri_tri_intersect (Volume_02/Number_2/Moller1997b/
 * tritri_isectline.c), the routine the port algorithms/moller97 (variant moller97) follows. */
#include "wrapper.h"

#include "tritri_isectline.c"

static void overlap(const double* pairs, size_t n, unsigned char* out) {
  size_t i;
  for (i = 0; i < n; ++i)
    out[i] = tri_tri_intersect(TRITRI_VERTEX(pairs, i, 0), TRITRI_VERTEX(pairs, i, 1), TRITRI_VERTEX(pairs, i, 2),
                               TRITRI_VERTEX(pairs, i, 3), TRITRI_VERTEX(pairs, i, 4), TRITRI_VERTEX(pairs, i, 5))
                 ? TRITRI_YES
                 : TRITRI_NO;
}

static const tritri_plugin kPlugin = {
    TRITRI_PLUGIN_ABI, "orig-moller97", "jgt-code Volume_02/Number_2/Moller1997b/tritri_isectline.c",
    "the authors' code: tri_tri_intersect, float changed to double", 1, 1e-6,
    "|N·V + d|, unnormalised plane distance, snapped to 0 below it", 0, 0, overlap, 0, 0};

TRITRI_AUTHORS_EXPORT const tritri_plugin* tritri_plugin_entry(void) { return &kPlugin; }
