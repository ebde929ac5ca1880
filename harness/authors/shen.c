/* Plug-in "orig-shen03": Shen, Heng and Tang's tri_tri_intersect (Volume_08/Number_1/Shen2003/
 * tri_tri.c). Where the routine reads uninitialised pointers (algorithms/shen03/README.md: one
 * triangle's distances all snapped to 0), its answer is undefined: a crash there is recorded
 * against the case by tritri's isolation, and `tritri diff` counts it as a difference. */
#include "wrapper.h"

#include "tri_tri.c"

static void overlap(const double* pairs, size_t n, unsigned char* out) {
  size_t i;
  for (i = 0; i < n; ++i)
    out[i] = tri_tri_intersect(TRITRI_VERTEX(pairs, i, 0), TRITRI_VERTEX(pairs, i, 1), TRITRI_VERTEX(pairs, i, 2),
                               TRITRI_VERTEX(pairs, i, 3), TRITRI_VERTEX(pairs, i, 4), TRITRI_VERTEX(pairs, i, 5))
                 ? TRITRI_YES
                 : TRITRI_NO;
}

static const tritri_plugin kPlugin = {
    TRITRI_PLUGIN_ABI, "orig-shen03", "jgt-code Volume_08/Number_1/Shen2003/tri_tri.c",
    "the authors' code: tri_tri_intersect, float changed to double", 1, 1e-7,
    "|N·V + d| and the line-line triple products, unnormalised", 0, 0, overlap, 0, 0};

TRITRI_AUTHORS_EXPORT const tritri_plugin* tritri_plugin_entry(void) { return &kPlugin; }
