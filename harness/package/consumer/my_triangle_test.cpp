// Testing your own triangle test with tritri's GoogleTest suites: adapt your function to take a
// tritri::TrianglePair and instantiate the overlap suite on it, or register it as an algorithm
// and instantiate the algorithm suite on its name (every level it answers, through its batch
// entry points).
#include <tritri/plugin.h>
#include <tritri/testing.hpp>

#include <utility>

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

// The same test as a registered algorithm: a batch entry point at the overlap level.
void separating_axis_batch(const tritri::TrianglePair* pairs, std::size_t n, tritri::Overlap* out) {
  static_assert(sizeof(tritri::Overlap) == 1 && sizeof(tritri::TrianglePair) == 18 * sizeof(double));
  tritri_plugin_entry()->overlap(reinterpret_cast<const double*>(pairs), n, reinterpret_cast<unsigned char*>(out));
}

const tritri::Algorithm& separating_axes = [] {
  tritri::Algorithm a;
  a.name = "separating-axes";
  a.set_batch<tritri::Level::overlap>(tritri::Scalar::double_, separating_axis_batch);
  return tritri::add_external_algorithm(std::move(a));
}();

TRITRI_ALGORITHM_CONFORMANCE(SeparatingAxesRegistered, "separating-axes", general_position)
