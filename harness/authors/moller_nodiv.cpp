/* Plug-in "orig-moller97-nodiv": Möller's NoDivTriTriIsect from opttritri.c (the file the port
 * algorithms/moller97, variant moller97-nodiv, follows). opttritri.c writes FABS as a functional
 * cast, float(fabs(x)), which is C++: this wrapper is C++ for that reason only. */
#include "wrapper.h"

#include "opttritri.c"

static void overlap(const double* pairs, size_t n, unsigned char* out) {
  for (size_t i = 0; i < n; ++i)
    out[i] = NoDivTriTriIsect(TRITRI_VERTEX(pairs, i, 0), TRITRI_VERTEX(pairs, i, 1), TRITRI_VERTEX(pairs, i, 2),
                              TRITRI_VERTEX(pairs, i, 3), TRITRI_VERTEX(pairs, i, 4), TRITRI_VERTEX(pairs, i, 5))
                 ? TRITRI_YES
                 : TRITRI_NO;
}

static const tritri_plugin kPlugin = {
    TRITRI_PLUGIN_ABI, "orig-moller97-nodiv", "jgt-code Volume_02/Number_2/Moller1997b/opttritri.c",
    "the authors' code: NoDivTriTriIsect, float changed to double", 1, 1e-6,
    "|N·V + d|, unnormalised plane distance, snapped to 0 below it", 0, 0, overlap, nullptr, nullptr};

extern "C" TRITRI_AUTHORS_EXPORT const tritri_plugin* tritri_plugin_entry(void) { return &kPlugin; }
