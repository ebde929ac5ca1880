// Differential fuzzing: random and near-singular pairs go to the oracle and to every algorithm at
// every level it serves. Nothing may crash (a crash, a sanitizer report or an oracle that
// contradicts itself is the finding); disagreements with the oracle are expected data, counted
// and logged, not failures.
//
// The input bytes are a recipe rather than raw doubles, so that the fuzzer reaches singular
// configurations: coordinates on a small integer grid (shared vertices, coplanar and collinear
// contact happen often), then optional tiny nudges, scales and offsets by powers of two.
#include "harness/check/check.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace {

struct Reader {
  const std::uint8_t* data;
  std::size_t size, at = 0;
  std::uint8_t byte() { return at < size ? data[at++] : 0; }
};

struct Tally {
  unsigned long pairs = 0, disagreements = 0;
  FILE* log = nullptr;
  ~Tally() {
    std::fprintf(stderr, "differential: %lu pairs, %lu disagreements with the oracle (logged to fuzz-disagreements.log)\n",
                 pairs, disagreements);
    if (log) std::fclose(log);
  }
};
Tally tally;

tritri::TrianglePair recipe(Reader& r) {
  double xyz[18];
  for (double& x : xyz) x = static_cast<double>(static_cast<int>(r.byte() % 9) - 4);
  const std::uint8_t twist = r.byte();
  if (twist & 1) {  // nudge one coordinate by a few ulps or by a tiny relative amount
    double& x = xyz[r.byte() % 18];
    const int ulps = static_cast<int>(r.byte() % 7) - 3;
    for (int k = 0; k < std::abs(ulps); ++k) x = std::nextafter(x, ulps > 0 ? 1e300 : -1e300);
  }
  if (twist & 2) {  // scale by 2^k: exact, the answer must not change
    const int k = static_cast<int>(r.byte() % 81) - 40;
    for (double& x : xyz) x = std::ldexp(x, k);
  }
  if (twist & 4) {  // translate by 2^k: exact while the coordinates stay representable
    const double offset = std::ldexp(1.0, static_cast<int>(r.byte() % 61) - 10);
    for (int i = 0; i < 18; i += 3) xyz[i] += offset;
  }
  if (twist & 8) {  // an arbitrary double for one coordinate
    std::uint64_t bits = 0;
    for (int k = 0; k < 8; ++k) bits = bits << 8 | r.byte();
    double any;
    std::memcpy(&any, &bits, sizeof any);
    if (std::isfinite(any) && std::abs(any) < 1e150) xyz[r.byte() % 18] = any;
  }
  tritri::TrianglePair p;
  for (int v = 0; v < 3; ++v) {
    p.t1[v] = {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]};
    p.t2[v] = {xyz[9 + 3 * v], xyz[9 + 3 * v + 1], xyz[9 + 3 * v + 2]};
  }
  return p;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Reader r{data, size};
  tritri::Case c;
  c.name = "fuzz";
  c.pair = recipe(r);
  const std::vector<tritri::Case> cases{c};
  const auto labels = tritri::label_cases(cases);
  // The fuzzer must see a crash itself, not have it contained in a child process.
  tritri::IsolationOptions in_process;
  in_process.enabled = false;  // throws (and so aborts) if CGAL contradicts itself
  ++tally.pairs;
  for (const auto& algorithm : tritri::registry().all()) {
    tritri::CheckResult result;
    tritri::score(algorithm, cases, labels, tritri::answer_cases(algorithm, cases, in_process), result);
    for (const auto& f : result.failures) {
      ++tally.disagreements;
      if (!tally.log) tally.log = std::fopen("fuzz-disagreements.log", "a");
      if (tally.log && tally.disagreements <= 10000)
        std::fprintf(tally.log, "# %s %s: answered %s, oracle %s\n%s\n", f.algorithm.c_str(),
                     std::string(tritri::to_string(f.level)).c_str(), f.answer.c_str(), f.expected.c_str(),
                     tritri::format_case(c, tritri::NumberStyle::hex).c_str());
    }
  }
  return 0;
}
