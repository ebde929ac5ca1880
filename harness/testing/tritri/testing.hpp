// Test your own triangle–triangle overlap test with GoogleTest, in one line:
//
//   #include <tritri/testing.hpp>
//   bool my_overlap(const tritri::TrianglePair& pair);   // your test, adapted to tritri's pair
//   TRITRI_OVERLAP_CONFORMANCE(MyOverlap, my_overlap);
//
// and link tritri::testing (find_package(tritri)). The suite checks, against tritri's exact
// oracle (CGAL):
//   - the built-in cases (every relation, small integers: exact in any arithmetic);
//   - random pairs in general position (touching has probability zero there);
//   - that no answer changes with the order of the arguments or of the vertices (72 variants);
//   - the quick singular-configuration corpus: its disagreements with the oracle are printed
//     and, with TRITRI_OVERLAP_CONFORMANCE_WITH_BASELINE, compared with a recorded file, so that
//     a new disagreement fails and a fixed one is reported. Run once with the environment
//     variable TRITRI_WRITE_BASELINE=1 to record the file.
#pragma once

#include "tritri/geometry.hpp"

#include <gtest/gtest.h>

#include <string>

namespace tritri::testing {

using OverlapFunction = bool (*)(const TrianglePair&);

void expect_builtin_cases(OverlapFunction overlap);
void expect_random_general_position(OverlapFunction overlap);
void expect_order_independence(OverlapFunction overlap);
// Empty baseline path: only report. Otherwise compare with (or, with TRITRI_WRITE_BASELINE=1,
// write) the recorded disagreements.
void check_singular_corpus(OverlapFunction overlap, const std::string& name, const std::string& baseline_path);

template <class Implementation>
class OverlapConformance : public ::testing::Test {};

TYPED_TEST_SUITE_P(OverlapConformance);

TYPED_TEST_P(OverlapConformance, BuiltinCasesAreAnsweredAsTheOracleDoes) {
  expect_builtin_cases(&TypeParam::overlap);
}
TYPED_TEST_P(OverlapConformance, RandomPairsInGeneralPositionAreAnsweredAsTheOracleDoes) {
  expect_random_general_position(&TypeParam::overlap);
}
TYPED_TEST_P(OverlapConformance, AnswersDoNotDependOnArgumentOrVertexOrder) {
  expect_order_independence(&TypeParam::overlap);
}
TYPED_TEST_P(OverlapConformance, SingularCorpusDisagreementsMatchTheBaseline) {
  check_singular_corpus(&TypeParam::overlap, TypeParam::name(), TypeParam::baseline());
}

REGISTER_TYPED_TEST_SUITE_P(OverlapConformance, BuiltinCasesAreAnsweredAsTheOracleDoes,
                            RandomPairsInGeneralPositionAreAnsweredAsTheOracleDoes,
                            AnswersDoNotDependOnArgumentOrVertexOrder,
                            SingularCorpusDisagreementsMatchTheBaseline);

}  // namespace tritri::testing

// Use at global scope. GoogleTest pastes the suite's name into identifiers, so the instantiation
// happens inside tritri::testing, and the adapter type gets a namespace of its own.
#define TRITRI_OVERLAP_CONFORMANCE_WITH_BASELINE(Name, function, baseline_path)          \
  namespace tritri_conformance {                                                         \
  struct Name {                                                                          \
    static bool overlap(const ::tritri::TrianglePair& pair) { return function(pair); }   \
    static std::string name() { return #Name; }                                          \
    static std::string baseline() { return baseline_path; }                              \
  };                                                                                     \
  }                                                                                      \
  namespace tritri::testing {                                                            \
  INSTANTIATE_TYPED_TEST_SUITE_P(Name, OverlapConformance, ::tritri_conformance::Name);  \
  }

#define TRITRI_OVERLAP_CONFORMANCE(Name, function) \
  TRITRI_OVERLAP_CONFORMANCE_WITH_BASELINE(Name, function, "")
