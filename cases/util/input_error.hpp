// The one error type for a fault in the user's input: the arguments, and the files, libraries
// and commands they name (unreadable, malformed, unloadable). `tritri` exits 2 on it, with its
// message; any other exception is a bug in tritri and exits 3 (harness/cli/dispatch.cpp). The
// message names what and where: "FILE:LINE: problem", "plug-in 'LIB': problem".
#pragma once

#include <stdexcept>

namespace tritri {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace tritri
