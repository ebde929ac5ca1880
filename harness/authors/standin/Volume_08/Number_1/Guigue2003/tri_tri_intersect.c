/* Stand-in for jgt-code's Guigue2003/tri_tri_intersect.c: the same two routines and signatures
 * (double, as the original), none of the authors' arithmetic. */
#include "standin/boxes.h" /* found through harness/authors on the include path */

int tri_tri_overlap_test_3d(double p1[3], double q1[3], double r1[3], double p2[3], double q2[3], double r2[3]) {
  return STANDIN_BOXES_MEET(p1, q1, r1, p2, q2, r2);
}

int tri_tri_intersection_test_3d(double p1[3], double q1[3], double r1[3], double p2[3], double q2[3],
                                 double r2[3], int* coplanar, double source[3], double target[3]) {
  STANDIN_BOXES_SEGMENT(p1, q1, r1, p2, q2, r2, coplanar, source, target);
}
