/* Plug-in "orig-shen03": Shen, Heng and Tang's tri_tri_intersect (Volume_08/Number_1/Shen2003/
 * tri_tri.c). Where the routine reads uninitialised pointers (algorithms/shen03/README.md: one
 * triangle's distances all snapped to 0), its answer is undefined: a crash there is recorded
 * against the case by tritri's isolation, and `tritri diff` counts it as a difference. */
#include "wrapper.h"

#include "tri_tri.c"

TRITRI_AUTHORS_OVERLAP(tri_tri_intersect)

TRITRI_AUTHORS_PLUGIN("orig-shen03", "jgt-code Volume_08/Number_1/Shen2003/tri_tri.c",
                      "the authors' code: tri_tri_intersect" TRITRI_AUTHORS_AS_BUILT, 1e-7,
                      "|N·V + d| and the line-line triple products, unnormalised", 0)
