// The suite of a registered algorithm (TRITRI_ALGORITHM_CONFORMANCE), through its batch entry
// points.
#include "harness/testing/subject.hpp"

#include "cases/util/random.hpp"

namespace tritri::testing {
namespace {

// The built-in cases the promise covers: all of them when exact, the family "general" else.
std::vector<Case> promised_cases(const Algorithm& algorithm, Promise promise) {
  std::vector<Case> out;
  for (Case& c : builtin_cases()) {
    if (promise != Promise::exact && c.family() != "general") continue;
    if (!algorithm.accepts_degenerate && has_degenerate_triangle(c.pair)) continue;
    out.push_back(std::move(c));
  }
  return out;
}

bool same_segment(const SegmentAnswer& a, const SegmentAnswer& b) {
  return a.kind == b.kind && a.p == b.p && a.q == b.q;
}

// The first level at which answers i of `a` and `b` differ (endpoints compared with ==); empty
// when none does.
std::string first_difference(const LevelAnswers& a, const LevelAnswers& b, std::size_t i) {
  if (!a.overlap.empty() && a.overlap[i] != b.overlap[i])
    return "overlap " + std::string(to_string(b.overlap[i])) + ", double " + std::string(to_string(a.overlap[i]));
  if (!a.relation.empty() &&
      (a.relation[i].relation != b.relation[i].relation || a.relation[i].dimension != b.relation[i].dimension))
    return "relation " + std::string(to_string(b.relation[i].relation)) + ", double " +
           std::string(to_string(a.relation[i].relation));
  if (!a.segment.empty() && !same_segment(a.segment[i], b.segment[i]))
    return "segment " + std::string(to_string(b.segment[i].kind)) + ", double " +
           std::string(to_string(a.segment[i].kind)) + " (or other endpoints)";
  return "";
}

}  // namespace

const Algorithm* registered(const std::string& name) {
  const Algorithm* a = registry().find(name);
  if (!a) {
    ADD_FAILURE() << "no algorithm named " << name << " is registered";
  } else if (!a->timeable()) {
    ADD_FAILURE() << name << " is not answered through batch entry points";
    a = nullptr;
  }
  return a;
}

void expect_builtin_cases(const Algorithm& algorithm, Promise promise, Scalar scalar) {
  expect_cases(subject_of(algorithm, scalar), promised_cases(algorithm, promise));
}

void expect_random_general_position(const Algorithm& algorithm) {
  expect_general_position(subject_of(algorithm, Scalar::double_));
}

void expect_order_independence(const Algorithm& algorithm, Promise promise) {
  expect_same_in_any_order(subject_of(algorithm, Scalar::double_), promised_cases(algorithm, promise));
}

void expect_small_integer_pairs(const Algorithm& algorithm) {
  // Coordinates in [-3, 3]: about one pair in ten is singular (vertices on planes and edges,
  // coplanar contact), and every value is exact in double.
  expect_pairs(subject_of(algorithm, Scalar::double_), random_grid_pairs(stream_seed(1, "small-integers"), 4000, 3),
               200);
}

// Counted's arithmetic is double's, the order of Eigen's sums included: any difference means
// the operation counts describe another computation than the one checked.
void expect_counted_answers_as_double(const Algorithm& algorithm) {
  const std::vector<TrianglePair> pairs = counting_pairs();
  const LevelAnswers in_double = subject_of(algorithm, Scalar::double_).answer(pairs);
  const LevelAnswers counted = subject_of(algorithm, Scalar::counted).answer(pairs);
  int differences = 0;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    if (const std::string d = first_difference(in_double, counted, i); !d.empty() && ++differences <= 10)
      ADD_FAILURE() << algorithm.name << "@counted answers pair " << i << " otherwise: " << d << "\n"
                    << paste_ready(pairs[i]);
  EXPECT_EQ(differences, 0) << "pairs answered otherwise in Counted than in double, of " << pairs.size();
}

}  // namespace tritri::testing
