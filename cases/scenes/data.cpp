#include "cases/scenes/data.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace tritri::scenes {
namespace fs = std::filesystem;
namespace {

constexpr const char* kDebianArchive = "/usr/share/doc/libcgal-dev/data.tar.gz";

// The archive libcgal-demo installs, as its package lists it (the path has moved between
// Debian releases), or the usual place.
std::string find_archive() {
  if (FILE* p = popen("dpkg -L libcgal-demo 2>/dev/null", "r")) {
    char line[4096];
    std::string found;
    while (std::fgets(line, sizeof line, p)) {
      std::string s(line);
      while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
      if (s.size() >= 11 && s.compare(s.size() - 11, 11, "data.tar.gz") == 0 && found.empty()) found = s;
    }
    pclose(p);
    if (!found.empty() && fs::exists(found)) return found;
  }
  if (fs::exists(kDebianArchive)) return kDebianArchive;
  return {};
}

fs::path cache_root() {
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return fs::path(x) / "tritri";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".cache" / "tritri";
  return fs::temp_directory_path() / "tritri-cache";
}

std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

std::string cgal_mesh_dir() {
  if (const char* d = std::getenv("TRITRI_MESH_DIR"); d && *d) return d;
  const fs::path dir = cache_root() / "cgal-meshes";
  if (fs::exists(dir / "meshes" / "knot1.off")) return (dir / "meshes").string();
  const std::string archive = find_archive();
  if (archive.empty())
    throw std::runtime_error("CGAL's example meshes are not installed: the scenes on real meshes need the "
                             "Debian package libcgal-demo (./scripts/setup installs it), or TRITRI_MESH_DIR "
                             "set to a directory of its data/meshes");
  fs::create_directories(cache_root());
  const fs::path tmp = cache_root() / ("cgal-meshes.partial." + std::to_string(getpid()));
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  // Only data/meshes: the archive holds far more (point sets, images) than the scenes read.
  const std::string cmd = "tar -xzf " + quoted(archive) + " -C " + quoted(tmp.string()) +
                          " --wildcards 'data/meshes/*' 2>&1";
  if (std::system(cmd.c_str()) != 0 || !fs::exists(tmp / "data" / "meshes" / "knot1.off")) {
    fs::remove_all(tmp);
    throw std::runtime_error("could not unpack data/meshes from " + archive + " into " + dir.string());
  }
  fs::rename(tmp / "data", tmp / "ready");
  std::error_code ec;
  fs::rename(tmp / "ready", dir, ec);  // another process may have won the race: its copy is as good
  fs::remove_all(tmp);
  if (!fs::exists(dir / "meshes" / "knot1.off")) throw std::runtime_error("could not fill the mesh cache " + dir.string());
  return (dir / "meshes").string();
}

}  // namespace tritri::scenes
