// Loading shared-library plug-ins (algorithms/api/tritri/plugin.h) as algorithms.
#pragma once

#include "tritri/algorithm.hpp"

#include <string>

namespace tritri {

// Loads the library, checks what it declares, and adds it to the registry under its own name.
// Throws InputError (cases/util/input_error.hpp) naming the file and the problem: the user's library.
const Algorithm& load_plugin(const std::string& path);

}  // namespace tritri
