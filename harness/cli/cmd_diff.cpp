// `tritri diff`: where two algorithms answer differently, case by case. Made to set a port
// beside its authors' code (scripts/authors-code builds the originals as plug-ins), it works
// for any two algorithms, e.g. a port against its x86-64-v3 build (NAME@v3fma). Only the two
// answers are compared; with --oracle each overlap difference is also judged: which side is
// wrong, by a false positive or a false negative.
#include "harness/cli/args.hpp"
#include "harness/check/check.hpp"
#include "harness/check/judge.hpp"
#include "harness/cli/commands.hpp"
#include "cases/util/atomic_file.hpp"
#include "cases/util/progress.hpp"

#include <nlohmann/json.hpp>

#include <cstring>
#include <iostream>
#include <map>

namespace tritri::cli {
namespace {

struct Difference {
  std::size_t case_index;
  std::string level;  // "overlap", "segment", or "fate" (one side crashed, hung or declined)
  std::string a, b;   // the two answers, as words
};

struct FamilyTally {
  std::size_t cases = 0, differ = 0, overlap_differ = 0;
  // --oracle: among the overlap differences, the wrong side's error (false positive, negative).
  std::size_t a_fp = 0, a_fn = 0, b_fp = 0, b_fn = 0;
};

struct PairResult {
  const Algorithm* a = nullptr;
  const Algorithm* b = nullptr;
  bool segment = false;  // both answer the segment level: it is compared too
  bool judged = false;   // --oracle: the overlap differences are judged
  std::size_t overlap_differ = 0, segment_differ = 0, fate_differ = 0;
  bool incomplete = false;  // a side stopped at the fault limit (--max-faults)
  std::map<std::string, FamilyTally> families;
  std::vector<Difference> differences;
};

// The answer that decides overlap, as the judge derives it (check.hpp's overlap_of).
std::string overlap_word(const Algorithm& algorithm, const Answers& answers) {
  if (answers.declined) return "unsupported";
  return std::string(to_string(overlap_of(algorithm, answers)));
}

// One side's overlap answer judged against the oracle: counted as a false positive or a
// false negative when it is wrong.
void tally_error(Overlap answer, const Truth& truth, std::size_t& fp, std::size_t& fn) {
  if (judge_overlap(answer, truth) != Verdict::wrong) return;
  ++(answer == Overlap::yes ? fp : fn);
}

// Same kind and, for a point or a segment, the same bits in every coordinate: a port that is
// the published arithmetic gives the published ends exactly, ties included.
bool same_segment(const SegmentAnswer& x, const SegmentAnswer& y) {
  if (x.kind != y.kind) return false;
  if (x.kind != SegmentKind::point && x.kind != SegmentKind::segment) return true;
  return std::memcmp(x.p.data(), y.p.data(), 3 * sizeof(double)) == 0 &&
         std::memcmp(x.q.data(), y.q.data(), 3 * sizeof(double)) == 0;
}

std::string fate_word(const Answers& answers) {
  if (answers.fate != Fate::ok) return std::string(to_string(answers.fate));
  return answers.declined ? "unsupported" : "ok";
}

// `truths`: the oracle's, one per case, with --oracle; empty without.
PairResult compare_pair(const Algorithm& a, const Algorithm& b, const std::vector<Case>& cases,
                        const std::vector<Truth>& truths, const IsolationOptions& isolation) {
  PairResult r;
  r.a = &a;
  r.b = &b;
  r.segment = a.answers(Level::segment) && b.answers(Level::segment);
  r.judged = !truths.empty();
  const auto answers_a = answer_cases(a, cases, isolation);
  const auto answers_b = answer_cases(b, cases, isolation);
  r.incomplete = report_stopped(std::cerr, a, cases, answers_a);
  r.incomplete = report_stopped(std::cerr, b, cases, answers_b) || r.incomplete;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Answers& x = answers_a[i];
    const Answers& y = answers_b[i];
    FamilyTally& tally = r.families[cases[i].family()];
    ++tally.cases;
    std::optional<Difference> d;
    if (x.fate != Fate::ok || y.fate != Fate::ok || x.declined != y.declined) {
      if (fate_word(x) != fate_word(y)) {  // both crashed alike: no difference to report
        d = Difference{i, "fate", fate_word(x), fate_word(y)};
        ++r.fate_differ;
      }
    } else if (overlap_word(a, x) != overlap_word(b, y)) {
      d = Difference{i, "overlap", overlap_word(a, x), overlap_word(b, y)};
      ++r.overlap_differ;
      ++tally.overlap_differ;
      if (r.judged) {
        tally_error(overlap_of(a, x), truths[i], tally.a_fp, tally.a_fn);
        tally_error(overlap_of(b, y), truths[i], tally.b_fp, tally.b_fn);
      }
    } else if (r.segment && !x.declined && !same_segment(x.segment, y.segment)) {
      d = Difference{i, "segment", segment_text(x.segment), segment_text(y.segment)};
      ++r.segment_differ;
    }
    if (!d) continue;
    ++tally.differ;
    r.differences.push_back(*d);
  }
  return r;
}

std::size_t total(const PairResult& r) { return r.overlap_differ + r.segment_differ + r.fate_differ; }

void print_pair(std::ostream& out, const PairResult& r, const std::vector<Case>& cases, std::size_t max_examples) {
  out << r.a->name << " vs " << r.b->name << ": " << cases.size() << " cases, " << total(r)
      << " answered differently (overlap " << r.overlap_differ << ", segment "
      << (r.segment ? std::to_string(r.segment_differ) : std::string("-")) << ", crash/timeout/unsupported "
      << r.fate_differ << ")\n";
  out << "  family\tcases\tdiffer" << (r.judged ? "\twrong: A fp\tA fn\tB fp\tB fn" : "") << '\n';
  for (const auto& [family, t] : r.families) {
    if (t.differ == 0) continue;
    out << "  " << family << '\t' << t.cases << '\t' << t.differ;
    if (r.judged) out << '\t' << t.a_fp << '\t' << t.a_fn << '\t' << t.b_fp << '\t' << t.b_fn;
    out << '\n';
  }
  // Paste-ready: the first few per family, each as a comment and the case in hex floats.
  std::map<std::string, std::size_t> shown;
  for (const auto& d : r.differences) {
    const Case& c = cases[d.case_index];
    if (shown[c.family()]++ >= max_examples) continue;
    out << "# " << c.family() << ": " << d.level << ' ' << r.a->name << '=' << d.a << ' ' << r.b->name << '='
        << d.b << '\n'
        << format_case(c, NumberStyle::hex) << '\n';
  }
  out << '\n';
}

nlohmann::json pair_json(const PairResult& r, const std::vector<Case>& cases, std::size_t max_examples) {
  nlohmann::json j = {{"a", r.a->name},
                      {"b", r.b->name},
                      {"segment_compared", r.segment},
                      {"oracle", r.judged},
                      {"cases", cases.size()},
                      {"differ", total(r)},
                      {"overlap_differ", r.overlap_differ},
                      {"segment_differ", r.segment_differ},
                      {"fate_differ", r.fate_differ}};
  nlohmann::json families = nlohmann::json::array();
  for (const auto& [family, t] : r.families) {
    nlohmann::json f = {{"family", family}, {"cases", t.cases}, {"differ", t.differ}, {"overlap_differ", t.overlap_differ}};
    if (r.judged) f.update({{"a_fp", t.a_fp}, {"a_fn", t.a_fn}, {"b_fp", t.b_fp}, {"b_fn", t.b_fn}});
    families.push_back(f);
  }
  j["families"] = families;
  nlohmann::json examples = nlohmann::json::array();
  std::map<std::string, std::size_t> shown;
  for (const auto& d : r.differences) {
    const Case& c = cases[d.case_index];
    if (shown[c.family()]++ >= max_examples) continue;
    examples.push_back({{"name", c.name}, {"family", c.family()}, {"level", d.level}, {"a", d.a}, {"b", d.b},
                        {"case", format_case(c, NumberStyle::hex)}});
  }
  j["examples"] = examples;
  return j;
}

// The pairs to compare: --pair A=B (repeatable), or exactly two --algo.
std::vector<std::pair<const Algorithm*, const Algorithm*>> chosen_pairs(const Args& args) {
  std::vector<std::pair<const Algorithm*, const Algorithm*>> pairs;
  for (const auto& p : args.values("--pair")) {
    const auto eq = p.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == p.size())
      throw UsageError("--pair takes A=B (two algorithm names), not '" + p + "'");
    const auto a = select_algorithms({p.substr(0, eq)});
    const auto b = select_algorithms({p.substr(eq + 1)});
    pairs.emplace_back(a.front(), b.front());
  }
  const auto algos = args.values("--algo");
  if (!algos.empty()) {
    const auto chosen = select_algorithms(algos);
    if (chosen.size() != 2) throw UsageError("diff compares exactly two --algo (or use --pair A=B)");
    pairs.emplace_back(chosen[0], chosen[1]);
  }
  if (pairs.empty()) throw UsageError("diff needs two --algo NAME, or --pair A=B");
  return pairs;
}

