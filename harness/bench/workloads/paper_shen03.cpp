// paper:shen03 and paper:shen03-drawn: Shen, Heng & Tang 2003's test package (jgt-code
// Volume_08/Number_1/Shen2003/tri_tri_test), whose Performance.cpp times their test against
// Möller's:
//   - data: data/intersected.txt and data/separated.txt, 5,000 pairs each, written by
//     Generation.cpp: both triangles' coordinates uniform in the unit cube (rand()/RAND_MAX, in
//     float), printed with six decimals, filed by what Möller's float test answered;
//   - pool: PAIR_NUMBER = 5,000 pairs at INTERSECTION_RATIO = 0.1 (datatype.h): the first 500
//     pairs of intersected.txt, then the first 4,500 of separated.txt, in that order — sorted by
//     outcome — read into float arrays;
//   - loop: LOOP_NUMBER = 1,000 passes over the 5,000 pairs, nothing precomputed, each call
//     tri_tri_intersect(u0, u1, u2, v0, v1, v2) with the file's second triangle first.
// paper:shen03 reads the files from the user's checkout (--authors-code PATH; never stored in
// this repository) and is skipped with one line without it. paper:shen03-drawn draws the same
// set-up from Generation.cpp's distribution with our RNG (six decimals, then float), labelled by
// the oracle in place of Möller's test. Both take /n:N, /r:R, /shuffled and /ours.
#include "harness/bench/workloads/paper.hpp"

#include "harness/bench/workloads/ratio.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace tritri::bench::paper {
namespace {

constexpr std::size_t kPairs = 5000;
constexpr double kRatio = 0.1;
constexpr const char* kData = "/Volume_08/Number_1/Shen2003/tri_tri_test/data/";

std::size_t yes_of(const Value& v) { return intersecting_of(v.r.value_or(kRatio), v.n.value_or(kPairs)); }
std::size_t no_of(const Value& v) { return v.n.value_or(kPairs) - yes_of(v); }

// A pair as the package's files hold it, v0 v1 v2 u0 u1 u2, with u first as Performance.cpp
// calls tri_tri_intersect(u0, u1, u2, v0, v1, v2).
TrianglePair pair_of(const float (&x)[18]) {
  TrianglePair p;
  for (int k = 0; k < 3; ++k) {
    p.t2[k] = {x[3 * k], x[3 * k + 1], x[3 * k + 2]};
    p.t1[k] = {x[9 + 3 * k], x[9 + 3 * k + 1], x[9 + 3 * k + 2]};
  }
  return p;
}

// The first `count` pairs of one of the package's files, as Performance.cpp reads them (float),
// the file's second triangle first.
std::vector<TrianglePair> read_data(const std::string& path, std::size_t count) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("paper:shen03: cannot read " + path);
  std::vector<TrianglePair> pairs;
  for (std::size_t i = 0; i < count; ++i) {
    float x[18];
    for (float& c : x)
      if (!(in >> c)) throw std::invalid_argument("paper:shen03: " + path + " ends before pair " + std::to_string(i + 1) +
                                                  " of the " + std::to_string(count) + " needed");
    pairs.push_back(pair_of(x));
  }
  return pairs;
}

std::string describe(const Value& v, const char* source) {
  std::ostringstream s;
  s << "driver=Shen2003/Performance.cpp source=" << source << " scalar=float loops=1000 order="
    << (v.shuffled ? "shuffled" : "intersecting-first") << " ratio=" << ratio_text(v.r.value_or(kRatio));
  return s.str();
}

DriverPairs from_files(const Value& v, const WorkloadInput& input) {
  if (v.ours) return {ours_yes_then_no(yes_of(v), no_of(v), input), "", describe(v, "ours")};
  if (input.authors_code.empty()) return {{}, "needs the authors' data files: --authors-code PATH (a jgt-code checkout)", ""};
  const std::string dir = input.authors_code + kData;
  std::vector<TrianglePair> pairs = read_data(dir + "intersected.txt", yes_of(v));
  const std::vector<TrianglePair> no = read_data(dir + "separated.txt", no_of(v));
  pairs.insert(pairs.end(), no.begin(), no.end());
  return {pairs, "", describe(v, "the package's data files")};
}

// Generation.cpp's draw: rand()/RAND_MAX in float, printed with six decimals and read back
// into float, in the file's order (the first triangle v, then u: T1 is u, as Performance.cpp
// calls it).
TrianglePair generation_pair(Rng& rng) {
  float x[18];
  for (float& c : x) c = static_cast<float>(std::round(rng.unit() * 1e6) / 1e6);
  return pair_of(x);
}

DriverPairs drawn(const Value& v, const WorkloadInput& input) {
  if (v.ours) return {ours_yes_then_no(yes_of(v), no_of(v), input), "", describe(v, "ours")};
  Rng rng(sub_seed(input.pool.seed, "paper:shen03-drawn"));
  return {yes_then_no(yes_of(v), no_of(v), rng, &generation_pair, "paper:shen03-drawn"), "",
          describe(v, "Generation.cpp's distribution, our RNG")};
}

// The data files' content, so that a cached pool is not reused for other files.
std::string data_identity(const WorkloadInput& input) {
  if (input.authors_code.empty()) return "";
  std::string id;
  for (const char* f : {"intersected.txt", "separated.txt"}) {
    std::ifstream in(input.authors_code + kData + f, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    id += std::string(f) + "=" + hex64(fnv1a(bytes.str())) + " ";
  }
  return id;
}

}  // namespace

const Driver& shen03_driver() {
  static const Driver d{"shen03", "shuffled n r ours", &from_files, &data_identity};
  return d;
}

const Driver& shen03_drawn_driver() {
  static const Driver d{"shen03-drawn", "shuffled n r ours", &drawn};
  return d;
}

}  // namespace tritri::bench::paper
