// paper:tropp06: the main() of Tropp, Tal & Shimshoni's file (the driver of their timing, as
// issue #26 describes it; the file is not in jgt-code, `scripts/authors-code --tropp FILE` takes a
// user's copy):
//   - data: 10,000 triangles P_i and 10,000 Q_i, every coordinate drand48() (uniform in the unit
//     cube, double), P's and Q's coordinates drawn alternately;
//   - edges: precomputed before the clock starts, EP_i = (P_i1 − P_i0, P_i2 − P_i0) and, as the
//     driver writes it, EQ_i = (Q_i1 − P_i0, Q_i2 − P_i0): B's edges are taken from A's first
//     vertex, so B_j = (Q_j0, Q_j0 + Q_j1 − P_j0, Q_j0 + Q_j2 − P_j0), which reaches [−1, 2]³;
//   - loop: for j < 1,000, for i < 10,000: tr_tri_intersect3D(A_i, B_j), double.
// The pool is that loop's pairs in its order: B_j held for 10,000 calls while A_i runs through
// the same sequence each time. 10⁷ distinct pairs do not fit a pool (1.4 GB, and the oracle
// labels every pair), so it keeps the first 8 B's (80,000 pairs, /n:N for another count): a
// pass over it has the per-pair pattern of the driver's loop. drand48 is replaced by our RNG's
// unit() (53 bits where drand48 has 48: the same distribution). Takes /n:N, /shuffled, /ours.
// The edges precomputed outside the timed loop are tropp06's stage:edges-given on this pool.
// /ours: each of the driver's pairs replaced by one of ours with the same answer, so the
// sequence of answers, which a branch predictor sees, is the driver's.
#include "harness/bench/workloads/paper.hpp"

#include <algorithm>

namespace tritri::bench::paper {
namespace {

constexpr std::size_t kTriangles = 10000;
constexpr std::size_t kDefaultPairs = 8 * kTriangles;

std::vector<TrianglePair> ours_in_place(const std::vector<TrianglePair>& pairs, const WorkloadInput& input) {
  const std::vector<Truth> truth = label_pairs(pairs);
  std::size_t yes = 0;
  for (const Truth& t : truth) yes += t.overlap ? 1 : 0;
  const std::vector<TrianglePair> ours = ours_yes_then_no(yes, pairs.size() - yes, input);
  std::vector<TrianglePair> out;
  std::size_t next_yes = 0, next_no = yes;
  for (const Truth& t : truth) out.push_back(ours[t.overlap ? next_yes++ : next_no++]);
  return out;
}

DriverPairs grid(const Value& v, const WorkloadInput& input) {
  Rng rng(sub_seed(input.pool.seed, "paper:tropp06"));
  const std::size_t n = v.n.value_or(kDefaultPairs);
  const std::size_t bs = std::min(kTriangles, (n + kTriangles - 1) / kTriangles);
  std::vector<Triangle> a(kTriangles), b(bs);
  for (std::size_t i = 0; i < kTriangles; ++i) {
    Triangle p, q;
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        p[j][k] = rng.unit();
        q[j][k] = rng.unit();
      }
    a[i] = p;
    if (i < bs) b[i] = {{q[0], q[0] + (q[1] - p[0]), q[0] + (q[2] - p[0])}};
  }
  std::vector<TrianglePair> pairs;
  for (std::size_t j = 0; j < bs; ++j)
    for (std::size_t i = 0; i < kTriangles && pairs.size() < n; ++i) pairs.push_back({a[i], b[j]});
  if (v.ours) pairs = ours_in_place(pairs, input);
  return {pairs, "", "driver=Tropp2006/main() scalar=double edges=precomputed order=" +
                         std::string(v.shuffled ? "shuffled" : "B-held-A-inner") + " B=" + std::to_string(bs) +
                         " distribution=" + (v.ours ? "ours" : "unit-cube")};
}

}  // namespace

const Driver& tropp06_driver() {
  static const Driver d{"tropp06", "shuffled n ours", &grid};
  return d;
}

}  // namespace tritri::bench::paper