const char* const kDiffHelp =
    "usage: tritri diff (--algo A,B | --pair A=B...) [--oracle] [--json OUT] [--examples N]\n"
    "                   [--plugin LIB...] [--exec COMMAND]... FILE...\n\n"
    "Where two algorithms answer differently, case by case (only their answers; --oracle also\n"
    "judges the differences).\n"
    "Made for a port against its authors' code (scripts/authors-code builds the originals as\n"
    "plug-ins named orig-PORT): e.g.\n"
    "  tritri diff --plugin build/authors/libguigue-overlap.so --pair guigue03=orig-guigue03 FILE...\n"
    "Compared: the overlap answer (from the overlap level, else the relation, else the segment);\n"
    "when both answer the segment level, the segment too (same kind, and the same bits in every\n"
    "coordinate of its ends); a case where one side crashed, hung or was not called counts as a\n"
    "difference of its own ('crash/timeout/unsupported').\n"
    "Printed per pair: the counts, the families with differences, then the first N (--examples,\n"
    "default 3) differing cases of each family, paste-ready (a comment, then the case in hex).\n"
    "  --pair A=B      a pair to compare (repeatable); or give exactly two --algo\n"
    "  --oracle        label the cases with the exact oracle and judge each overlap difference:\n"
    "                  per family, how many times A, and B, is the wrong side, by a false\n"
    "                  positive (fp) or a false negative (fn); in the JSON a_fp, a_fn, b_fp, b_fn\n"
    "                  per family (e.g. --pair moller97=moller97@v3fma: what the compiler changes)\n"
    "  --json OUT      also write the result as JSON (schema tritri-diff/1: per pair the counts,\n"
    "                  per family cases, differ and overlap_differ, and the examples)\n";

}  // namespace

