#include "harness/cli/args.hpp"
#include "harness/cli/commands.hpp"

#include "harness/run/plugin.hpp"
#include "harness/run/process_plugin.hpp"

#include <map>
#include <ostream>

namespace tritri::cli {

std::vector<Case> load_cases(const std::vector<std::string>& files) {
  if (files.empty()) throw UsageError("no case file given (the built-in cases are cases/builtin.cases)");
  std::vector<Case> all;
  std::map<std::string, std::pair<std::string, int>> seen;
  for (const auto& file : files) {
    for (auto& c : read_case_file(file)) {
      auto [it, inserted] = seen.emplace(c.name, std::pair{c.source, c.line});
      if (!inserted)
        throw CaseFileError(c.source, c.line,
                            "case name '" + c.name + "' is already used at " + it->second.first + ":" +
                                std::to_string(it->second.second));
      all.push_back(std::move(c));
    }
  }
  if (all.empty()) {
    std::string names;
    for (const auto& f : files) names += (names.empty() ? "" : ", ") + f;
    throw UsageError("no cases in " + names + " (every line is blank or a comment)");
  }
  return all;
}

const OptionSpec kRunOptions = {.valued = {"--exec", "--exec-name", "--timeout", "--max-faults"},
                                .lists = {"--plugin"},
                                .flags = {"--no-isolation"}};
// The defaults shown are the ones used: IsolationOptions' and ProcessPluginOptions' (harness/run/).
const std::string kRunOptionsHelp =
    "  --plugin LIB...      also run the algorithms in shared libraries LIB (C ABI: tritri/plugin.h)\n"
    "  --exec COMMAND       also run an algorithm in another process over the line protocol\n"
    "                       (harness/run/process_plugin.hpp); correctness only\n"
    "  --exec-name NAME     the name of the --exec algorithm (default: exec, exec2, ...)\n"
    "  --timeout S          a case that makes no progress for S seconds is a timeout (default " +
    format_double(IsolationOptions{}.stall_seconds) + ";\n                       " +
    format_double(ProcessPluginOptions{}.timeout_seconds) + " per case for --exec)\n" +
    "  --max-faults N       after N crashes or timeouts of one algorithm its run stops: the rest of\n"
    "                       its cases are not run, the result says so and the exit status is 1\n"
    "                       (default " + std::to_string(IsolationOptions{}.max_faults) + "; 0: no limit)\n"
    "  --no-isolation       run algorithms in this process (for a debugger; a crash ends the run)\n";

void load_external_algorithms(const Args& args) {
  for (const auto& lib : args.values("--plugin")) load_plugin(lib);
  const auto commands = args.values("--exec");
  const auto names = args.values("--exec-name");
  if (names.size() > commands.size()) throw UsageError("more --exec-name than --exec options");
  const double timeout = args.seconds("--timeout").value_or(ProcessPluginOptions{}.timeout_seconds);
  for (std::size_t i = 0; i < commands.size(); ++i) {
    const std::string name = i < names.size() ? names[i] : i == 0 ? "exec" : "exec" + std::to_string(i + 1);
    add_process_algorithm(commands[i], name, timeout);
  }
}

IsolationOptions isolation_options(const Args& args) {
  IsolationOptions options;
  options.enabled = !args.flag("--no-isolation");
  options.stall_seconds = args.seconds("--timeout").value_or(options.stall_seconds);
  options.max_faults = args.count("--max-faults", options.max_faults);
  return options;
}

bool report_stopped(std::ostream& out, const Algorithm& algorithm, const std::vector<Case>& cases,
                    const std::vector<Answers>& answers) {
  const auto stopped = stopped_run(algorithm, cases, answers);
  if (stopped) print_stopped(out, *stopped);
  return stopped.has_value();
}

const char* const kShardHelp =
    "  --shard K/N          only part K of N of the input (0 <= K < N; contiguous ranges of the\n"
    "                       cases in file order): the N outputs concatenated in order (the header\n"
    "                       line is shard 0's) are the unsharded output\n";

std::optional<Shard> shard_spec(const Args& args) {
  const auto spec = args.value("--shard");
  if (!spec) return std::nullopt;
  Shard shard;
  const auto slash = spec->find('/');
  const auto digits = [](const std::string& t) { return !t.empty() && t.find_first_not_of("0123456789") == std::string::npos; };
  if (slash == std::string::npos || !digits(spec->substr(0, slash)) || !digits(spec->substr(slash + 1)))
    throw UsageError("--shard: expected K/N with 0 <= K < N (e.g. 0/4), got '" + *spec + "'");
  try {
    shard.index = std::stoull(spec->substr(0, slash));
    shard.count = std::stoull(spec->substr(slash + 1));
  } catch (const std::out_of_range&) {
    throw UsageError("--shard " + *spec + ": a number is too large");
  }
  if (shard.count == 0 || shard.index >= shard.count)
    throw UsageError("--shard " + *spec + ": K must be below N and N at least 1 (shards are numbered 0 to N-1)");
  return shard;
}

std::optional<Shard> shard_option(const Args& args) {
  auto shard = shard_spec(args);
  if (!shard) return std::nullopt;
  shard->total = count_cases(args.positional());
  shard->range = shard_range(shard->index, shard->count, shard->total);
  return shard;
}

std::string vec_text(const Vec3<double>& v) {
  return format_double(v.x()) + "," + format_double(v.y()) + "," + format_double(v.z());
}

std::string segment_text(const SegmentAnswer& s) {
  switch (s.kind) {
    case SegmentKind::point: return vec_text(s.p);
    case SegmentKind::segment: return vec_text(s.p) + ";" + vec_text(s.q);
    default: return std::string(to_string(s.kind));
  }
}

}  // namespace tritri::cli
