#include "harness/run/process_plugin.hpp"

#include "harness/run/process_child.hpp"

#include "cases/casefile.hpp"
#include "cases/util/input_error.hpp"
#include "cases/util/text.hpp"

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>

namespace tritri {
namespace {

constexpr const char* kProtocol = "2";
// Cases written ahead of the answer awaited: enough that the pipe never runs dry between
// answers, few enough that a plug-in restarted after a fault is not handed much twice.
constexpr std::size_t kInFlight = 256;
// A freshly started process also pays its interpreter's start-up before its first answer, which
// on a loaded machine can exceed a short per-answer limit: that answer gets this much more.
constexpr double kStartupSeconds = 10.0;

std::string request(const std::string& name, const TrianglePair& pair) {
  Case c;
  c.name = name;
  c.pair = pair;
  return format_case(c) + '\n';
}

// A plug-in that dies makes our next write fail with EPIPE; we handle that, not the signal.
class SigpipeIgnored {
 public:
  SigpipeIgnored() {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGPIPE, &ignore, &previous_);
  }
  ~SigpipeIgnored() { sigaction(SIGPIPE, &previous_, nullptr); }
  SigpipeIgnored(const SigpipeIgnored&) = delete;
  SigpipeIgnored& operator=(const SigpipeIgnored&) = delete;

 private:
  struct sigaction previous_ {};
};

// A time the plug-in wrote: a whole word strtod reads.
std::optional<double> number(std::string_view word) {
  const std::string text(word);
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) return std::nullopt;
  return x;
}

bool is_greeting(const std::string& line) { return line.rfind("#tritri", 0) == 0; }

// "#tritri 2 degenerate timing": unknown words are features of a later protocol, ignored.
ProcessFeatures parse_greeting(const std::string& line) {
  ProcessFeatures f;
  f.greeted = true;
  for (const auto& w : split_words(line)) {
    f.degenerate = f.degenerate || w == "degenerate";
    f.timing = f.timing || w == "timing";
  }
  return f;
}

// The next answer line of a child; a fresh one's greeting, if it sends one, is read first.
ProcessChild::Read read_answer(ProcessChild& child, bool& fresh, ProcessFeatures& features, std::string& line,
                               double limit) {
  ProcessChild::Read got = child.read_line(line, limit);
  if (fresh && got == ProcessChild::Read::line && is_greeting(line)) {
    features = parse_greeting(line);
    got = child.read_line(line, limit);
  }
  fresh = false;
  return got;
}

// Reads answer lines into a ProcessAnswers, holding the plug-in to the protocol.
class AnswerReader {
 public:
  AnswerReader(const ProcessPluginOptions& options, const std::vector<std::string>& names, ProcessAnswers& out)
      : options_(options), names_(names), out_(out) {
    out.stopped_at = names.size();
    out.overlap.assign(names.size(), Overlap::unsupported);
    out.relation.assign(names.size(), RelationAnswer{});
  }

  void read(std::size_t i, const std::string& line) {
    const auto w = split_words(line);
    if (w.size() < 2 || w.size() > 3) throw error(i, line, "expected 'name overlap [relation]'");
    if (w[0] != names_[i]) throw error(i, line, "the answer names another case");
    if (w[1] == "0") out_.overlap[i] = Overlap::no;
    else if (w[1] == "1") out_.overlap[i] = Overlap::yes;
    else if (w[1] != "unsupported") throw error(i, line, "overlap must be 0, 1 or unsupported");
    const bool has_relation = w.size() == 3;
    if (relation_seen_ < 0) relation_seen_ = has_relation;
    if (has_relation != (relation_seen_ == 1)) throw error(i, line, "every answer must give a relation, or none may");
    out_.answers_relation = relation_seen_ == 1;
    if (!has_relation) return;
    const auto r = parse_relation(w[2]);
    if (!r || *r == Relation::degenerate || *r == Relation::unknown)
      throw error(i, line, "'" + std::string(w[2]) + "' is not a relation (see 'tritri label --help')");
    out_.relation[i] = answer_with(*r);
  }

 private:
  InputError error(std::size_t i, const std::string& line, const std::string& what) const {
    return InputError("process plug-in '" + options_.command + "' answered '" + line + "' to case '" + names_[i] +
                      "': " + what);
  }

  const ProcessPluginOptions& options_;
  const std::vector<std::string>& names_;
  ProcessAnswers& out_;
  int relation_seen_ = -1;  // unknown until the first answer
};

}  // namespace

ProcessAnswers run_process_plugin(const ProcessPluginOptions& options, const std::vector<std::string>& names,
                                  const std::vector<TrianglePair>& pairs) {
  const SigpipeIgnored sigpipe;
  ProcessAnswers result;
  AnswerReader reader(options, names, result);
  auto child = std::make_unique<ProcessChild>(options.command, kProtocol);
  bool fresh = true;
  std::size_t sent = 0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    for (; sent < pairs.size() && sent < i + kInFlight; ++sent) child->send(request(names[sent], pairs[sent]));
    std::string line;
    const double limit = options.timeout_seconds + (fresh ? kStartupSeconds : 0.0);
    const ProcessChild::Read got = read_answer(*child, fresh, result.features, line, limit);
    if (got == ProcessChild::Read::line) {
      reader.read(i, line);
      continue;
    }
    // The first case it has not answered is the one it was on: it answers in order.
    const std::string ended = child->stop();
    if (got == ProcessChild::Read::timeout)
      result.faults.push_back({i, Fate::timeout, "no answer within " + format_double(limit) + " s"});
    else
      result.faults.push_back({i, Fate::crash, "the process ended (" + ended + ")"});
    if (options.max_faults && result.faults.size() >= options.max_faults && i + 1 < pairs.size()) {
      result.stopped_at = i + 1;
      break;
    }
    child = std::make_unique<ProcessChild>(options.command, kProtocol);
    fresh = true;
    sent = i + 1;
  }
  return result;
}

