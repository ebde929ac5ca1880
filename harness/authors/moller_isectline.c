/* Plug-in "orig-moller97-segment": Möller's tri_tri_intersect_with_isectline
 * (tritri_isectline.c), both its 0/1 answer and its segment. Where the routine reads an unset
 * interval (algorithms/moller97/README.md: one triangle's distances all snapped to 0), its
 * answer is whatever that memory held: `tritri diff` counts those cases as differences. */
#include "wrapper.h"

#include "tritri_isectline.c"

TRITRI_AUTHORS_SEGMENT(tri_tri_intersect_with_isectline)

TRITRI_AUTHORS_PLUGIN("orig-moller97-segment", "jgt-code Volume_02/Number_2/Moller1997b/tritri_isectline.c",
                      "the authors' code: tri_tri_intersect_with_isectline" TRITRI_AUTHORS_AS_BUILT, 1e-6,
                      "|N·V + d|, unnormalised plane distance, snapped to 0 below it", segment)
