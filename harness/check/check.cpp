#include "harness/check/check.hpp"

#include "harness/run/process_plugin.hpp"
#include "cases/util/stats.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <exception>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <unistd.h>

namespace tritri {
namespace {

std::string overlap_word(bool b) { return b ? "1" : "0"; }

std::string relation_word(const RelationAnswer& a) {
  if (a.relation == Relation::unknown) return "dim:" + std::string(to_string(a.dimension));
  return std::string(to_string(a.relation));
}

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
  tally.errors.push_back(hausdorff_distance(s.p, q, truth.points[0], b) / (scale > 0 ? scale : 1.0));
}

}  // namespace

double SegmentTally::median_error() const { return median(errors); }

double SegmentTally::max_error() const {
  if (errors.empty()) return std::numeric_limits<double>::quiet_NaN();
  return *std::max_element(errors.begin(), errors.end());
}

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
  auto record_faults = [&](const std::vector<Fault>& faults) {
    for (const Fault& f : faults) {
      answers[index[f.index]].fate = f.fate;
      answers[index[f.index]].fault = f.detail;
    }
  };

  if (algorithm.process) {
    std::vector<std::string> names;
    for (std::size_t i : index) names.push_back(cases[i].name);
    const ProcessAnswers got = run_process_plugin(
        {algorithm.process->command, algorithm.process->timeout_seconds}, names, pairs);
    for (std::size_t k = 0; k < index.size(); ++k) {
      answers[index[k]].overlap = got.overlap[k];
      answers[index[k]].relation = got.relation[k];
    }
    record_faults(got.faults);
    return answers;
  }

  // The answers are written to memory shared with the child that computes them.
  SharedArray<Overlap> overlap(algorithm.overlap ? pairs.size() : 0);
  SharedArray<RelationAnswer> relation(algorithm.relation ? pairs.size() : 0);
  SharedArray<SegmentAnswer> segment(algorithm.segment ? pairs.size() : 0);
  record_faults(run_isolated(pairs.size(), [&](std::size_t begin, std::size_t end) {
    const TrianglePair* batch = pairs.data() + begin;
    if (algorithm.overlap) algorithm.overlap(batch, end - begin, overlap.data() + begin);
    if (algorithm.relation) algorithm.relation(batch, end - begin, relation.data() + begin);
    if (algorithm.segment) algorithm.segment(batch, end - begin, segment.data() + begin);
  }, isolation));
  for (std::size_t k = 0; k < index.size(); ++k) {
    if (answers[index[k]].fate != Fate::ok) continue;
    if (algorithm.overlap) answers[index[k]].overlap = overlap[k];
    if (algorithm.relation) answers[index[k]].relation = relation[k];
    if (algorithm.segment) answers[index[k]].segment = segment[k];
  }
  return answers;
}

void score(const Algorithm& algorithm, const std::vector<Case>& cases,
           const std::vector<OracleRecord>& oracle, const std::vector<Answers>& answers,
           CheckResult& result) {
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string family = cases[i].family();
    if (std::find(result.families.begin(), result.families.end(), family) == result.families.end())
      result.families.push_back(family);
    Tally& tally = result.tallies[{algorithm.name, family}];
    ++tally.cases;
    const Answers& a = answers[i];
    const OracleRecord& truth = oracle[i];
    if (a.declined) {
      ++tally.unsupported;
      continue;
    }
    auto fail = [&](Level level, std::string answer, std::string expected) {
      result.failures.push_back({algorithm.name, i, level, std::move(answer), std::move(expected), ""});
    };
    if (a.fate != Fate::ok) {
      ++(a.fate == Fate::crash ? tally.crashes : tally.timeouts);
      result.failures.push_back({algorithm.name, i, Level::overlap, to_string(a.fate), overlap_word(truth.overlap), a.fault});
      continue;
    }

    // Overlap: from the overlap level, else derived from the relation the algorithm gave, else
    // from its segment answer.
    Overlap overlap = a.overlap;
    if (!algorithm.answers(Level::overlap) && !algorithm.answers(Level::relation) && algorithm.answers(Level::segment)) {
      overlap = a.segment.kind == SegmentKind::unsupported ? Overlap::unsupported
                : a.segment.kind == SegmentKind::empty    ? Overlap::no
                                                          : Overlap::yes;
    }
    if (!algorithm.answers(Level::overlap) && algorithm.answers(Level::relation)) {
      const Dimension d = a.relation.relation == Relation::unknown ? a.relation.dimension
                                                                    : dimension_of(a.relation.relation);
      overlap = a.relation.relation == Relation::unsupported || d == Dimension::unknown
                    ? Overlap::unsupported
                    : (d == Dimension::none ? Overlap::no : Overlap::yes);
    }
    bool unsupported = overlap == Overlap::unsupported;
    if (!unsupported) {
      const bool said = overlap == Overlap::yes;
      if (said && !truth.overlap) ++tally.false_positives;
      if (!said && truth.overlap) ++tally.false_negatives;
      if (said != truth.overlap) fail(Level::overlap, overlap_word(said), overlap_word(truth.overlap));
    }

    if (algorithm.answers(Level::relation)) {
      const RelationAnswer& r = a.relation;
      if (r.relation == Relation::unsupported) {
        unsupported = true;
      } else {
        // Degenerate input has no relation of two proper triangles: only the dimension is scored.
        const bool by_dimension = r.relation == Relation::unknown || truth.degenerate;
        const Dimension said_dim = r.relation == Relation::unknown ? r.dimension : dimension_of(r.relation);
        const bool wrong = by_dimension ? said_dim != truth.dimension : r.relation != truth.relation;
        const std::string said = by_dimension ? "dim:" + std::string(to_string(said_dim)) : relation_word(r);
        const std::string expected = by_dimension ? "dim:" + std::string(to_string(truth.dimension))
                                                  : std::string(to_string(truth.relation));
        ++tally.confusion[{said, expected}];
        if (wrong) {
          ++tally.misclassified;
          fail(Level::relation, relation_word(r), expected);
        }
      }
    }
    if (algorithm.answers(Level::segment)) score_segment(a.segment, cases[i].pair, truth, tally.segment);
    if (unsupported) {
      ++tally.unsupported;
      fail(Level::overlap, "unsupported", overlap_word(truth.overlap));
    }
  }
}

CheckResult run_check(const std::vector<const Algorithm*>& algorithms, const std::vector<Case>& cases,
                      const std::vector<OracleRecord>& oracle, const IsolationOptions& isolation) {
  CheckResult result;
  result.algorithms = algorithms;
  for (const auto& c : cases) {
    const std::string family = c.family();
    if (std::find(result.families.begin(), result.families.end(), family) == result.families.end())
      result.families.push_back(family);
  }
  for (const Algorithm* algorithm : algorithms)
    score(*algorithm, cases, oracle, answer_cases(*algorithm, cases, isolation), result);
  return result;
}

}  // namespace tritri
