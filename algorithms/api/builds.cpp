#include "algorithms/api/builds.hpp"

#include <cstdlib>
#include <dlfcn.h>
#include <filesystem>
#include <iostream>
#include <string>

namespace tritri {

std::filesystem::path beside_program(const std::filesystem::path& relative) {
  std::error_code error;
  const auto program = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return relative;
  return (program.parent_path() / relative).lexically_normal();
}

namespace {

constexpr const char* kSuffix = "@v3fma";
constexpr const char* kFlags = "-march=x86-64-v3 -ffp-contract=fast";

// The module may use anything -march=x86-64-v3 allows (AVX2, FMA, BMI1/2, F16C, MOVBE, ...):
// running it on a CPU without them would end in an illegal instruction, not a wrong answer.
bool cpu_runs_x86_64_v3() {
#if defined(__x86_64__) && defined(__clang__)
  __builtin_cpu_init();  // clang 14 knows no "x86-64-v3" level: its defining features, one by one
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi") &&
         __builtin_cpu_supports("bmi2");
#elif defined(__x86_64__)
  __builtin_cpu_init();
  return __builtin_cpu_supports("x86-64-v3");
#else
  return false;
#endif
}

#ifdef TRITRI_V3FMA_MODULE
// TRITRI_V3FMA_MODULE is relative to the running program's directory: the same path leads from
// build/bin to the module in the build tree and from bin/ to it in an installation.
std::filesystem::path module_path() { return beside_program(TRITRI_V3FMA_MODULE); }

// Loads the module and returns its registry, or nullptr with `why` set.
const Registry* load_module(std::string& why) {
  if (const char* setting = std::getenv("TRITRI_V3FMA"); setting && std::string(setting) == "off") {
    why = "TRITRI_V3FMA=off";
    return nullptr;
  }
  if (!cpu_runs_x86_64_v3()) {
    why = "this CPU lacks AVX2/FMA (x86-64-v3)";
    return nullptr;
  }
  const auto path = module_path();
  if (!std::filesystem::exists(path)) {
    why = path.string() + " not found";
    return nullptr;
  }
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    why = dlerror();
    return nullptr;
  }
  auto entry = reinterpret_cast<BuildModuleEntry>(dlsym(handle, kBuildModuleEntry));
  if (!entry) {
    why = path.string() + " does not export " + kBuildModuleEntry;
    return nullptr;
  }
  return entry();
}
#endif

}  // namespace

void add_builds(Registry& registry) {
#ifdef TRITRI_V3FMA_MODULE
  std::string why;
  const Registry* module = load_module(why);
  if (!module) {
    std::cerr << "tritri: the " << kFlags << " build (NAME" << kSuffix << ") is not loaded: " << why << '\n';
    return;
  }
  for (const Algorithm& built : module->all()) {
    Algorithm a = built;
    a.name += kSuffix;
    a.build = kSuffix + 1;
    a.summary += std::string(" [built with ") + kFlags + "]";
    registry.set_current_folder(built.folder);
    registry.add(std::move(a));
  }
#else
  (void)registry;  // the compiler cannot target x86-64-v3: no module was built (CMake said so)
#endif
}

}  // namespace tritri
