/* Stand-in for jgt-code's Shen2003/tri_tri.c: the same routine and signature. */
#include "standin/boxes.h" /* found through harness/authors on the include path */

int tri_tri_intersect(float V0[3], float V1[3], float V2[3], float U0[3], float U1[3], float U2[3]) {
  return STANDIN_BOXES_MEET(V0, V1, V2, U0, U1, U2);
}