SelfTimed time_process_plugin(const ProcessPluginOptions& options, const std::vector<std::string>& names,
                              const std::vector<TrianglePair>& pairs, int repetitions, double min_seconds) {
  const SigpipeIgnored sigpipe;
  auto fail = [&](const std::string& what) { return InputError("process plug-in '" + options.command + "' " + what); };
  SelfTimed out;
  AnswerReader reader(options, names, out.answers);
  ProcessChild child(options.command, kProtocol);
  std::string line;
  if (child.read_line(line, kStartupSeconds + options.timeout_seconds) != ProcessChild::Read::line || !is_greeting(line))
    throw fail("did not greet with '#tritri 2 ... timing' (harness/run/process_plugin.hpp): it does not time itself");
  out.answers.features = parse_greeting(line);
  if (!out.answers.features.timing) throw fail("does not offer 'timing' in its greeting '" + line + "'");
  child.send("#time " + std::to_string(pairs.size()) + " " + std::to_string(repetitions) + " " +
             format_double(min_seconds) + "\n");
  for (std::size_t i = 0; i < pairs.size(); ++i) child.send(request(names[i], pairs[i]));
  // Reading the pool and its first pass at the per-answer limit per thousand pairs, and the
  // warm-up's and each repetition's minimum time twice over.
  const double budget = kStartupSeconds + options.timeout_seconds * (1.0 + static_cast<double>(pairs.size()) / 1000.0) +
                        2.0 * (repetitions + 1) * min_seconds;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(budget);
  auto next = [&](const char* what) {
    const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    const ProcessChild::Read got = child.read_line(line, std::max(left, 0.0));
    if (got == ProcessChild::Read::timeout) throw fail("gave no " + std::string(what) + " within " + format_double(budget) + " s");
    if (got == ProcessChild::Read::eof) throw fail("ended (" + child.stop() + ") before its " + what);
  };
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    next("answer");
    reader.read(i, line);
  }
  next("'#timed' line");
  const auto w = split_words(line);
  if (w.empty() || w[0] != "#timed" || w.size() != static_cast<std::size_t>(repetitions) + 1)
    throw fail("answered '" + line + "' where '#timed' and " + std::to_string(repetitions) + " times were due");
  for (std::size_t r = 1; r < w.size(); ++r) {
    const auto ns = number(w[r]);
    if (!ns || !std::isfinite(*ns) || *ns < 0) throw fail("gave the time '" + std::string(w[r]) + "' in '" + line + "'");
    out.ns_per_pair.push_back(*ns);
  }
  return out;
}

}  // namespace tritri

namespace tritri {
namespace {
// By name: the registry's entries are copied (NAME@float and the like), names are unique.
std::map<std::string, ProcessPluginOptions>& process_plugins() {
  static std::map<std::string, ProcessPluginOptions> plugins;
  return plugins;
}

// Two triangles in crossing planes, apart: any test answers it quickly.
TrianglePair probe_pair() {
  const Triangle floor{{Vec3<double>(0, 0, 0), Vec3<double>(1, 0, 0), Vec3<double>(0, 1, 0)}};
  const Triangle above{{Vec3<double>(0, 0, 1), Vec3<double>(1, 0, 2), Vec3<double>(0, 1, 3)}};
  return {floor, above};
}

std::map<std::string, ProcessFeatures>& features_seen() {
  static std::map<std::string, ProcessFeatures> features;
  return features;
}
}  // namespace

ProcessFeatures process_features(const std::string& name) {
  auto& seen = features_seen();
  if (const auto found = seen.find(name); found != seen.end()) return found->second;
  const ProcessPluginOptions* process = find_process_plugin(name);
  if (!process) return {};
  return seen[name] = run_process_plugin(*process, {"probe"}, {probe_pair()}).features;
}

const ProcessPluginOptions* find_process_plugin(const std::string& name) {
  auto& plugins = process_plugins();
  if (const auto found = plugins.find(name); found != plugins.end()) return &found->second;
  // A registered algorithm that runs as a process, with the default limit.
  const Algorithm* a = registry().find(name);
  if (!a || a->process.empty()) return nullptr;
  return &(plugins[name] = {process_command(*a)});
}

const Algorithm& add_process_algorithm(const std::string& command, const std::string& name,
                                       double timeout_seconds) {
  if (registry().find(name))
    throw InputError("process plug-in name '" + name + "' is already taken (choose one with --exec-name)");
  const ProcessAnswers probe = run_process_plugin({command, timeout_seconds}, {"probe"}, {probe_pair()});
  if (!probe.faults.empty())
    throw InputError("process plug-in '" + command + "' did not answer a probe case: " +
                             probe.faults.front().detail);
  Algorithm a;
  a.name = name;
  a.citation = "process plug-in: " + command;
  a.summary = "process plug-in (" + command + ")";
  a.accepts_degenerate = probe.features.degenerate;
  a.answered_elsewhere = probe.answers_relation ? LevelSet{Level::overlap, Level::relation} : LevelSet{Level::overlap};
  a.folder = "exec:" + command;
  const Algorithm& added = add_external_algorithm(std::move(a));
  process_plugins()[name] = {command, timeout_seconds};
  features_seen()[name] = probe.features;
  return added;
}

}  // namespace tritri
