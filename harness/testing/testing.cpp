#include "harness/testing/tritri/testing.hpp"

#include "harness/check/check.hpp"
#include "harness/check/check_output.hpp"
#include "cases/generator/corpus.hpp"
#include "cases/util/atomic_file.hpp"

#include <array>
#include <cstdlib>
#include <filesystem>
#include <random>

namespace tritri::testing {
namespace {

std::string paste_ready(const TrianglePair& pair) {
  Case c;
  c.name = "failing";
  c.pair = pair;
  return format_case(c, NumberStyle::hex);
}

constexpr std::array<std::array<int, 3>, 6> kOrders{
    {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};

Triangle permuted(const Triangle& t, const std::array<int, 3>& o) { return {{t[o[0]], t[o[1]], t[o[2]]}}; }

}  // namespace

void expect_builtin_cases(OverlapFunction overlap) {
  for (const Case& c : builtin_cases()) {
    const bool truth = oracle_label(c.pair).overlap;
    EXPECT_EQ(overlap(c.pair), truth) << "built-in case " << c.name << " (" << c.label("expect").value_or("")
                                      << "), paste-ready:\n" << paste_ready(c.pair);
  }
}

void expect_random_general_position(OverlapFunction overlap) {
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto random_triangle = [&] {
    return Triangle{{Vec3<double>(unit(rng), unit(rng), unit(rng)), Vec3<double>(unit(rng), unit(rng), unit(rng)),
                     Vec3<double>(unit(rng), unit(rng), unit(rng))}};
  };
  int wrong = 0;
  for (int i = 0; i < 2000 && wrong < 5; ++i) {
    const TrianglePair pair{random_triangle(), random_triangle()};
    const bool truth = oracle_label(pair).overlap;
    if (overlap(pair) != truth) {
      ++wrong;
      ADD_FAILURE() << "random pair " << i << ": answered " << !truth << ", oracle " << truth << "\n"
                    << paste_ready(pair);
    }
  }
}

void expect_order_independence(OverlapFunction overlap) {
  for (const Case& c : builtin_cases()) {
    const bool first = overlap(c.pair);
    for (bool swap : {false, true})
      for (const auto& o1 : kOrders)
        for (const auto& o2 : kOrders) {
          TrianglePair p{permuted(c.pair.t1, o1), permuted(c.pair.t2, o2)};
          if (swap) p = swapped(p);
          if (overlap(p) != first) {
            ADD_FAILURE() << "case " << c.name << ": the answer changes with the order of arguments or vertices\n"
                          << paste_ready(c.pair) << "\n" << paste_ready(p);
            goto next_case;
          }
        }
  next_case:;
  }
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
  std::cout << "[ tritri   ] " << name << " on the quick singular corpus: " << result.failures.size()
            << " disagreements with the oracle in " << corpus.size() << " cases\n";
  if (baseline_path.empty()) return;
  const Baseline current = baseline_of(result, corpus);
  const char* write = std::getenv("TRITRI_WRITE_BASELINE");
  if ((write && std::string(write) == "1") || !std::filesystem::exists(baseline_path)) {
    write_file_atomically(baseline_path, [&](std::ostream& out) { write_baseline(out, current); });
    std::cout << "[ tritri   ] recorded " << current.size() << " disagreements in " << baseline_path << "\n";
    if (!(write && std::string(write) == "1"))
      FAIL() << "no baseline at " << baseline_path << ": recorded one; check it in and run again";
    return;
  }
  const auto comparison = compare_with_baseline(read_baseline(baseline_path), result, corpus);
  for (const auto& [a, c, level, answer, oracle] : comparison.new_failures)
    ADD_FAILURE() << "new disagreement: case " << c << " answered " << answer << ", oracle " << oracle;
  for (const auto& row : comparison.fixed)
    std::cout << "[ tritri   ] no longer wrong (re-record the baseline): case " << std::get<1>(row) << "\n";
}

}  // namespace tritri::testing
