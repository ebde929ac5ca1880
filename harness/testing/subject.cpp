#include "harness/testing/subject.hpp"

#include "harness/check/judge.hpp"
#include "cases/oracle/oracle.hpp"
#include "cases/util/parallel.hpp"
#include "cases/util/random.hpp"

#include <algorithm>
#include <array>
#include <tuple>

namespace tritri::testing {
namespace {

// Disagreements are counted in full and printed up to this many, each paste-ready.
constexpr int kPrinted = 10;

class Disagreements {
 public:
  explicit Disagreements(std::string what) : what_(std::move(what)) {}
  void add(const std::string& problem, const TrianglePair& pair) {
    if (++count_ <= kPrinted) ADD_FAILURE() << what_ << ": " << problem << "\n" << paste_ready(pair);
  }
  ~Disagreements() { EXPECT_EQ(count_, 0) << what_ << ": disagreements in all (the first " << kPrinted << " above)"; }

 private:
  std::string what_;
  int count_ = 0;
};

std::string word(Overlap o) { return std::string(to_string(o)); }
std::string word(bool overlap) { return word(overlap ? Overlap::yes : Overlap::no); }

// What is wrong with answer i at each level; empty when every level agrees with the oracle.
std::string disagreement(const LevelAnswers& a, std::size_t i, const Truth& truth) {
  std::string out;
  if (!a.overlap.empty() && judge_overlap(a.overlap[i], truth) != Verdict::right)
    out += "overlap " + word(a.overlap[i]) + ", oracle " + word(truth.overlap) + "; ";
  if (!a.relation.empty()) {
    const RelationVerdict v = judge_relation(a.relation[i], truth);
    if (v.verdict != Verdict::right) out += "relation " + v.said + ", oracle " + v.expected + "; ";
  }
  if (!a.segment.empty() && judge_overlap(implied_overlap(a.segment[i]), truth) != Verdict::right)
    out += "segment " + std::string(to_string(a.segment[i].kind)) + ", oracle overlap " + word(truth.overlap) + "; ";
  return out;
}

// Answers i and j say the same: overlap, relation and the overlap a segment implies (its
// endpoints depend on the order of the vertices by construction).
bool same_answers(const LevelAnswers& a, std::size_t i, std::size_t j) {
  if (!a.overlap.empty() && a.overlap[i] != a.overlap[j]) return false;
  if (!a.relation.empty() &&
      (a.relation[i].relation != a.relation[j].relation || a.relation[i].dimension != a.relation[j].dimension))
    return false;
  return a.segment.empty() || implied_overlap(a.segment[i]) == implied_overlap(a.segment[j]);
}

// The error of a segment against the oracle's exact one: the endpoints' distances, in the
// better of the two orders.
double endpoint_error(const SegmentAnswer& s, const OracleRecord& truth) {
  const Vec3<double>& a = truth.points[0];
  const Vec3<double>& b = truth.points[1];
  return std::min((s.p - a).norm() + (s.q - b).norm(), (s.p - b).norm() + (s.q - a).norm());
}

bool general_position(const OracleRecord& r) {
  return r.relation == Relation::disjoint || r.relation == Relation::cross;
}

}  // namespace

std::string paste_ready(const TrianglePair& pair) {
  Case c;
  c.name = "failing";
  c.pair = pair;
  return format_case(c, NumberStyle::hex);
}

Subject subject_of(OverlapFunction overlap, std::string name) {
  Subject s;
  s.name = std::move(name);
  s.answer = [overlap](const std::vector<TrianglePair>& pairs) {
    LevelAnswers out;
    for (const TrianglePair& p : pairs) out.overlap.push_back(overlap(p) ? Overlap::yes : Overlap::no);
    return out;
  };
  return s;
}

Subject subject_of(const Algorithm& algorithm, Scalar scalar) {
  Subject s;
  s.name = algorithm.name;
  if (scalar != Scalar::double_) s.name.append("@").append(to_string(scalar));  // as on_scalar names it
  s.tolerant = !algorithm.tolerance.none();
  s.answer = [&algorithm, scalar](const std::vector<TrianglePair>& pairs) {
    LevelAnswers out;
    auto answers = std::tie(out.overlap, out.relation, out.segment);
    for_each_level([&](auto level) {
      constexpr Level L = decltype(level)::value;
      const auto batch = algorithm.batch<L>(scalar);
      if (!batch) return;
      auto& v = std::get<static_cast<std::size_t>(L)>(answers);
      v.resize(pairs.size());
      batch(pairs.data(), pairs.size(), v.data());
    });
    return out;
  };
  return s;
}

std::vector<OracleRecord> oracle_records(const std::vector<TrianglePair>& pairs) {
  std::vector<OracleRecord> records(pairs.size());
  parallel_chunks(pairs.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) records[i] = oracle_label(pairs[i]);
  });
  return records;
}

