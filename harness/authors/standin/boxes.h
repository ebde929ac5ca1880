/* The stand-in's one test, shared by every stand-in routine: do the triangles' axis-aligned
 * bounding boxes meet? Not a triangle-triangle test (it says yes to many disjoint pairs): it is
 * here so that CI, which has no copy of the authors' code, can build the authors'-code plug-ins
 * and run `tritri diff` and `tritri bench` on them (harness/authors/CMakeLists.txt). The stand-in
 * files declare float arrays, as the originals do, so that scripts/authors-code's float->double
 * change is exercised; this header is not copied, so it is a macro that works on either type. */
#ifndef STANDIN_BOXES_H
#define STANDIN_BOXES_H

#define STANDIN_MAX3(a, b, c) ((a) > (b) ? ((a) > (c) ? (a) : (c)) : ((b) > (c) ? (b) : (c)))
#define STANDIN_MIN3(a, b, c) ((a) < (b) ? ((a) < (c) ? (a) : (c)) : ((b) < (c) ? (b) : (c)))

/* Whether the boxes of (a0, a1, a2) and (b0, b1, b2) overlap along axis k. */
#define STANDIN_AXIS_MEETS(a0, a1, a2, b0, b1, b2, k)                             \
  (!(STANDIN_MAX3(a0[k], a1[k], a2[k]) < STANDIN_MIN3(b0[k], b1[k], b2[k]) ||     \
     STANDIN_MAX3(b0[k], b1[k], b2[k]) < STANDIN_MIN3(a0[k], a1[k], a2[k])))

/* 1 when the boxes of (a0, a1, a2) and (b0, b1, b2) meet on every axis, else 0. */
#define STANDIN_BOXES_MEET(a0, a1, a2, b0, b1, b2)                                                  \
  (STANDIN_AXIS_MEETS(a0, a1, a2, b0, b1, b2, 0) && STANDIN_AXIS_MEETS(a0, a1, a2, b0, b1, b2, 1) && \
   STANDIN_AXIS_MEETS(a0, a1, a2, b0, b1, b2, 2))

/* The body of the stand-in's segment routines: where the boxes meet, the "segment" is the first
 * triangle's edge a0 to a1 (not coplanar), returned as 1; else 0. */
#define STANDIN_BOXES_SEGMENT(a0, a1, a2, b0, b1, b2, coplanar, end1, end2) \
  do {                                                                      \
    int j_;                                                                 \
    if (!STANDIN_BOXES_MEET(a0, a1, a2, b0, b1, b2)) return 0;              \
    *(coplanar) = 0;                                                        \
    for (j_ = 0; j_ < 3; ++j_) {                                            \
      (end1)[j_] = (a0)[j_];                                                \
      (end2)[j_] = (a1)[j_];                                                \
    }                                                                       \
    return 1;                                                               \
  } while (0)

#endif
