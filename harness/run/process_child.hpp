// A process plug-in's process: started through /bin/sh in its own process group, spoken to over
// pipes. Writes are queued and sent while waiting for answers, so that many cases can be in
// flight at once without either side blocking on a full pipe (process_plugin.hpp).
#pragma once

#include <string>
#include <string_view>
#include <sys/types.h>

namespace tritri {

class ProcessChild {
 public:
  // Starts `command` with TRITRI_PROTOCOL=<protocol> added to its environment.
  ProcessChild(const std::string& command, const char* protocol);
  ~ProcessChild() { stop(); }
  ProcessChild(const ProcessChild&) = delete;
  ProcessChild& operator=(const ProcessChild&) = delete;

  // Queues text for its standard input; it is sent while read_line waits.
  void send(std::string_view text) { pending_.append(text); }

  enum class Read { line, eof, timeout };
  // The next line of its standard output, waiting at most `seconds` (sending what is queued
  // meanwhile). A process that has stopped reading gets the rest of its queue dropped.
  Read read_line(std::string& line, double seconds);

  // Ends it (SIGKILL to its group if it is still running) and says how it ended: "exit status N",
  // "killed by signal N".
  std::string stop();

 private:
  bool flush_some();  // false when its input is closed (EPIPE)

  pid_t pid_ = -1;
  int to_ = -1, from_ = -1;
  std::string pending_;   // queued for its input
  std::string buffer_;    // read from its output, not yet returned
};

}  // namespace tritri
