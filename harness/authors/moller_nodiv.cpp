/* Plug-in "orig-moller97-nodiv": Möller's NoDivTriTriIsect from opttritri.c (the file the port
 * algorithms/moller97, variant moller97-nodiv, follows). opttritri.c writes FABS as a functional
 * cast, float(fabs(x)), which is C++: this wrapper is C++ for that reason only. */
#include "wrapper.h"

#include "opttritri.c"

TRITRI_AUTHORS_OVERLAP(NoDivTriTriIsect)

TRITRI_AUTHORS_PLUGIN("orig-moller97-nodiv", "jgt-code Volume_02/Number_2/Moller1997b/opttritri.c",
                      "the authors' code: NoDivTriTriIsect" TRITRI_AUTHORS_AS_BUILT, 1e-6,
                      "|N·V + d|, unnormalised plane distance, snapped to 0 below it", nullptr)
