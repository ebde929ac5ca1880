// Where the real meshes come from: CGAL's example data set, which Debian ships in the package
// libcgal-demo as one data.tar.gz. The meshes a scene needs are unpacked once into a cache
// directory; nothing of them is stored in the repository.
#pragma once

#include <string>

namespace tritri::scenes {

// The directory holding CGAL's data/meshes/*.off, unpacked on first use:
//   $TRITRI_MESH_DIR if set (used as is, never written);
//   else $XDG_CACHE_HOME/tritri/cgal-meshes (~/.cache/tritri/cgal-meshes), filled from the
//   data.tar.gz that `dpkg -L libcgal-demo` lists (or /usr/share/doc/libcgal-dev/data.tar.gz).
// The unpacking goes to a temporary directory renamed into place, so an interrupted run leaves
// no half-filled cache. Throws std::runtime_error with one clear message (install libcgal-demo:
// scripts/setup does) when the archive is not there.
std::string cgal_mesh_dir();

}  // namespace tritri::scenes
