/* Stand-in for the authors' file with tr_tri_intersect3D: the same signature (a vertex and two
 * edge vectors per triangle), none of the authors' arithmetic. Returns 12 (a code the original
 * uses for "edges 1 and 2 cross") where the bounding boxes meet, else 0. */
#include "standin/boxes.h" /* found through harness/authors on the include path */

int tr_tri_intersect3D(double* C1, double* P1, double* P2, double* D1, double* Q1, double* Q2) {
  double a[3][3], b[3][3];
  int k;
  for (k = 0; k < 3; ++k) {
    a[0][k] = C1[k];
    a[1][k] = C1[k] + P1[k];
    a[2][k] = C1[k] + P2[k];
    b[0][k] = D1[k];
    b[1][k] = D1[k] + Q1[k];
    b[2][k] = D1[k] + Q2[k];
  }
  return STANDIN_BOXES_MEET(a[0], a[1], a[2], b[0], b[1], b[2]) ? 12 : 0;
}
