#include "harness/hunt/hunt.hpp"

#include "cases/case_stream.hpp"
#include "cases/label.hpp"
#include "harness/check/check.hpp"
#include "harness/check/judge.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace tritri::hunt {

std::string Signature::key() const {
  return "level=" + level + " answer=" + answer + " oracle=" + oracle + " plane=" + plane + " shared=" + shared +
         " scale=" + scale + " transform=" + transform;
}

namespace {

std::string plane_class(const TrianglePair& p, Relation oracle) {
  switch (oracle) {
    case Relation::coplanar_overlap:
    case Relation::coplanar_disjoint:
    case Relation::coplanar_point:
    case Relation::coplanar_segment: return "coplanar";
    case Relation::parallel: return "parallel";
    case Relation::degenerate: return "degenerate";
    default: break;
  }
  const Vec3<double> n1 = (p.t1[1] - p.t1[0]).cross(p.t1[2] - p.t1[0]);
  const Vec3<double> n2 = (p.t2[1] - p.t2[0]).cross(p.t2[2] - p.t2[0]);
  const double sine = n1.cross(n2).norm() / (n1.norm() * n2.norm());
  return sine < 0x1p-20 ? "near_parallel" : "general";
}

std::string shared_class(const TrianglePair& p) {
  int shared = 0;
  for (const auto& v : p.t2.v)
    for (const auto& w : p.t1.v)
      if (v == w) {
        ++shared;
        break;
      }
  return shared == 0 ? "none" : shared == 1 ? "vertex" : "edge";
}

std::string scale_class(const TrianglePair& p) {
  double largest = 0;
  for (int i = 0; i < 18; ++i) largest = std::max(largest, std::fabs(coordinate(p, i)));
  return largest < 0x1p-20 ? "tiny" : largest > 0x1p20 ? "huge" : "unit";
}

}  // namespace

Signature signature_of(const TrianglePair& pair, Relation oracle, Level level, std::string answer, Transform t) {
  return {std::string(to_string(level)), std::move(answer), std::string(to_string(oracle)), plane_class(pair, oracle),
          shared_class(pair), scale_class(pair), std::string(to_string(t))};
}

namespace {

using Clock = std::chrono::steady_clock;

const Algorithm& exact_algorithm() {
  const Algorithm* a = registry().find("exact");
  if (!a || !a->batch<Level::relation>()) throw std::logic_error("hunt: the 'exact' algorithm is not registered");
  return *a;
}

// exact's verdicts, in this process (exact is the judge: its answers are the oracle's).
std::vector<Truth> exact_truths(const std::vector<TrianglePair>& pairs) {
  std::vector<RelationAnswer> answers(pairs.size());
  exact_algorithm().batch<Level::relation>()(pairs.data(), pairs.size(), answers.data());
  std::vector<Truth> truths(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    truths[i].relation = answers[i].relation;
    truths[i].dimension = answers[i].dimension;
    truths[i].overlap = answers[i].dimension != Dimension::none;
    truths[i].degenerate = answers[i].relation == Relation::degenerate;
  }
  return truths;
}

bool same_truth(const Truth& a, const Truth& b) { return a.relation == b.relation && a.dimension == b.dimension; }
bool judgeable(const Truth& t) { return t.relation != Relation::unsupported; }  // exact declines non-finite input

struct Judged {
  bool wrong = false;
  bool fault = false;
  std::string answer;  // the judged word, or crash/timeout
  std::string detail;
};

Judged judged(const Algorithm& algorithm, const Answers& a, const Truth& truth, Level level) {
  if (a.fate == Fate::crash || a.fate == Fate::timeout) return {true, true, std::string(to_string(a.fate)), a.fault};
  if (a.declined || a.fate != Fate::ok || !judgeable(truth)) return {};
  if (level == Level::overlap) {
    const Overlap o = overlap_of(algorithm, a);
    if (judge_overlap(o, truth) == Verdict::wrong) return {true, false, overlap_word(o == Overlap::yes), ""};
    return {};
  }
  RelationVerdict v = judge_relation(a.relation, truth);
  if (v.verdict == Verdict::wrong) return {true, false, v.said, ""};
  return {};
}

std::vector<Case> as_cases(const std::vector<TrianglePair>& pairs) {
  std::vector<Case> cases(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    cases[i].name = "hunt" + std::to_string(i);
    cases[i].pair = pairs[i];
  }
  return cases;
}

// One hunt in progress: the algorithm, its judge, and what has been found.
class Hunter {
 public:
  Hunter(const Algorithm& algorithm, const HuntOptions& options)
      : algorithm_(algorithm), options_(options), self_(algorithm.folder == exact_algorithm().folder) {
    result_.algorithm = algorithm.name;
  }

