// Testing your own triangle test with tritri's GoogleTest suite: adapt your function to take a
// tritri::TrianglePair, and instantiate the suite on it.
#include <tritri/plugin.h>
#include <tritri/testing.hpp>

// The function under test. Here it is the example plug-in's separating-axis test (mine.c),
// reached through its C entry point; yours would be called directly.
bool separating_axis_overlap(const tritri::TrianglePair& pair) {
  static_assert(sizeof(pair) == 18 * sizeof(double));
  unsigned char answer = 0;
  tritri_plugin_entry()->overlap(reinterpret_cast<const double*>(&pair), 1, &answer);
  return answer == TRITRI_YES;
}

TRITRI_OVERLAP_CONFORMANCE_WITH_BASELINE(SeparatingAxes, separating_axis_overlap,
                                         "separating-axes-expected-failures.tsv")
