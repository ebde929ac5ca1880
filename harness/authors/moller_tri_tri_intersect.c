/* Plug-in "orig-moller97": Möller's tri_tri_intersect (Volume_02/Number_2/Moller1997b/
 * tritri_isectline.c), the routine the port algorithms/moller97 (variant moller97) follows. */
#include "wrapper.h"

#include "tritri_isectline.c"

TRITRI_AUTHORS_OVERLAP(tri_tri_intersect)

TRITRI_AUTHORS_PLUGIN("orig-moller97", "jgt-code Volume_02/Number_2/Moller1997b/tritri_isectline.c",
                      "the authors' code: tri_tri_intersect" TRITRI_AUTHORS_AS_BUILT, 1e-6,
                      "|N·V + d|, unnormalised plane distance, snapped to 0 below it", 0)
