// Differential test of the exact algorithm against tritri's oracle (cases/oracle/oracle.hpp),
// on every batch ISA this machine runs, the scalar-only batch, and the one-pair API, at both
// levels. Families:
//   random       random triangles of mixed sizes, scattered or centred on each other (1,000,000)
//   small-int    coordinates in -3..3: shared vertices, coplanar, touching, degenerate
//   scaled       small-int and random pairs times 2^k, k in [-1000, 900]
//   perturbed    small-int pairs with one coordinate moved by 1-3 ulps or by 2^-10..2^-60
//   wide         coordinates of wildly different magnitudes in one pair (subnormal to 2^1000)
//   translated   small-int pairs moved by a random offset (off the grid: exact path)
//   corpus       tritri's singular-configuration corpus (cases/generator), quick or full
// Exits 1 on any disagreement. Usage: exact_diff [--random=N] [--scale=F] [--full-corpus]
// ctest runs a small share (--random=20000 --scale=0.05); the full run (1,000,000 random pairs,
// about 2 million in all, minutes) is a separate command: build/bin/exact_diff --full-corpus.
#include "algorithms/exact/exact.hpp"
#include "cases/generator/exact_pairs.hpp"
#include "cases/generator/corpus.hpp"
#include "cases/label.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

using namespace tritri;
using namespace exact_pairs;
namespace ex = tritri::exact;

namespace {

void show(const TrianglePair& p) {
  for (const Triangle* t : {&p.t1, &p.t2})
    for (const auto& v : t->v) std::printf(" %a %a %a |", v.x(), v.y(), v.z());
  std::printf("\n");
}

long disagreements = 0;

void check_family(const std::string& name, const std::vector<TrianglePair>& pairs) {
  const std::vector<Truth> truth = label_pairs(pairs);
  long degenerate = 0, meets = 0;
  for (const auto& t : truth) {
    degenerate += t.degenerate;
    meets += t.overlap;
  }
  std::printf("%-12s %8zu pairs (%ld meet, %ld degenerate)\n", name.c_str(), pairs.size(), meets, degenerate);
  auto compare = [&](const std::string& path, const std::vector<Overlap>& ov, const std::vector<RelationAnswer>& rel) {
    long bad_o = 0, bad_r = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const bool o_wrong = ov[i] == Overlap::unsupported || (ov[i] == Overlap::yes) != truth[i].overlap;
      const bool r_wrong = rel[i].relation != truth[i].relation || rel[i].dimension != truth[i].dimension;
      bad_o += o_wrong;
      bad_r += r_wrong;
      if ((o_wrong || r_wrong) && bad_o + bad_r <= 3) {
        std::printf("    DISAGREE %s #%zu: overlap %d (oracle %d), relation %s/%s (oracle %s/%s):", path.c_str(), i,
                    static_cast<int>(ov[i]), truth[i].overlap, std::string(to_string(rel[i].relation)).c_str(),
                    std::string(to_string(rel[i].dimension)).c_str(), std::string(to_string(truth[i].relation)).c_str(),
                    std::string(to_string(truth[i].dimension)).c_str());
        show(pairs[i]);
      }
    }
    disagreements += bad_o + bad_r;
    std::printf("    %-10s overlap disagreements %ld, relation disagreements %ld\n", path.c_str(), bad_o, bad_r);
  };
  std::vector<Overlap> ov(pairs.size());
  std::vector<RelationAnswer> rel(pairs.size());
  for (ex::Isa isa : kIsas) {  // every set: NEON on aarch64
    if (!ex::supported(isa)) continue;
    ex::reset_stats();
    ex::overlap_batch_with(isa, pairs.data(), pairs.size(), ov.data());
    const ex::Stats st = ex::stats();
    ex::relation_batch_with(isa, pairs.data(), pairs.size(), rel.data());
    compare(std::string("batch/") + ex::to_string(isa), ov, rel);
    if (isa != ex::Isa::scalar)
      std::printf("               (overlap: %.3f%% undecided by pass 1, %.3f%% by pass 2)\n",
                  100.0 * static_cast<double>(st.pending) / static_cast<double>(pairs.size()),
                  100.0 * static_cast<double>(st.scalar) / static_cast<double>(pairs.size()));
  }
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    ov[i] = ex::overlap(pairs[i]);
    rel[i] = ex::relation(pairs[i]);
  }
  compare("one-pair", ov, rel);
  std::fflush(stdout);
}

