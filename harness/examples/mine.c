/* An example tritri plug-in in C: a separating-axis triangle–triangle test.
 *
 * Two convex sets are disjoint iff some axis separates their projections. For two triangles
 * the candidates are both normals, the 9 cross products of an edge of one with an edge of the
 * other, and (for coplanar triangles) each normal crossed with each edge. Touching projections
 * count as overlapping, so the triangles are closed. Axes that come out exactly zero (parallel
 * edges) are skipped. It is exact only where the arithmetic is: tritri will show you where not.
 *
 * Build:  cc -O2 -shared -fPIC -I<tritri>/algorithms/api mine.c -o libmine.so
 * Run:    tritri check --plugin ./libmine.so cases/builtin.cases */
#include "tritri/plugin.h"

typedef struct { double x, y, z; } vec;

static vec sub(vec a, vec b) { vec r = {a.x - b.x, a.y - b.y, a.z - b.z}; return r; }
static vec cross(vec a, vec b) {
  vec r = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
  return r;
}
static double dot(vec a, vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/* Does `axis` separate the triangles' projections? */
static int separates(vec axis, const vec* t1, const vec* t2) {
  if (axis.x == 0 && axis.y == 0 && axis.z == 0) return 0;
  double lo1 = dot(axis, t1[0]), hi1 = lo1, lo2 = dot(axis, t2[0]), hi2 = lo2;
  for (int i = 1; i < 3; ++i) {
    const double a = dot(axis, t1[i]), b = dot(axis, t2[i]);
    if (a < lo1) lo1 = a;
    if (a > hi1) hi1 = a;
    if (b < lo2) lo2 = b;
    if (b > hi2) hi2 = b;
  }
  return hi1 < lo2 || hi2 < lo1;
}

static int overlap_one(const double* p) {
  vec t1[3], t2[3], e1[3], e2[3];
  for (int i = 0; i < 3; ++i) {
    vec a = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
    vec b = {p[9 + 3 * i], p[9 + 3 * i + 1], p[9 + 3 * i + 2]};
    t1[i] = a;
    t2[i] = b;
  }
  for (int i = 0; i < 3; ++i) {
    e1[i] = sub(t1[(i + 1) % 3], t1[i]);
    e2[i] = sub(t2[(i + 1) % 3], t2[i]);
  }
  const vec n1 = cross(e1[0], e1[1]), n2 = cross(e2[0], e2[1]);
  if (separates(n1, t1, t2) || separates(n2, t1, t2)) return 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (separates(cross(e1[i], e2[j]), t1, t2)) return 0;
  for (int i = 0; i < 3; ++i)  /* in-plane axes: they decide coplanar pairs */
    if (separates(cross(n1, e1[i]), t1, t2) || separates(cross(n2, e2[i]), t1, t2)) return 0;
  return 1;
}

static void overlap(const double* pairs, size_t n, unsigned char* out) {
  for (size_t i = 0; i < n; ++i) out[i] = overlap_one(pairs + 18 * i) ? TRITRI_YES : TRITRI_NO;
}

static const tritri_plugin kMine = {
    TRITRI_PLUGIN_ABI,
    "mine",
    "an example: the separating-axis theorem, 17 axes",
    "tutorial example plug-in (C ABI): separating axes, closed, no tolerance",
    1,           /* closed: touching counts */
    0.0, 0, 0,   /* no tolerance */
    0,           /* zero-area triangles: not accepted */
    overlap, 0, 0};

const tritri_plugin* tritri_plugin_entry(void) { return &kMine; }
