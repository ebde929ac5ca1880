// Writing result files so that an interrupted run never leaves a half-written one behind.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>

namespace tritri {

// Writes through `fill` into a temporary file beside `path`, then renames it over `path`.
// Throws InputError (cases/util/input_error.hpp) naming the path if it cannot be written.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& fill);

}  // namespace tritri
