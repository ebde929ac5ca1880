#include "harness/check/check.hpp"

#include "harness/check/judge.hpp"

#include "harness/run/runner.hpp"
#include "cases/util/stats.hpp"

#include <algorithm>
#include <ostream>
#include <optional>
#include <cstdio>
#include <exception>
#include <limits>
#include <stdexcept>
#include <unistd.h>

namespace tritri {
namespace {

double point_segment_distance(const Vec3<double>& p, const Vec3<double>& a, const Vec3<double>& b) {
  const Vec3<double> ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + ab * t)).norm();
}

Dimension dimension_of(SegmentKind k) {
  switch (k) {
    case SegmentKind::empty: return Dimension::none;
    case SegmentKind::point: return Dimension::point;
    case SegmentKind::segment: return Dimension::segment;
    case SegmentKind::area: return Dimension::area;
    default: return Dimension::unknown;
  }
}

void score_segment(const SegmentAnswer& s, const TrianglePair& pair, const OracleRecord& truth,
                   SegmentTally& tally) {
  if (s.kind == SegmentKind::unsupported) return;
  ++tally.answered;
  if (s.kind == SegmentKind::coplanar) {
    ++tally.not_computed;
    return;
  }
  if (dimension_of(s.kind) != truth.dimension) ++tally.kind_mismatches;
  const bool answered_geometry = s.kind == SegmentKind::point || s.kind == SegmentKind::segment;
  const bool exact_geometry = truth.point_count == 1 || truth.point_count == 2;
  if (!answered_geometry || !exact_geometry) return;
  const Vec3<double>& q = s.kind == SegmentKind::point ? s.p : s.q;
  const Vec3<double>& b = truth.points[truth.point_count == 2 ? 1 : 0];
  const double scale = pair_size(pair);
  tally.errors.add(hausdorff_distance(s.p, q, truth.points[0], b) / (scale > 0 ? scale : 1.0));
}

}  // namespace

double SegmentTally::median_error() const { return errors.median(); }

double SegmentTally::max_error() const { return errors.max(); }

// Between two convex sets the distance to the other is convex along a segment, so the
// Hausdorff distance between segments is attained at an endpoint.
double hausdorff_distance(const Vec3<double>& a0, const Vec3<double>& a1, const Vec3<double>& b0,
                          const Vec3<double>& b1) {
  return std::max({point_segment_distance(a0, b0, b1), point_segment_distance(a1, b0, b1),
                   point_segment_distance(b0, a0, a1), point_segment_distance(b1, a0, a1)});
}

double pair_size(const TrianglePair& pair) {
  Vec3<double> lo = pair.t1[0], hi = pair.t1[0];
  for (const Triangle* t : {&pair.t1, &pair.t2})
    for (int i = 0; i < 3; ++i) {
      lo = lo.cwiseMin((*t)[i]);
      hi = hi.cwiseMax((*t)[i]);
    }
  return (hi - lo).norm();
}

Overlap overlap_of(const Algorithm& algorithm, const Answers& a) {
  if (algorithm.answers(Level::overlap)) return a.overlap;
  if (algorithm.answers(Level::relation)) return implied_overlap(a.relation);
  if (algorithm.answers(Level::segment)) return implied_overlap(a.segment);
  return Overlap::unsupported;
}

std::vector<Answers> answer_cases(const Algorithm& algorithm, const std::vector<Case>& cases,
                                  const IsolationOptions& isolation) {
  std::vector<Answers> answers(cases.size());
  // Only the pairs the algorithm accepts are handed to it, in contiguous batches.
  std::vector<std::size_t> index;
  std::vector<TrianglePair> pairs;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (!algorithm.accepts_degenerate && has_degenerate_triangle(cases[i].pair)) {
      answers[i].declined = true;
      continue;
    }
    index.push_back(i);
    pairs.push_back(cases[i].pair);
  }
  std::vector<std::string> names;
  for (std::size_t i : index) names.push_back(cases[i].name);
  const RunAnswers got = run_algorithm(algorithm, names, pairs, LevelSet::all(), isolation);
  for (const Fault& f : got.faults) {
    answers[index[f.index]].fate = f.fate;
    answers[index[f.index]].fault = f.detail;
  }
  for (std::size_t k = got.stopped_at; k < index.size(); ++k) {
    answers[index[k]].fate = Fate::not_run;
    answers[index[k]].fault = "not run: the run stopped at the fault limit (--max-faults)";
  }
  for (std::size_t k = 0; k < index.size(); ++k) {
    Answers& a = answers[index[k]];
    if (a.fate != Fate::ok) continue;
    if (!got.overlap.empty()) a.overlap = got.overlap[k];
    if (!got.relation.empty()) a.relation = got.relation[k];
    if (!got.segment.empty()) a.segment = got.segment[k];
  }
  return answers;
}