  HuntResult run();

 private:
  // The judge's truths: exact's, or the oracle's when exact is the algorithm hunted (it cannot
  // judge itself).
  std::vector<Truth> truths(const std::vector<TrianglePair>& pairs) const {
    return self_ ? label_pairs(pairs) : exact_truths(pairs);
  }
  // Batch k starts at pair k·batch of the whole run (search_batch draws exactly `batch`).
  std::size_t start_of(std::size_t k) const { return k * options_.batch; }
  bool budget_left(std::size_t k, double elapsed) const {
    if (options_.end_batch && k >= *options_.end_batch) return false;
    return options_.pairs ? start_of(k) < *options_.pairs : elapsed < options_.seconds;
  }
  void judge_batch(const std::vector<Candidate>& batch, std::size_t start, double elapsed);
  void confirm(const std::vector<TrianglePair>& pairs, std::vector<Truth>& truths, std::vector<Judged>& verdicts,
               const std::vector<Answers>& answers);
  void record(const Candidate& c, const Truth& truth, const Judged& j, const Judged& base, std::size_t start,
              double elapsed);
  void shrink_group(Group& group, const std::function<bool()>& out_of_time);

  const Algorithm& algorithm_;
  const HuntOptions& options_;
  const bool self_;
  HuntResult result_;
  std::map<std::string, std::size_t> group_of_;  // signature key -> index in result_.groups
  std::vector<Truth> group_truth_;               // the oracle's verdict on each group's found pair
};


// Every failure exact reports is judged again on the oracle's verdict: a failure counts only when
// the oracle confirms it, and exact and the oracle disagreeing is recorded (a bug in one of them).
void Hunter::confirm(const std::vector<TrianglePair>& pairs, std::vector<Truth>& truths,
                     std::vector<Judged>& verdicts, const std::vector<Answers>& answers) {
  if (self_) return;  // the truths are the oracle's already
  std::vector<std::size_t> suspects;
  std::vector<TrianglePair> suspect_pairs;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    if (verdicts[i].wrong) {
      suspects.push_back(i);
      suspect_pairs.push_back(pairs[i]);
    }
  if (suspects.empty()) return;
  const std::vector<Truth> oracle = label_pairs(suspect_pairs);
  for (std::size_t k = 0; k < suspects.size(); ++k) {
    const std::size_t i = suspects[k];
    if (!same_truth(oracle[k], truths[i])) {
      result_.exact_oracle_disagreements.push_back(pairs[i]);
      truths[i] = oracle[k];
      if (verdicts[i].fault) continue;
      verdicts[i] = judged(algorithm_, answers[i], truths[i], options_.level);
      if (!verdicts[i].wrong) ++result_.unconfirmed;
    }
  }
}

void Hunter::record(const Candidate& c, const Truth& truth, const Judged& j, const Judged& base, std::size_t start,
                    double elapsed) {
  // A transformed copy whose base was answered right: the transformation broke it.
  const Transform t = c.transform != Transform::none && !base.wrong ? c.transform : Transform::none;
  const Signature signature = signature_of(c.pair, truth.relation, options_.level, j.answer, t);
  auto [it, added] = group_of_.emplace(signature.key(), result_.groups.size());
  if (added) {
    Group g;
    g.signature = signature;
    g.first_seconds = elapsed;
    g.first_pairs = start;
    g.source = std::string(to_string(c.source));
    g.detail = j.detail;
    g.known = options_.known.count(it->first) > 0;
    g.found = g.witness = c.pair;
    result_.groups.push_back(g);
    group_truth_.push_back(truth);
  }
  Group& g = result_.groups[it->second];
  // The cheapest failure of the group is where shrinking starts: a grid pair that fails the same
  // way shrinks further than the first failure a walk found.
  if (!added && pair_cost(c.pair) < pair_cost(g.found)) {
    g.found = g.witness = c.pair;
    group_truth_[it->second] = truth;
  }
  ++g.count;
  ++result_.failures;
  result_.faults += j.fault;
  if (!result_.first_failure_seconds) {
    result_.first_failure_seconds = elapsed;
    result_.first_failure_pairs = start;
  }
}

void Hunter::judge_batch(const std::vector<Candidate>& batch, std::size_t start, double elapsed) {
  std::vector<TrianglePair> pairs;
  for (const Candidate& c : batch) pairs.push_back(c.pair);
  IsolationOptions isolation = options_.isolation;
  if (isolation.max_faults > 0) isolation.max_faults -= result_.faults;
  const std::vector<Answers> answers = answer_cases(algorithm_, as_cases(pairs), isolation);
  std::vector<Truth> truth = truths(pairs);
  std::vector<Judged> verdicts(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    verdicts[i] = judged(algorithm_, answers[i], truth[i], options_.level);
    if (answers[i].fate == Fate::not_run) result_.stopped = true;
  }
  confirm(pairs, truth, verdicts, answers);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (!verdicts[i].wrong) continue;
    if (verdicts[i].fault && !judgeable(truth[i])) truth[i] = label_pairs({pairs[i]})[0];
    record(batch[i], truth[i], verdicts[i], verdicts[batch[i].base], start, elapsed);
  }
}

