#include "harness/bench/pools.hpp"

#include "cases/util/progress.hpp"

#include <algorithm>
#include <cstdio>

namespace tritri::bench {
namespace {

// Random order of the vertices and of the triangles, so no algorithm always sees the contact on
// the same vertex or the same triangle.
TrianglePair scramble(TrianglePair p, Rng& r) {
  for (Triangle* t : {&p.t1, &p.t2}) {
    const auto k = r.integer(0, 2);
    std::rotate(t->v.begin(), t->v.begin() + k, t->v.end());
    if (r.coin()) std::swap(t->v[1], t->v[2]);
  }
  if (r.coin()) std::swap(p.t1, p.t2);
  return p;
}

// FNV-1a continued over the pair's 18 coordinates.
std::uint64_t hash_pair(const TrianglePair& p, std::uint64_t h) {
  for (const Triangle* t : {&p.t1, &p.t2})
    for (const auto& v : t->v) h = fnv1a(v.data(), 3 * sizeof(double), h);
  return h;
}

}  // namespace

std::size_t Pool::intersecting() const {
  return static_cast<std::size_t>(std::count_if(truth.begin(), truth.end(), [](const Truth& t) { return t.overlap; }));
}

std::array<std::size_t, 5> Pool::stage_mix() const {
  std::array<std::size_t, 5> mix{};
  for (const auto& t : truth) ++mix[static_cast<std::size_t>(t.stage)];
  return mix;
}

std::string Pool::stage_mix_text() const {
  const auto mix = stage_mix();
  std::string out;
  for (Stage s : {Stage::plane2, Stage::plane1, Stage::coplanar, Stage::interval, Stage::degenerate}) {
    if (s == Stage::degenerate && mix[static_cast<std::size_t>(s)] == 0) continue;
    if (!out.empty()) out += ' ';
    out += std::string(to_string(s)) + "=" + std::to_string(mix[static_cast<std::size_t>(s)]);
  }
  return out;
}

std::uint64_t pair_hash(const TrianglePair& p) { return hash_pair(p, kFnvOffset); }

std::vector<Candidate> draw(std::size_t count, Rng& rng, const std::function<TrianglePair(Rng&)>& make,
                            std::unordered_set<std::uint64_t>& seen, const std::string& what) {
  std::vector<TrianglePair> pairs(count);
  {
    Progress progress(what + ": drawing pairs", count);
    for (std::size_t i = 0; i < count; ++i) {
      pairs[i] = scramble(make(rng), rng);
      if (i % 4096 == 0) progress.update(i);
    }
  }
  Progress progress(what + ": labelling by the oracle", count);
  const auto truth = label_pairs(pairs, progress.callback());
  progress.finish();
  std::vector<Candidate> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    if (truth[i].relation == Relation::degenerate) continue;
    if (!seen.insert(pair_hash(pairs[i])).second) continue;
    out.push_back({pairs[i], truth[i]});
  }
  return out;
}

Pool make_pool(std::string workload, std::string value, std::uint64_t seed, std::vector<Candidate> c) {
  Rng rng(seed);
  rng.shuffle(c);
  Pool p{std::move(workload), std::move(value), seed, {}, {}};
  p.pairs.reserve(c.size());
  p.truth.reserve(c.size());
  for (const auto& x : c) {
    p.pairs.push_back(x.pair);
    p.truth.push_back(x.truth);
  }
  return p;
}

std::uint64_t hash_pools(const std::vector<const Pool*>& pools) {
  std::uint64_t h = kFnvOffset;
  for (const Pool* p : pools) {
    const std::string name = p->name();
    h = fnv1a(name, h);
    for (const auto& pair : p->pairs) h = hash_pair(pair, h);
  }
  return h;
}

Pool pool_of_rows(std::string workload, std::string value, std::uint64_t seed, const std::vector<TrianglePair>& pairs,
                  const std::vector<Truth>& truth, const std::vector<std::size_t>& rows) {
  Pool p{std::move(workload), std::move(value), seed, {}, {}};
  for (std::size_t r : rows)
    if (!truth[r].degenerate) {
      p.pairs.push_back(pairs[r]);
      p.truth.push_back(truth[r]);
    }
  return p;
}

}  // namespace tritri::bench
