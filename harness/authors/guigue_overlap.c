/* Plug-in "orig-guigue03": Guigue and Devillers' tri_tri_overlap_test_3d
 * (Volume_08/Number_1/Guigue2003/tri_tri_intersect.c; double already, USE_EPSILON_TEST as
 * shipped: off). */
#include "wrapper.h"

#include "tri_tri_intersect.c"

TRITRI_AUTHORS_OVERLAP(tri_tri_overlap_test_3d)

TRITRI_AUTHORS_PLUGIN("orig-guigue03", "jgt-code Volume_08/Number_1/Guigue2003/tri_tri_intersect.c",
                      "the authors' code: tri_tri_overlap_test_3d", 0.0, 0, 0)