void expect_cases(const Subject& subject, const std::vector<Case>& cases) {
  std::vector<TrianglePair> pairs;
  for (const Case& c : cases) pairs.push_back(c.pair);
  const LevelAnswers answers = subject.answer(pairs);
  const std::vector<OracleRecord> truth = oracle_records(pairs);
  Disagreements wrong(subject.name + " on the built-in cases");
  for (std::size_t i = 0; i < cases.size(); ++i)
    if (const std::string problem = disagreement(answers, i, truth_of(truth[i])); !problem.empty())
      wrong.add("case " + cases[i].name + " (" + std::string(cases[i].label("expect").value_or("")) + "): " + problem,
                cases[i].pair);
}

void expect_general_position(const Subject& subject) {
  // Non-meeting pairs nearer than this are left out for an algorithm that declares a tolerance:
  // the tolerances of the ports, in the coordinates' units, are 1e-7 at most.
  constexpr double kClearOfTolerance = 1e-5;
  static const std::vector<TrianglePair> pairs = random_pairs(stream_seed(1, "general-position"), 3000);
  static const std::vector<OracleRecord> truth = oracle_records(pairs);
  const std::size_t n = pairs.size();
  std::vector<TrianglePair> both = pairs;
  for (const TrianglePair& p : pairs) both.push_back(swapped(p));
  const LevelAnswers answers = subject.answer(both);
  Disagreements wrong(subject.name + " in general position");
  std::size_t checked = 0, meeting = 0, crossing = 0;
  for (std::size_t i = 0; i < 2 * n; ++i) {
    const OracleRecord& t = truth[i % n];
    if (!general_position(t)) continue;
    if (subject.tolerant && !t.overlap && t.separation < kClearOfTolerance) continue;
    const std::string which = "random pair " + std::to_string(i % n) + (i < n ? "" : " (swapped)") + ": ";
    if (i < n) ++checked, meeting += t.overlap;
    if (const std::string problem = disagreement(answers, i, truth_of(t)); !problem.empty())
      wrong.add(which + problem, both[i]);
    // A tolerance widens the segment as it widens contact (by how much is the algorithm's to
    // say): endpoints are held to the oracle's without one.
    if (answers.segment.empty() || subject.tolerant || t.relation != Relation::cross) continue;
    crossing += i < n;
    const SegmentAnswer& s = answers.segment[i];
    if (s.kind != SegmentKind::segment || endpoint_error(s, t) >= 1e-9)
      wrong.add(which + "segment " + std::string(to_string(s.kind)) + " off by " + format_double(endpoint_error(s, t)) +
                    ", more than 1e-9",
                both[i]);
  }
  // The sample is what it claims: nearly all of it in general position, with both outcomes.
  EXPECT_GT(checked, n * 29 / 30);
  EXPECT_GT(meeting, checked / 10);
  EXPECT_GT(checked - meeting, checked / 10);
  if (!answers.segment.empty() && !subject.tolerant) {
    EXPECT_GT(crossing, checked / 10);
  }
}

void expect_same_in_any_order(const Subject& subject, const std::vector<Case>& cases) {
  Disagreements changed(subject.name + " in another order of the arguments or vertices");
  for (const Case& c : cases) {
    const std::vector<TrianglePair> orders = every_order(c.pair);
    const LevelAnswers answers = subject.answer(orders);
    for (std::size_t i = 1; i < orders.size(); ++i)
      if (!same_answers(answers, 0, i)) {
        changed.add("case " + c.name + " is answered otherwise in order " + std::to_string(i) + " of 72", orders[i]);
        break;
      }
  }
}

void expect_pairs(const Subject& subject, const std::vector<TrianglePair>& pairs, std::size_t singular_at_least) {
  const std::vector<OracleRecord> truth = oracle_records(pairs);
  std::vector<TrianglePair> both = pairs;
  for (const TrianglePair& p : pairs) both.push_back(swapped(p));
  const LevelAnswers answers = subject.answer(both);
  Disagreements wrong(subject.name + " on small-integer pairs");
  std::size_t singular = 0;
  for (std::size_t i = 0; i < both.size(); ++i) {
    const OracleRecord& t = truth[i % pairs.size()];
    if (i < pairs.size()) singular += !general_position(t);
    if (const std::string problem = disagreement(answers, i, truth_of(t)); !problem.empty())
      wrong.add("pair " + std::to_string(i % pairs.size()) + (i < pairs.size() ? ": " : " (swapped): ") + problem,
                both[i]);
  }
  EXPECT_GE(singular, singular_at_least) << "the sample hardly exercises singular configurations";
}

}  // namespace tritri::testing
