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
//
// An algorithm in tritri's registry (a built-in one, or one added with add_external_algorithm)
// is tested through its batch entry points, at every level it answers: overlap; relation
// (judged by the dimension alone when it states only that); segment (by the overlap it implies
// and, in general position, by its endpoints). The tests are those it promises:
//
//   TRITRI_ALGORITHM_CONFORMANCE(Guigue03, "guigue03", exact)
//
//   none               its counting instantiation (tritri/counting.hpp), if registered, answers
//                      exactly as double: a published defect, wrong even in general position,
//                      promises no more;
//   almost_everywhere  and random pairs in general position, in both argument orders, are
//                      answered as the oracle does (clear of its tolerance, if it declares one;
//                      segment endpoints to 1e-9, if it declares none);
//   general_position   and so are the built-in cases of the family "general", in each of their
//                      72 orders, also by its float instantiation, if registered (a special
//                      position random pairs never take, such as a plane through a coordinate
//                      axis, is what separates it from almost_everywhere);
//   exact              and every built-in case in each of its 72 orders, and random
//                      small-integer pairs in both orders, singular ones included: where the
//                      arithmetic is exact, so is the algorithm.
// Its disagreements beyond what it promises are its baseline (`tritri check --baseline`).
#pragma once

#include "cases/generator/pairs.hpp"
#include "tritri/algorithm.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace tritri::testing {

// ---- the pairs the suites draw (tritri's own generator: the same pairs on every toolchain) ----
// random_pairs, random_grid_pairs, counting_pairs: cases/generator/pairs.hpp says what each is.

using pairs::counting_pairs;
using pairs::random_grid_pairs;
using pairs::random_pairs;

// ---- a function: the overlap suite ----

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
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(OverlapConformance);

// ---- a registered algorithm: the suite at every level it answers ----

// Strongest first: each promise includes those after it.
enum class Promise : std::uint8_t { exact, general_position, almost_everywhere, none };

// The registered algorithm of that name; a test failure (and nullptr) if there is none or it is
// not answered through batch entry points.
const Algorithm* registered(const std::string& name);

void expect_builtin_cases(const Algorithm& algorithm, Promise promise, Scalar scalar = Scalar::double_);
void expect_random_general_position(const Algorithm& algorithm);
void expect_order_independence(const Algorithm& algorithm, Promise promise);
void expect_small_integer_pairs(const Algorithm& algorithm);
void expect_counted_answers_as_double(const Algorithm& algorithm);

// One typed suite per promise: TRITRI_ALGORITHM_CONFORMANCE instantiates those the promise
// includes, so that a test not promised is not there at all rather than skipped.
template <class Implementation>
class AlgorithmConformance : public ::testing::Test {
 protected:
  // Runs check(algorithm) when the algorithm is instantiated on `scalar`, and skips the test
  // otherwise (it fails when no such algorithm is registered).
  static void on(Scalar scalar, void (*check)(const Algorithm&)) {
    const Algorithm* a = registered(Implementation::name());
    if (!a) return;
    if (!a->has_scalar(scalar)) GTEST_SKIP() << a->name << " has no " << to_string(scalar) << " instantiation";
    check(*a);
  }
};
template <class Implementation>
class ExactConformance : public AlgorithmConformance<Implementation> {};
template <class Implementation>
class GeneralPositionConformance : public AlgorithmConformance<Implementation> {};
template <class Implementation>
class AlmostEverywhereConformance : public AlgorithmConformance<Implementation> {};
template <class Implementation>
class InstantiationConformance : public AlgorithmConformance<Implementation> {};

TYPED_TEST_SUITE_P(ExactConformance);
TYPED_TEST_P(ExactConformance, SmallIntegerPairsAreAnsweredAsTheOracleDoes) {
  TestFixture::on(Scalar::double_, expect_small_integer_pairs);
}
REGISTER_TYPED_TEST_SUITE_P(ExactConformance, SmallIntegerPairsAreAnsweredAsTheOracleDoes);