std::vector<TrianglePair> make(std::size_t n, GenRng& r, const std::function<TrianglePair(GenRng&)>& f) {
  std::vector<TrianglePair> out(n);
  for (auto& p : out) p = f(r);
  return out;
}

constexpr const char* kUsage =
    "usage: exact_diff [--random=N] [--scale=F] [--full-corpus]\n"
    "Compares exact's answers (every batch ISA this machine runs, the scalar batch, the one-pair\n"
    "API; overlap and relation) with the exact oracle's on generated pair sets; exits 1 on any\n"
    "disagreement, 2 on a bad argument.\n"
    "  --random=N     random pairs of mixed sizes (default 1000000)\n"
    "  --scale=F      the other sets' sizes times F (default 1; ctest runs 0.05)\n"
    "  --full-corpus  the whole generated corpus rather than the quick one (minutes)\n";

// The value after `prefix` in `arg`, parsed whole; false when it is not a count (or a positive
// number): the caller names the argument.
bool parse_count(const std::string& arg, std::size_t prefix, std::size_t& out) {
  const char* s = arg.c_str() + prefix;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(s, &end, 10);
  if (*s < '0' || *s > '9' || *end != '\0') return false;
  out = static_cast<std::size_t>(v);
  return true;
}
bool parse_scale(const std::string& arg, std::size_t prefix, double& out) {
  const char* s = arg.c_str() + prefix;
  char* end = nullptr;
  const double v = std::strtod(s, &end);
  if (end == s || *end != '\0' || !(v > 0.0) || !std::isfinite(v)) return false;
  out = v;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t n_random = 1000000;
  double scale = 1.0;
  bool full_corpus = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    bool ok = true;
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (a.rfind("--random=", 0) == 0) {
      ok = parse_count(a, 9, n_random);
    } else if (a.rfind("--scale=", 0) == 0) {
      ok = parse_scale(a, 8, scale);
    } else if (a == "--full-corpus") {
      full_corpus = true;
    } else {
      std::fprintf(stderr, "exact_diff: unknown argument '%s'\n%s", a.c_str(), kUsage);
      return 2;
    }
    if (!ok) {
      std::fprintf(stderr, "exact_diff: bad value in '%s' (--random takes a count, --scale a positive number)\n", a.c_str());
      return 2;
    }
  }
  auto count = [&](double n) { return static_cast<std::size_t>(n * scale); };
  std::printf("exact: differential test against %s; detected ISA %s\n", oracle_description().c_str(),
              ex::to_string(ex::detected_isa()));
  GenRng r(20240601);
  check_family("random", make(n_random, r, [](GenRng& g) { return random_pair(g); }));
  check_family("small-int", make(count(300000), r, [](GenRng& g) { return small_int_pair(g, 3); }));
  check_family("scaled", make(count(200000), r, [](GenRng& g) {
                 const int k = g.integer(0, 9) == 0 ? (g.coin() ? -1000 : 900) : static_cast<int>(g.integer(-1000, 900));
                 return scaled(g.coin() ? small_int_pair(g, 3) : random_pair(g), k);
               }));
  check_family("perturbed", make(count(200000), r, [](GenRng& g) { return perturbed(small_int_pair(g, 3), g); }));
  check_family("perturbed-scaled", make(count(50000), r, [](GenRng& g) {
                 return scaled(perturbed(small_int_pair(g, 3), g), static_cast<int>(g.integer(-1000, 900)));
               }));
  check_family("wide", make(count(50000), r, [](GenRng& g) { return wide_pair(g); }));
  check_family("translated", make(count(100000), r, [](GenRng& g) {
                 return translated(small_int_pair(g, 3), cube(g, std::ldexp(1.0, static_cast<int>(g.integer(-20, 20)))));
               }));
  {
    const auto cases = corpus::generate_corpus(full_corpus ? corpus::default_options() : corpus::quick_options());
    std::vector<TrianglePair> pairs;
    for (const auto& c : cases) pairs.push_back(c.pair);
    check_family(full_corpus ? "corpus-full" : "corpus-quick", pairs);
  }
  std::printf("total disagreements: %ld\n", disagreements);
  std::printf("%s\n", disagreements == 0 ? "1 passed, 0 failed" : "0 passed, 1 failed");
  return disagreements == 0 ? 0 : 1;
}