// Shrinks a group's witness: a step is kept while the algorithm gives the same wrong answer and
// the judge's verdict is unchanged; the witness is then confirmed by the oracle.
void Hunter::shrink_group(Group& group, const std::function<bool()>& out_of_time) {
  const Truth truth = group_truth_[static_cast<std::size_t>(&group - result_.groups.data())];
  IsolationOptions isolation = options_.isolation;
  isolation.max_faults = 4;  // a step that crashes is not the same failure: stop such a batch early
  const StillFails still_fails = [&](const std::vector<TrianglePair>& pairs) {
    const std::vector<Answers> answers = answer_cases(algorithm_, as_cases(pairs), isolation);
    const std::vector<Truth> verdict = truths(pairs);
    std::vector<bool> fails(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const Judged j = judged(algorithm_, answers[i], verdict[i], options_.level);
      fails[i] = same_truth(verdict[i], truth) && j.wrong && !j.fault && j.answer == group.signature.answer;
    }
    return fails;
  };
  const Shrunk shrunk = shrink(group.found, still_fails, options_.shrink_rounds, out_of_time);
  group.shrink_steps = shrunk.steps;
  group.shrink_cut = shrunk.cut;
  if (self_ || same_truth(label_pairs({shrunk.pair})[0], truth)) {
    group.witness = shrunk.pair;
    return;
  }
  result_.exact_oracle_disagreements.push_back(shrunk.pair);
  group.confirmed_witness = false;  // keep the found pair, which the oracle confirmed
}

HuntResult Hunter::run() {
  const auto start = Clock::now();
  const auto since = [&start] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  const OverlapDecider decide = [this](const std::vector<TrianglePair>& pairs) {
    const std::vector<Truth> t = truths(pairs);
    std::vector<bool> overlap(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i) overlap[i] = t[i].overlap;
    return overlap;
  };
  for (std::size_t k = options_.first_batch; budget_left(k, since()) && !result_.stopped; ++k) {
    std::vector<Candidate> batch = search_batch(options_.seed, k, options_.batch, decide);
    if (options_.pairs && start_of(k) + batch.size() > *options_.pairs) batch.resize(*options_.pairs - start_of(k));
    judge_batch(batch, start_of(k), since());
    result_.pairs += batch.size();
    ++result_.batches;
    if (options_.isolation.max_faults > 0 && result_.faults >= options_.isolation.max_faults) result_.stopped = true;
    if (options_.progress) options_.progress(result_.pairs, result_.groups.size(), result_.failures, since());
  }
  result_.seconds = since();
  const std::function<bool()> out_of_time = [&] {
    return options_.shrink_seconds && since() - result_.seconds >= *options_.shrink_seconds;
  };
  for (Group& g : result_.groups)
    if (!g.known && g.signature.answer != "crash" && g.signature.answer != "timeout") shrink_group(g, out_of_time);
  result_.shrink_seconds = since() - result_.seconds;
  return result_;
}

}  // namespace

void check_level(const Algorithm& algorithm, Level level) {
  // Every algorithm answers overlap, directly or through its relation or segment (overlap_of).
  if (level == Level::relation && !algorithm.answers(Level::relation))
    throw std::invalid_argument(algorithm.name + " does not answer the relation level (--level relation)");
}

std::pair<std::size_t, std::size_t> take_shard(HuntOptions& options, std::size_t k, std::size_t n) {
  if (!options.pairs) throw std::invalid_argument("a hunt in seconds has no fixed set of batches to split into shards");
  const std::size_t pairs = *options.pairs, batches = (pairs + options.batch - 1) / options.batch;
  const CaseRange range = shard_range(k, n, batches);
  options.first_batch = range.first;
  options.end_batch = range.end;
  return {std::min(range.first * options.batch, pairs), std::min(range.end * options.batch, pairs)};
}

HuntResult run_hunt(const Algorithm& algorithm, const HuntOptions& options) {
  check_level(algorithm, options.level);
  return Hunter(algorithm, options).run();
}

}  // namespace tritri::hunt
