// The provenance written into the JSON's context: what was built, from which source, and how the
// run was made, so that two result files can be told apart.
#include "harness/bench/report.hpp"

#include "tritri/isa.hpp"

#include <cstdio>
#include <fstream>

#if __has_include(<fcl/config.h>)
#include <fcl/config.h>
#endif

#ifndef TRITRI_BUILD_FLAGS
#define TRITRI_BUILD_FLAGS "unknown"
#endif
#ifndef TRITRI_BUILD_TYPE
#define TRITRI_BUILD_TYPE "unknown"
#endif
#ifndef TRITRI_SOURCE_DIR
#define TRITRI_SOURCE_DIR "."
#endif

namespace tritri::bench {
namespace {

std::string shell_output(const std::string& command) {
  std::string out;
  if (FILE* p = popen(command.c_str(), "r")) {
    char buf[256];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

std::string git_dirty(const std::string& dir) {
  return shell_output("git -C '" + dir + "' status --porcelain --untracked-files=no 2>/dev/null").empty() ? "false"
                                                                                                        : "true";
}

std::string compiler() {
#if defined(__clang__)
  return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("gcc ") + __VERSION__;
#else
  return "unknown";
#endif
}

}  // namespace

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      const std::size_t at = line.find_first_not_of(' ', line.find(':') + 1);
      return at == std::string::npos ? "unknown" : line.substr(at);
    }
  return "unknown";
}

std::vector<std::pair<std::string, std::string>> build_context() {
  std::vector<std::pair<std::string, std::string>> c;
  const std::string dir = TRITRI_SOURCE_DIR;
  const std::string sha = shell_output("git -C '" + dir + "' rev-parse HEAD 2>/dev/null");
  c.emplace_back("git_sha", sha.empty() ? "unknown" : sha);
  c.emplace_back("git_dirty", sha.empty() ? "unknown" : git_dirty(dir));
  c.emplace_back("compiler", compiler());
  c.emplace_back("build_type", TRITRI_BUILD_TYPE);
  c.emplace_back("compiler_flags", TRITRI_BUILD_FLAGS);
  c.emplace_back("fp_contract", std::string(TRITRI_BUILD_FLAGS).find("-ffp-contract=off") != std::string::npos
                                    ? "off"
                                    : "compiler default");
  c.emplace_back("cgal_version", oracle_description());
#ifdef FCL_VERSION
  c.emplace_back("fcl_version", FCL_VERSION);
#else
  c.emplace_back("fcl_version", "not found");
#endif
  c.emplace_back("eigen_version", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) +
                                      "." + std::to_string(EIGEN_MINOR_VERSION));
  c.emplace_back("google_benchmark", "1.7.1 (Debian libbenchmark-dev, find_package(benchmark))");
  return c;
}

RunContext run_context(const Options& options, const Planned& planned, const std::string& corpus_hash) {
  auto c = build_context();
  c.emplace_back("corpus_hash", corpus_hash);
  c.emplace_back("seed", std::to_string(options.seed));
  c.emplace_back("pool_size", std::to_string(options.pool_size));
  c.emplace_back("oracle", oracle_description());
  c.emplace_back("repetitions", std::to_string(options.repetitions));
  c.emplace_back("random_interleaving", options.interleave ? "true" : "false");
  c.emplace_back("timing", "CPU time per pair: one iteration is one in-order pass over the pool, one pair per "
                           "out-of-line call (mode call) or in batches (mode batch)");
  c.emplace_back("reference", options.reference);
  std::string modes;
  for (Mode m : options.modes) modes += (modes.empty() ? "" : ",") + std::string(to_string(m));
  c.emplace_back("modes", modes);
  c.emplace_back("cpu_model", cpu_model());
  c.emplace_back("isa", std::string(to_string(requested_isa())));
  c.emplace_back("isa_machine", std::string(to_string(machine_isa())));
  c.insert(c.end(), planned.context.begin(), planned.context.end());
  for (const auto& planned_pool : planned.pools) {
    const Pool& p = planned_pool.pool;
    c.emplace_back("pool " + p.name(), "size=" + std::to_string(p.size()) + " intersecting=" +
                                           std::to_string(p.intersecting()) + " " + p.stage_mix_text());
  }
  return c;
}

}  // namespace tritri::bench
