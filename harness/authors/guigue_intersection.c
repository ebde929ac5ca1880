/* Plug-in "orig-guigue03-segment": Guigue and Devillers' tri_tri_intersection_test_3d
 * (tri_tri_intersect.c), its 0/1 answer and its segment (source, target). */
#include "wrapper.h"

#include "tri_tri_intersect.c"

TRITRI_AUTHORS_SEGMENT(tri_tri_intersection_test_3d)

TRITRI_AUTHORS_PLUGIN("orig-guigue03-segment", "jgt-code Volume_08/Number_1/Guigue2003/tri_tri_intersect.c",
                      "the authors' code: tri_tri_intersection_test_3d", 0.0, 0, segment)
