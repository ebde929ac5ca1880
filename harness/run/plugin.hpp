// Loading shared-library plug-ins (algorithms/api/tritri/plugin.h) as algorithms.
#pragma once

#include "tritri/algorithm.hpp"

#include <string>

namespace tritri {

// Loads the library, checks what it declares, and adds it to the registry under its own name.
// Throws std::runtime_error naming the file and the problem.
const Algorithm& load_plugin(const std::string& path);

}  // namespace tritri
