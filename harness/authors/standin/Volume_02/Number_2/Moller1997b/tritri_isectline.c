/* Stand-in for jgt-code's Moller1997b/tritri_isectline.c: the same three routines, the same
 * signatures, none of the authors' arithmetic (standin/boxes.h says why it exists). */
#include "standin/boxes.h" /* found through harness/authors on the include path */

int tri_tri_intersect(float V0[3], float V1[3], float V2[3], float U0[3], float U1[3], float U2[3]) {
  return STANDIN_BOXES_MEET(V0, V1, V2, U0, U1, U2);
}

int NoDivTriTriIsect(float V0[3], float V1[3], float V2[3], float U0[3], float U1[3], float U2[3]) {
  return STANDIN_BOXES_MEET(V0, V1, V2, U0, U1, U2);
}

/* The "segment" is V0 to V1 whenever the boxes meet. */
int tri_tri_intersect_with_isectline(float V0[3], float V1[3], float V2[3], float U0[3], float U1[3],
                                     float U2[3], int* coplanar, float isectpt1[3], float isectpt2[3]) {
  STANDIN_BOXES_SEGMENT(V0, V1, V2, U0, U1, U2, coplanar, isectpt1, isectpt2);
}
