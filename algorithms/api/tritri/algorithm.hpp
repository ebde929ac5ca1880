// What an algorithm declares about itself (Declaration, Algorithm: its semantics and its entry
// points) and the Registry that holds every algorithm a run can choose from.
#pragma once

#include "tritri/entry_points.hpp"
#include "tritri/stages.hpp"

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tritri {

// closed: touching (a shared boundary point) counts as intersecting. open: it does not.
enum class Boundary : std::uint8_t { closed, open };

struct Tolerance {
  double value = 0.0;    // 0 with an empty quantity: no tolerance, every comparison is exact-zero
  std::string quantity;  // what it is compared with, e.g. "|d|, unnormalised plane distance"
  bool relative = false;

  bool none() const { return quantity.empty(); }
};

// Where an algorithm's batches went, as named counts (e.g. the exact test: pairs left undecided by
// its SIMD filter, pairs decided by its exact engine). `tritri bench` resets them, runs each
// level once over each pool on the calling thread, untimed, and records what `read` returns.
using CounterList = std::vector<std::pair<std::string, std::uint64_t>>;
struct PathCounters {
  void (*reset)() = nullptr;
  CounterList (*read)() = nullptr;
  explicit operator bool() const { return reset && read; }
};

// What an algorithm says about itself, for registering it in one expression:
//   Algorithm a({.name = "moller97", .citation = kCitation, .summary = "...", .tolerance = snap});
struct Declaration {
  std::string name;
  std::string citation;
  std::string summary;
  Boundary boundary = Boundary::closed;
  Tolerance tolerance = {};
  bool accepts_degenerate = false;
};

struct Algorithm;
// One variant of a paper's entry: the paper's declaration under the variant's name and summary.
Algorithm variant(Declaration paper, std::string name, std::string summary);

// Its entry points (EntryPoints: batch<L>(), one_pair<L>(), ...) are set by add_level
// (tritri/add_level.hpp).
struct Algorithm : EntryPoints {
  Algorithm() = default;
  explicit Algorithm(Declaration d)
      : name(std::move(d.name)),
        citation(std::move(d.citation)),
        summary(std::move(d.summary)),
        boundary(d.boundary),
        tolerance(std::move(d.tolerance)),
        accepts_degenerate(d.accepts_degenerate) {}

  std::string name;      // short, unique, used on the command line: "moller97"
  std::string citation;  // full reference
  std::string summary;   // one line: what this entry is (which variant, what it changes)
  Boundary boundary = Boundary::closed;
  Tolerance tolerance;
  bool accepts_degenerate = false;  // zero-area triangles; if false the harness never passes one

  // Levels it answers through no entry point here: the harness reaches such an algorithm by a
  // means of its own (harness/run/runner.hpp), and checks it but cannot time it.
  LevelSet answered_elsewhere;
  // For an algorithm that runs as a process (a library in another language, spoken to over the
  // protocol of harness/run/process_plugin.hpp; it answers its levels elsewhere): the command
  // that starts it, through /bin/sh, with "{peers}" where the directory of the process peers'
  // scripts goes, e.g. "node {peers}/three-mesh-bvh/three_mesh_bvh.mjs". process_command()
  // resolves it. Empty for every other algorithm.
  std::string process;

  // Stages timed on their own by `tritri bench` (see StageEntry). Optional.
  std::vector<StageEntry> stages;
  // Counts of the paths its batches took (see PathCounters). Optional.
  PathCounters counters;

  std::string folder;  // filled in by the registry: the algorithm's folder under algorithms/
  // "" for the project's build; the build's name ("v3fma") for an entry of a second build of the
  // same code (algorithms/api/builds.hpp). A second build doubles a run's time, so its entries
  // run when named (--algo NAME@v3fma), not by default.
  std::string build;

  // It answers `level` (through a batch entry point on double, or elsewhere).
  bool answers(Level level) const { return has_batch(level) || answered_elsewhere.contains(level); }
  // It can be timed: every level it answers has a batch entry point here.
  bool timeable() const { return answered_elsewhere.empty(); }
  std::string levels() const;  // "overlap,relation"

  // The same algorithm answering through its instantiation on `s` in place of double, named
  // NAME@float (or @counted), with no stages; nullopt when it has no such instantiation.
  std::optional<Algorithm> on_scalar(Scalar s) const;
};

class Registry {
 public:
  // Called from each algorithm folder's registration function.
  void add(Algorithm algorithm);

  // A deque: pointers to entries stay valid when plug-ins are added later.
  const std::deque<Algorithm>& all() const { return algorithms_; }
  const Algorithm* find(std::string_view name) const;

  // Used by the generated registration code: the folder the next add() calls come from.
  void set_current_folder(std::string folder) { current_folder_ = std::move(folder); }

 private:
  std::deque<Algorithm> algorithms_;
  std::string current_folder_;
};

// Every built-in algorithm, registered once on first use, and any plug-in added since.
const Registry& registry();

// An algorithm that runs as a process (a process peer: algorithms/README.md): the declaration,
// answering the overlap level elsewhere, started by `command` (Algorithm::process).
Algorithm process_peer(Declaration declaration, std::string command);

// Algorithm::process with {peers} replaced by the directory of the process peers' scripts,
// TRITRI_PEERS_DIR relative to the running program's directory (the same in the build tree and in
// an installation), quoted for /bin/sh.
std::string process_command(const Algorithm& algorithm);

// Adds an algorithm from outside the build (a loaded plug-in). Keeps the folder it was given.
const Algorithm& add_external_algorithm(Algorithm algorithm);

}  // namespace tritri
