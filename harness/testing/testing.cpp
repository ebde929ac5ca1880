// The overlap suite of a function (TRITRI_OVERLAP_CONFORMANCE).
#include "harness/testing/subject.hpp"

#include "harness/check/check.hpp"
#include "harness/check/check_output.hpp"
#include "cases/generator/corpus.hpp"
#include "cases/util/atomic_file.hpp"

#include <cstdlib>
#include <filesystem>

namespace tritri::testing {

void expect_builtin_cases(OverlapFunction overlap) {
  expect_cases(subject_of(overlap, "the function"), builtin_cases());
}

void expect_random_general_position(OverlapFunction overlap) {
  expect_general_position(subject_of(overlap, "the function"));
}

void expect_order_independence(OverlapFunction overlap) {
  expect_same_in_any_order(subject_of(overlap, "the function"), builtin_cases());
}

void check_singular_corpus(OverlapFunction overlap, const std::string& name, const std::string& baseline_path) {
  static const std::vector<Case> corpus = corpus::generate_corpus(corpus::quick_options());
  static const std::vector<OracleRecord> labels = label_cases(corpus);
  Algorithm algorithm;
  algorithm.name = name;
  CheckResult result;
  result.algorithms = {&algorithm};
  // Score through tritri's own check, so the records match `tritri check --write-baseline`.
  std::vector<Answers> scored(corpus.size());
  for (std::size_t i = 0; i < corpus.size(); ++i) {
    if (has_degenerate_triangle(corpus[i].pair)) {
      scored[i].declined = true;
      continue;
    }
    scored[i].overlap = overlap(corpus[i].pair) ? Overlap::yes : Overlap::no;
  }
  // marks the level as answered
  algorithm.set_batch<Level::overlap>(Scalar::double_, [](const TrianglePair*, std::size_t, Overlap*) {});
  score(algorithm, corpus, labels, scored, result);
  for (const Case& c : corpus) result.names.add(c.name);
  result.names.seal();
  std::cout << "[ tritri   ] " << name << " on the quick singular corpus: " << result.failures.size()
            << " disagreements with the oracle in " << corpus.size() << " cases\n";
  if (baseline_path.empty()) return;
  const Baseline current = baseline_of(result);
  const char* write = std::getenv("TRITRI_WRITE_BASELINE");
  if ((write && std::string(write) == "1") || !std::filesystem::exists(baseline_path)) {
    write_file_atomically(baseline_path, [&](std::ostream& out) { write_baseline(out, current); });
    std::cout << "[ tritri   ] recorded " << current.size() << " disagreements in " << baseline_path << "\n";
    if (!(write && std::string(write) == "1"))
      FAIL() << "no baseline at " << baseline_path << ": recorded one; check it in and run again";
    return;
  }
  const auto comparison = compare_with_baseline(read_baseline(baseline_path), result);
  for (const auto& [a, c, level, answer, oracle] : comparison.new_failures)
    ADD_FAILURE() << "new disagreement: case " << c << " answered " << answer << ", oracle " << oracle;
  for (const auto& row : comparison.fixed)
    std::cout << "[ tritri   ] no longer wrong (re-record the baseline): case " << std::get<1>(row) << "\n";
}

}  // namespace tritri::testing
