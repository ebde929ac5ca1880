// Differential fuzzing: random and near-singular pairs go to the oracle and to every algorithm at
// every level it serves. Nothing may crash (a crash, a sanitizer report or an oracle that
// contradicts itself is the finding); disagreements with the oracle are expected data, counted
// and logged, not failures.
//
// The input bytes are a recipe rather than raw doubles, so that the fuzzer reaches singular
// configurations (cases/generator/pairs.hpp, recipe_pair).
#include "cases/generator/pairs.hpp"
#include "harness/check/check.hpp"

#include <cstdint>
#include <cstdio>

namespace {

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

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tritri::pairs::ByteReader r{data, size};
  tritri::Case c;
  c.name = "fuzz";
  c.pair = tritri::pairs::recipe_pair(r);
  const std::vector<tritri::Case> cases{c};
  const auto labels = tritri::label_cases(cases);
  // The fuzzer must see a crash itself, not have it contained in a child process.
  tritri::IsolationOptions in_process;
  in_process.enabled = false;  // throws (and so aborts) if CGAL contradicts itself
  ++tally.pairs;
  for (const auto& algorithm : tritri::registry().all()) {
    // A process peer (a Node.js script) would start a process per input: a fuzzer's thousands of
    // inputs a second become one. The check and the hunt cover those peers.
    if (!algorithm.timeable()) continue;
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
