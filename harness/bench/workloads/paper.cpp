#include "harness/bench/workloads/paper.hpp"

#include "harness/bench/workloads/ratio.hpp"
#include "cases/util/text.hpp"
#include "cases/util/progress.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace tritri::bench {
namespace paper {
namespace {

const std::vector<const Driver*>& drivers() {
  static const std::vector<const Driver*> all = {&shen03_driver(), &shen03_drawn_driver(), &tropp06_driver(),
                                                      &yuhe13_driver()};
  return all;
}

const Driver& driver_of(const std::string& name) {
  std::string known;
  for (const Driver* d : drivers()) {
    if (d->name == name) return *d;
    known += (known.empty() ? "" : ", ") + d->name;
  }
  throw std::invalid_argument("paper: unknown paper '" + name + "' (known: " + known + ")");
}

std::size_t parse_count(const std::string& text) {
  const std::size_t n = positive_count(text, 8);
  if (n == 0) throw std::invalid_argument("paper: n:'" + text + "' is not a number of pairs from 1 to 99999999");
  return n;
}

double parse_share(const std::string& text) {
  char* end = nullptr;
  const double r = std::strtod(text.c_str(), &end);
  if (text.empty() || *end || !(r >= 0 && r <= 1)) throw std::invalid_argument("paper: r:'" + text + "' is not in [0, 1]");
  return r;
}

// The pool of the driver's pairs, labelled, in its order (shuffled once when asked).
Pool labelled_pool(const std::string& value, std::uint64_t seed, const std::vector<TrianglePair>& pairs, bool shuffled) {
  Progress progress("paper:" + value + ": labelling by the oracle", pairs.size());
  const std::vector<Truth> truth = label_pairs(pairs, progress.callback());
  progress.finish();
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    if (!truth[i].degenerate) order.push_back(i);
  if (shuffled) {
    Rng rng(seed);
    rng.shuffle(order);
  }
  return pool_of_rows("paper", value, seed, pairs, truth, order);
}

class PaperWorkload : public Workload {
 public:
  PaperWorkload() : Workload("paper", "paper[:NAME[/shuffled|/n:N|/r:R|/ours...]]") {}
  std::vector<std::string> default_values() const override {
    std::vector<std::string> names;
    for (const Driver* d : drivers()) names.push_back(d->name);
    return names;
  }
  std::string parse_value(const std::string& value) const override { return paper::parse_value(value).text(); }
  // The drivers' pools are small and some read the user's files: only when asked for.
  bool in_default_set(const std::vector<const Algorithm*>&) const override { return false; }
  // Yu–He's Table 1 times its stages on its own 40 pairs; Tropp's caller-supplied edge vectors
  // are tropp06's stage: both belong on the drivers' pools beside the whole tests.
  bool times_levels_and_stages() const override { return true; }

  std::string cache_identity(const WorkloadInput& input) const override {
    std::string id;
    for (const Driver* d : drivers())
      if (const std::string x = d->identity ? d->identity(input) : ""; !x.empty()) id += d->name + " " + x + ";";
    return id;
  }

  WorkloadPools build(const std::vector<std::string>& values, const WorkloadInput& input) const override {
    WorkloadPools built;
    for (const auto& text : values) {
      const Value v = paper::parse_value(text);
      DriverPairs d = driver_of(v.name).build(v, input);
      if (!d.skipped.empty()) {
        std::fprintf(stderr, "bench: paper:%s skipped: %s\n", text.c_str(), d.skipped.c_str());
        built.context.emplace_back("paper " + text, "skipped: " + d.skipped);
        continue;
      }
      Pool p = labelled_pool(text, sub_seed(input.pool.seed, "paper:" + text), d.pairs, v.shuffled);
      built.context.emplace_back("paper " + text, d.about + " pairs=" + std::to_string(p.size()) +
                                                      " intersecting=" + std::to_string(p.intersecting()) +
                                                      " shuffled=" + (v.shuffled ? "1" : "0"));
      built.pools.push_back(std::move(p));
    }
    return built;
  }
};

}  // namespace

std::string Value::text() const {
  std::string t = name;
  if (n) t += "/n:" + std::to_string(*n);
  if (r) t += "/r:" + ratio_text(*r);
  if (shuffled) t += "/shuffled";
  if (ours) t += "/ours";
  return t;
}

Value parse_value(const std::string& text) {
  Value v;
  std::size_t at = text.find('/');
  v.name = text.substr(0, at);
  const Driver& d = driver_of(v.name);
  while (at != std::string::npos) {
    const std::size_t next = text.find('/', at + 1);
    const std::string m = text.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1);
    const std::string key = m.substr(0, m.find(':'));
    if (key.empty() || (" " + d.modifiers + " ").find(" " + key + " ") == std::string::npos)
      throw std::invalid_argument("paper:" + v.name + " does not take '/" + m + "' (it takes: " + d.modifiers + ")");
    if (m == "shuffled") v.shuffled = true;
    else if (m == "ours") v.ours = true;
    else if (m.rfind("n:", 0) == 0) v.n = parse_count(m.substr(2));
    else if (m.rfind("r:", 0) == 0) v.r = parse_share(m.substr(2));
    else throw std::invalid_argument("paper: unknown modifier '/" + m + "' (shuffled, n:N, r:R, ours)");
    at = next;
  }
  return v;
}

Triangle unit_cube_triangle(Rng& rng) {
  Triangle t;
  for (int k = 0; k < 3; ++k) t[k] = {rng.unit(), rng.unit(), rng.unit()};
  return t;
}

TrianglePair rounded_to_float(const TrianglePair& p) { return cast<double>(cast<float>(p)); }

std::vector<TrianglePair> yes_then_no(std::size_t yes, std::size_t no, Rng& rng, TrianglePair (*make)(Rng&),
                                      const std::string& what) {
  std::vector<TrianglePair> got_yes, got_no;
  for (int round = 0; got_yes.size() < yes || got_no.size() < no; ++round) {
    if (round > 1000) throw std::runtime_error(what + ": the distribution yields too few pairs of one class");
    std::vector<TrianglePair> chunk(4096);
    for (auto& p : chunk) p = make(rng);
    const std::vector<Truth> truth = label_pairs(chunk);
    for (std::size_t i = 0; i < chunk.size(); ++i) {
      if (truth[i].degenerate) continue;
      auto& cls = truth[i].overlap ? got_yes : got_no;
      if (cls.size() < (truth[i].overlap ? yes : no)) cls.push_back(chunk[i]);
    }
  }
  got_yes.insert(got_yes.end(), got_no.begin(), got_no.end());
  return got_yes;
}

std::vector<TrianglePair> ours_yes_then_no(std::size_t yes, std::size_t no, const WorkloadInput& input) {
  const RatioCandidates c = ratio_candidates(yes, no, input.pool.seed, "paper pools (ours)");
  std::vector<TrianglePair> pairs;
  for (std::size_t i = 0; i < yes; ++i) pairs.push_back(c.yes[i].pair);
  for (std::size_t i = 0; i < no; ++i) pairs.push_back(c.no[i].pair);
  return pairs;
}

}  // namespace paper

std::unique_ptr<Workload> make_paper_workload() { return std::make_unique<paper::PaperWorkload>(); }

}  // namespace tritri::bench
