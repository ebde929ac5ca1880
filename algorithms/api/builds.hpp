// Builds: the algorithms tritri compiles from source, compiled a second time with other
// flags into a shared module of their own, and registered beside the baseline build as
// NAME@SUFFIX. There is one: v3fma, `-march=x86-64-v3 -ffp-contract=fast`, the build users ship
// (AVX2, and the compiler free to fuse a*b+c into one rounding).
//
// Why a module rather than more objects in the same binary: the ports are templates and inline
// functions, and the linker keeps one copy of each; two builds of them in one binary would be
// merged into whichever it saw first. The module hides every symbol but its entry point and is
// loaded with RTLD_LOCAL, so each build keeps its own code.
#pragma once

#include "tritri/algorithm.hpp"

#include <filesystem>

namespace tritri {

// The module's one exported function (C linkage): the algorithms compiled into it, in a registry
// of the module's own. The module is never unloaded, so the pointer and every batch entry point
// it holds stay valid.
using BuildModuleEntry = const Registry* (*)();
inline constexpr const char* kBuildModuleEntry = "tritri_build_registry";

// Loads the v3fma module when the CPU can run it and adds its algorithms to `registry`, each
// named NAME@v3fma, in the folder of its baseline build. When it cannot (a CPU without AVX2 and
// FMA, the module missing, TRITRI_V3FMA=off), writes one line on stderr saying why and adds
// nothing: the baseline build is complete without it.
void add_builds(Registry& registry);

// `relative` taken from the running program's directory (/proc/self/exe), so that a path into
// the build tree from build/bin is the same path into an installation from its bin/.
std::filesystem::path beside_program(const std::filesystem::path& relative);

}  // namespace tritri