TYPED_TEST_SUITE_P(GeneralPositionConformance);
TYPED_TEST_P(GeneralPositionConformance, BuiltinCasesAreAnsweredAsTheOracleDoes) {
  TestFixture::on(Scalar::double_, [](const Algorithm& a) { expect_builtin_cases(a, TypeParam::promise); });
}
TYPED_TEST_P(GeneralPositionConformance, AnswersDoNotDependOnArgumentOrVertexOrder) {
  TestFixture::on(Scalar::double_, [](const Algorithm& a) { expect_order_independence(a, TypeParam::promise); });
}
TYPED_TEST_P(GeneralPositionConformance, FloatInstantiationAnswersTheGeneralBuiltinCases) {
  TestFixture::on(Scalar::float_, [](const Algorithm& a) {
    expect_builtin_cases(a, Promise::general_position, Scalar::float_);
  });
}
REGISTER_TYPED_TEST_SUITE_P(GeneralPositionConformance, BuiltinCasesAreAnsweredAsTheOracleDoes,
                            AnswersDoNotDependOnArgumentOrVertexOrder, FloatInstantiationAnswersTheGeneralBuiltinCases);

TYPED_TEST_SUITE_P(AlmostEverywhereConformance);
TYPED_TEST_P(AlmostEverywhereConformance, RandomPairsInGeneralPositionAreAnsweredAsTheOracleDoes) {
  TestFixture::on(Scalar::double_, expect_random_general_position);
}
REGISTER_TYPED_TEST_SUITE_P(AlmostEverywhereConformance, RandomPairsInGeneralPositionAreAnsweredAsTheOracleDoes);

TYPED_TEST_SUITE_P(InstantiationConformance);
TYPED_TEST_P(InstantiationConformance, CountedInstantiationAnswersExactlyAsDouble) {
  TestFixture::on(Scalar::counted, expect_counted_answers_as_double);
}
REGISTER_TYPED_TEST_SUITE_P(InstantiationConformance, CountedInstantiationAnswersExactlyAsDouble);

GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(ExactConformance);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(GeneralPositionConformance);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(AlmostEverywhereConformance);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(InstantiationConformance);

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

// `promise_word`: exact, general_position, almost_everywhere or none (see the top of this file).
#define TRITRI_ALGORITHM_CONFORMANCE(Name, algorithm_name, promise_word)                         \
  namespace tritri_conformance {                                                                 \
  struct Name {                                                                                  \
    static std::string name() { return algorithm_name; }                                         \
    static constexpr ::tritri::testing::Promise promise = ::tritri::testing::Promise::promise_word; \
  };                                                                                             \
  }                                                                                              \
  namespace tritri::testing {                                                                    \
  TRITRI_CONFORMANCE_SUITES_##promise_word(Name)                                                 \
  }

// The suites each promise includes (an implementation detail of the macro above).
#define TRITRI_CONFORMANCE_SUITES_none(Name) \
  INSTANTIATE_TYPED_TEST_SUITE_P(Name, InstantiationConformance, ::tritri_conformance::Name);
#define TRITRI_CONFORMANCE_SUITES_almost_everywhere(Name) \
  TRITRI_CONFORMANCE_SUITES_none(Name)                    \
  INSTANTIATE_TYPED_TEST_SUITE_P(Name, AlmostEverywhereConformance, ::tritri_conformance::Name);
#define TRITRI_CONFORMANCE_SUITES_general_position(Name) \
  TRITRI_CONFORMANCE_SUITES_almost_everywhere(Name)      \
  INSTANTIATE_TYPED_TEST_SUITE_P(Name, GeneralPositionConformance, ::tritri_conformance::Name);
#define TRITRI_CONFORMANCE_SUITES_exact(Name)        \
  TRITRI_CONFORMANCE_SUITES_general_position(Name)   \
  INSTANTIATE_TYPED_TEST_SUITE_P(Name, ExactConformance, ::tritri_conformance::Name);
