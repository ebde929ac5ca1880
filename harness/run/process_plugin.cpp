#include "harness/run/process_plugin.hpp"

#include "cases/util/text.hpp"

#include "cases/casefile.hpp"
#include "cases/util/input_error.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <map>
#include <memory>
#include <poll.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

namespace tritri {
namespace {

class Child {
 public:
  explicit Child(const std::string& command) {
    int in[2], out[2];
    if (pipe(in) != 0 || pipe(out) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    pid_ = fork();
    if (pid_ < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
    if (pid_ == 0) {
      setpgid(0, 0);  // its own process group, so a timeout kills whatever it started
      dup2(in[0], STDIN_FILENO);
      dup2(out[1], STDOUT_FILENO);
      close(in[0]); close(in[1]); close(out[0]); close(out[1]);
      execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    close(in[0]);
    close(out[1]);
    to_ = in[1];
    from_ = out[0];
  }
  ~Child() { stop(); }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  bool write_line(const std::string& line) {
    std::size_t sent = 0;
    while (sent < line.size()) {
      const ssize_t n = ::write(to_, line.data() + sent, line.size() - sent);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;  // EPIPE: it has gone
      sent += static_cast<std::size_t>(n);
    }
    return true;
  }

  enum class Read { line, eof, timeout };
  Read read_line(std::string& line, double seconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    for (;;) {
      if (auto nl = buffer_.find('\n'); nl != std::string::npos) {
        line = buffer_.substr(0, nl);
        buffer_.erase(0, nl + 1);
        return Read::line;
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) return Read::timeout;
      pollfd p{from_, POLLIN, 0};
      const int ready = poll(&p, 1, static_cast<int>(left.count()));
      if (ready < 0 && errno == EINTR) continue;
      if (ready == 0) return Read::timeout;
      char chunk[4096];
      const ssize_t n = ::read(from_, chunk, sizeof chunk);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return Read::eof;
      buffer_.append(chunk, static_cast<std::size_t>(n));
    }
  }

  // How it ended, once it has: "exit status N", "SIGSEGV", ...
  std::string stop() {
    if (pid_ <= 0) return "";
    if (to_ >= 0) close(to_);
    if (from_ >= 0) close(from_);
    to_ = from_ = -1;
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == 0) {
      kill(-pid_, SIGKILL);
      waitpid(pid_, &status, 0);
    }
    pid_ = -1;
    if (WIFSIGNALED(status)) return std::string("killed by signal ") + std::to_string(WTERMSIG(status));
    return "exit status " + std::to_string(WEXITSTATUS(status));
  }

 private:
  pid_t pid_ = -1;
  int to_ = -1, from_ = -1;
  std::string buffer_;
};


std::string request(const std::string& name, const TrianglePair& pair) {
  Case c;
  c.name = name;
  c.pair = pair;
  return format_case(c) + '\n';
}

}  // namespace

ProcessAnswers run_process_plugin(const ProcessPluginOptions& options, const std::vector<std::string>& names,
                                  const std::vector<TrianglePair>& pairs) {
  // A plug-in that dies makes our next write fail with EPIPE; we handle that, not the signal.
  struct sigaction ignore {}, previous{};
  ignore.sa_handler = SIG_IGN;
  sigaction(SIGPIPE, &ignore, &previous);
  struct Restore {
    struct sigaction* p;
    ~Restore() { sigaction(SIGPIPE, p, nullptr); }
  } restore{&previous};

  ProcessAnswers result;
  result.stopped_at = pairs.size();
  result.overlap.assign(pairs.size(), Overlap::unsupported);
  result.relation.assign(pairs.size(), RelationAnswer{});
  int relation_seen = -1;  // unknown until the first answer
  auto protocol_error = [&](std::size_t i, const std::string& line, const std::string& what) {
    return InputError("process plug-in '" + options.command + "' answered '" + line + "' to case '" +
                              names[i] + "': " + what);
  };

  // A freshly started process also pays its interpreter's start-up before its first answer, which
  // on a loaded machine can exceed a short per-case limit: that answer gets kStartupSeconds more.
  constexpr double kStartupSeconds = 10.0;
  auto child = std::make_unique<Child>(options.command);
  bool fresh = true;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    std::string line;
    Child::Read got = Child::Read::eof;
    const double limit = options.timeout_seconds + (fresh ? kStartupSeconds : 0.0);
    if (child->write_line(request(names[i], pairs[i]))) got = child->read_line(line, limit);
    fresh = false;
    if (got != Child::Read::line) {
      const std::string ended = child->stop();
      if (got == Child::Read::timeout)
        result.faults.push_back({i, Fate::timeout, "no answer within " + format_double(limit) + " s"});
      else
        result.faults.push_back({i, Fate::crash, "the process ended (" + ended + ")"});
      if (options.max_faults && result.faults.size() >= options.max_faults && i + 1 < pairs.size()) {
        result.stopped_at = i + 1;
        break;
      }
      child = std::make_unique<Child>(options.command);
      fresh = true;
      continue;
    }
    const auto w = split_words(line);
    if (w.size() < 2 || w.size() > 3) throw protocol_error(i, line, "expected 'name overlap [relation]'");
    if (w[0] != names[i]) throw protocol_error(i, line, "the answer names another case");
    if (w[1] == "0") result.overlap[i] = Overlap::no;
    else if (w[1] == "1") result.overlap[i] = Overlap::yes;
    else if (w[1] != "unsupported") throw protocol_error(i, line, "overlap must be 0, 1 or unsupported");
    const bool has_relation = w.size() == 3;
    if (relation_seen < 0) relation_seen = has_relation;
    if (has_relation != (relation_seen == 1))
      throw protocol_error(i, line, "every answer must give a relation, or none may");
    if (has_relation) {
      const auto r = parse_relation(w[2]);
      if (!r || *r == Relation::degenerate || *r == Relation::unknown)
        throw protocol_error(i, line, "'" + std::string(w[2]) + "' is not a relation (see 'tritri label --help')");
      result.relation[i] = answer_with(*r);
    }
  }
  result.answers_relation = relation_seen == 1;
  return result;
}

}  // namespace tritri

namespace tritri {
namespace {
// By name: the registry's entries are copied (NAME@float and the like), names are unique.
std::map<std::string, ProcessPluginOptions>& process_plugins() {
  static std::map<std::string, ProcessPluginOptions> plugins;
  return plugins;
}
}  // namespace

const ProcessPluginOptions* find_process_plugin(const std::string& name) {
  const auto& plugins = process_plugins();
  const auto found = plugins.find(name);
  return found == plugins.end() ? nullptr : &found->second;
}

const Algorithm& add_process_algorithm(const std::string& command, const std::string& name,
                                       double timeout_seconds) {
  if (registry().find(name))
    throw InputError("process plug-in name '" + name + "' is already taken (choose one with --exec-name)");
  const Triangle floor{{Vec3<double>(0, 0, 0), Vec3<double>(1, 0, 0), Vec3<double>(0, 1, 0)}};
  const Triangle above{{Vec3<double>(0, 0, 1), Vec3<double>(1, 0, 2), Vec3<double>(0, 1, 3)}};
  const ProcessAnswers probe = run_process_plugin({command, timeout_seconds}, {"probe"}, {{floor, above}});
  if (!probe.faults.empty())
    throw InputError("process plug-in '" + command + "' did not answer a probe case: " +
                             probe.faults.front().detail);
  Algorithm a;
  a.name = name;
  a.citation = "process plug-in: " + command;
  a.summary = "process plug-in (" + command + ")";
  a.accepts_degenerate = false;
  a.answered_elsewhere = probe.answers_relation ? LevelSet{Level::overlap, Level::relation} : LevelSet{Level::overlap};
  a.folder = "exec:" + command;
  const Algorithm& added = add_external_algorithm(std::move(a));
  process_plugins()[name] = {command, timeout_seconds};
  return added;
}

}  // namespace tritri