namespace {

// One case's outcome, as the tally of that case alone; its disagreements go to `failures`.
Tally score_case(const Algorithm& algorithm, std::size_t i, const Case& c, const OracleRecord& truth,
                 const Answers& a, std::vector<Failure>& failures) {
  Tally tally;
  ++tally.cases;
  if (a.declined) {
    ++tally.unsupported;
    return tally;
  }
  auto fail = [&](Level level, std::string answer, std::string expected) {
    failures.push_back({algorithm.name, i, level, std::move(answer), std::move(expected), "", nullptr, {}});
  };
  if (a.fate == Fate::not_run) {
    ++tally.not_run;
    return tally;
  }
  if (a.fate != Fate::ok) {
    ++(a.fate == Fate::crash ? tally.crashes : tally.timeouts);
    failures.push_back(
        {algorithm.name, i, Level::overlap, to_string(a.fate), overlap_word(truth.overlap), a.fault, nullptr, {}});
    return tally;
  }

  // Overlap: from the overlap level, else what the relation decides, else the segment's.
  const Truth judged = truth_of(truth);
  const Overlap overlap = overlap_of(algorithm, a);
  bool unsupported = false;
  switch (judge_overlap(overlap, judged)) {
    case Verdict::unsupported: unsupported = true; break;
    case Verdict::wrong:
      ++(overlap == Overlap::yes ? tally.false_positives : tally.false_negatives);
      fail(Level::overlap, overlap_word(overlap == Overlap::yes), overlap_word(truth.overlap));
      break;
    case Verdict::right: break;
  }

  if (algorithm.answers(Level::relation)) {
    const RelationVerdict v = judge_relation(a.relation, judged);
    if (v.verdict == Verdict::unsupported) {
      unsupported = true;
    } else {
      ++tally.confusion[{v.said, v.expected}];
      if (v.verdict == Verdict::wrong) {
        ++tally.misclassified;
        fail(Level::relation, relation_word(a.relation), v.expected);
      }
    }
  }
  if (algorithm.answers(Level::segment)) score_segment(a.segment, c.pair, truth, tally.segment);
  if (unsupported) {
    ++tally.unsupported;
    fail(Level::overlap, "unsupported", overlap_word(truth.overlap));
  }
  return tally;
}

void note_group(CheckResult& result, const std::string& group) {
  if (std::find(result.groups.begin(), result.groups.end(), group) == result.groups.end())
    result.groups.push_back(group);
}

}  // namespace

void add_tally(SegmentTally& into, const SegmentTally& t) {
  into.answered += t.answered;
  into.kind_mismatches += t.kind_mismatches;
  into.not_computed += t.not_computed;
  into.errors.add(t.errors);
}

void add_tally(Tally& into, const Tally& t) {
  into.cases += t.cases;
  into.false_positives += t.false_positives;
  into.false_negatives += t.false_negatives;
  into.misclassified += t.misclassified;
  into.unsupported += t.unsupported;
  into.crashes += t.crashes;
  into.timeouts += t.timeouts;
  into.not_run += t.not_run;
  for (const auto& [cell, count] : t.confusion) into.confusion[cell] += count;
  add_tally(into.segment, t.segment);
}

std::optional<StoppedRun> stopped_run(const Algorithm& algorithm, const std::vector<Case>& cases,
                                      const std::vector<Answers>& answers) {
  StoppedRun run{algorithm.name, 0, 0, answers.size(), ""};
  for (std::size_t i = 0; i < answers.size(); ++i) {
    if (answers[i].fate == Fate::not_run) ++run.not_run;
    else if (answers[i].fate != Fate::ok && run.faults++ < 3)
      run.first += " " + cases[i].name + " (" + answers[i].fault + ")";
  }
  if (!run.not_run) return std::nullopt;
  return run;
}

void print_stopped(std::ostream& out, const StoppedRun& run) {
  out << "tritri: " << run.algorithm << " stopped after " << run.faults << " crashes or timeouts (--max-faults): "
      << run.not_run << " of " << run.cases << " cases not run; the first:" << run.first << '\n';
}

void score(const Algorithm& algorithm, const std::vector<Case>& cases,
           const std::vector<OracleRecord>& oracle, const std::vector<Answers>& answers,
           CheckResult& result, std::size_t first_index) {
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::size_t before = result.failures.size();
    const Tally one = score_case(algorithm, first_index + i, cases[i], oracle[i], answers[i], result.failures);
    if (result.failures.size() > before) {
      const auto subject = std::make_shared<const Case>(cases[i]);
      for (std::size_t k = before; k < result.failures.size(); ++k) {
        result.failures[k].subject = subject;
        result.failures[k].oracle_relation = oracle[i].relation;
      }
    }
    for (const std::string& group : groups_of(cases[i], result.groupings)) {
      const auto [tally, first] = result.tallies.try_emplace({algorithm.name, group});
      if (first) note_group(result, group);
      add_tally(tally->second, one);
    }
  }
}

CheckResult run_check(const std::vector<const Algorithm*>& algorithms, const std::vector<Case>& cases,
                      const std::vector<OracleRecord>& oracle, const IsolationOptions& isolation,
                      const std::vector<Grouping>& groupings) {
  CheckResult result;
  result.algorithms = algorithms;
  result.groupings = groupings;
  result.case_count = cases.size();
  result.judged.oracle = cases.size();
  for (const auto& c : cases) {
    result.names.add(c.name);
    for (const std::string& group : groups_of(c, groupings)) note_group(result, group);
  }
  result.names.seal();
  for (const Algorithm* algorithm : algorithms) {
    const auto answers = answer_cases(*algorithm, cases, isolation);
    if (auto stopped = stopped_run(*algorithm, cases, answers)) result.stopped.push_back(*stopped);
    score(*algorithm, cases, oracle, answers, result);
  }
  return result;
}

}  // namespace tritri
