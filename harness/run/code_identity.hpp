// Which code this process runs: every object loaded into it (the program, its shared libraries,
// the plug-ins dlopen'ed so far) named by path, size, inode and modification time. Rebuilding
// tritri, upgrading a library or replacing a plug-in changes it, so a result computed by this
// code (an algorithm's answers on a pool) can be kept and reused only under the same identity.
#pragma once

#include <string>

namespace tritri {

// 16 hex digits. Objects that cannot be looked at are named by path alone.
std::string loaded_code_identity();

}  // namespace tritri