int cmd_diff(int argc, char** argv) {
  Args args(argc, argv,
            merged({.valued = {"--json", "--examples"}, .lists = {"--algo", "--pair"}, .flags = {"--oracle"}},
                   kRunOptions));
  if (args.help()) {
    std::cout << kDiffHelp << '\n' << kRunOptionsHelp << '\n' << kListsHelp
              << "\nExit status: 0 when every pair answers alike; 1 when some differ; 2 on bad arguments or input.\n";
    return kOk;
  }
  load_external_algorithms(args);
  const auto pairs = chosen_pairs(args);
  if (args.positional().empty()) throw UsageError("diff needs case files");
  const std::size_t max_examples = args.count("--examples", 3);
  const auto cases = load_cases(args.positional());
  const auto isolation = isolation_options(args);
  std::vector<Truth> truths;
  if (args.flag("--oracle")) {
    Progress progress("labelling", cases.size());
    for (const OracleRecord& record : label_cases(cases, progress.callback())) truths.push_back(truth_of(record));
  }
  nlohmann::json out = {{"schema", "tritri-diff/1"}, {"inputs", args.positional()}, {"case_count", cases.size()}};
  out["pairs"] = nlohmann::json::array();
  bool any = false, complete = true;
  for (const auto& [a, b] : pairs) {
    const PairResult r = compare_pair(*a, *b, cases, truths, isolation);
    any = any || total(r) > 0;
    complete = complete && !r.incomplete;
    print_pair(std::cout, r, cases, max_examples);
    out["pairs"].push_back(pair_json(r, cases, max_examples));
  }
  out["complete"] = complete;  // false: a side stopped at the fault limit; its cases not run differ
  if (auto path = args.value("--json"))
    write_file_atomically(*path, [&](std::ostream& o) { o << out.dump(1) << '\n'; });
  return any ? kFindings : kOk;
}

}  // namespace tritri::cli
