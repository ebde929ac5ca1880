// A deliberately broken plug-in, for testing the harness's isolation: it segfaults when a
// coordinate is 13, aborts when one is 99, and loops forever when one is 666. Otherwise it
// answers with a bounding-box test (right for disjoint boxes, often wrong otherwise).
//
// Built in several flavours (compile definitions) to test the loader's refusals, and a
// well-behaved one for the bench's tests: BROKEN_WELL_BEHAVED never misbehaves. BROKEN_FLIP_AT=V flips the
// answer on every pair with a coordinate equal to V: a deliberately changed answer, for the gate.
#include "tritri/plugin.h"

#include <cstdlib>

namespace {

bool has(const double* pair, double value) {
  for (int k = 0; k < 18; ++k)
    if (pair[k] == value) return true;
  return false;
}

bool boxes_overlap(const double* p) {
  for (int axis = 0; axis < 3; ++axis) {
    double lo1 = p[axis], hi1 = p[axis], lo2 = p[9 + axis], hi2 = p[9 + axis];
    for (int v = 1; v < 3; ++v) {
      const double a = p[3 * v + axis], b = p[9 + 3 * v + axis];
      lo1 = a < lo1 ? a : lo1;
      hi1 = a > hi1 ? a : hi1;
      lo2 = b < lo2 ? b : lo2;
      hi2 = b > hi2 ? b : hi2;
    }
    if (hi1 < lo2 || hi2 < lo1) return false;
  }
  return true;
}

volatile int* volatile nowhere = nullptr;

void misbehave(const double* pair) {
  if (has(pair, 13)) *nowhere = 1;
  if (has(pair, 99)) std::abort();
  if (has(pair, 666))
    for (volatile bool forever = true; forever;) {
    }
}

[[maybe_unused]] void overlap(const double* pairs, size_t n, unsigned char* out) {
  for (size_t i = 0; i < n; ++i) {
#ifndef BROKEN_WELL_BEHAVED
    misbehave(pairs + 18 * i);
#endif
    bool answer = boxes_overlap(pairs + 18 * i);
#ifdef BROKEN_FLIP_AT
    if (has(pairs + 18 * i, BROKEN_FLIP_AT)) answer = !answer;
#endif
    out[i] = answer ? TRITRI_YES : TRITRI_NO;
  }
}

const tritri_plugin kPlugin = {
#ifdef BROKEN_BAD_ABI
    TRITRI_PLUGIN_ABI + 41,
#else
    TRITRI_PLUGIN_ABI,
#endif
    BROKEN_NAME,
    "none: a test fixture",
    "crashes on 13, aborts on 99, hangs on 666; a bounding-box test otherwise",
    1, 0.0, nullptr, 0, 0,
#ifdef BROKEN_NO_LEVELS
    nullptr,
#else
    overlap,
#endif
    nullptr, nullptr};

}  // namespace

#ifndef BROKEN_NO_ENTRY
extern "C" const tritri_plugin* tritri_plugin_entry(void) { return &kPlugin; }
#endif
