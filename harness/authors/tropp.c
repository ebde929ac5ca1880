/* Plug-in "orig-tropp06": Tropp, Tal and Shimshoni's tr_tri_intersect3D (the authors' file, given
 * to scripts/authors-code with --tropp). The routine takes a vertex and two edge vectors per
 * triangle; the wrapper forms them as the port does (A1 − A0, A2 − A0, then B's likewise).
 * Any non-zero return code (coplanar, or a pair of crossed edges) means the triangles meet. */
#include "wrapper.h"

#include "tr_tri_intersect3D.c" /* the --tropp file, copied under this name */

static void overlap(const double* pairs, size_t n, unsigned char* out) {
  size_t i;
  int k;
  for (i = 0; i < n; ++i) {
    const double* a0 = pairs + 18 * i;
    const double* b0 = a0 + 9;
    double p1[3], p2[3], q1[3], q2[3];
    for (k = 0; k < 3; ++k) {
      p1[k] = a0[3 + k] - a0[k];
      p2[k] = a0[6 + k] - a0[k];
      q1[k] = b0[3 + k] - b0[k];
      q2[k] = b0[6 + k] - b0[k];
    }
    out[i] = tr_tri_intersect3D((double*)a0, p1, p2, (double*)b0, q1, q2) ? TRITRI_YES : TRITRI_NO;
  }
}

TRITRI_AUTHORS_PLUGIN("orig-tropp06", "the authors' tr_tri_intersect3D (Tropp, Tal, Shimshoni 2006)",
                      "the authors' code: tr_tri_intersect3D", 0.0, 0, 0)
