#include "harness/run/code_identity.hpp"

#include "cases/util/random.hpp"
#include "cases/util/text.hpp"

#include <link.h>
#include <sys/stat.h>

#include <algorithm>
#include <string>
#include <vector>

namespace tritri {
namespace {

int collect(dl_phdr_info* info, std::size_t, void* data) {
  auto* paths = static_cast<std::vector<std::string>*>(data);
  // The program itself comes first, with an empty name.
  paths->push_back(info->dlpi_name && *info->dlpi_name ? info->dlpi_name : "/proc/self/exe");
  return 0;
}

std::string described(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return path + " ?";
  return path + " " + std::to_string(st.st_size) + " " + std::to_string(st.st_ino) + " " +
         std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec);
}

}  // namespace

std::string loaded_code_identity() {
  std::vector<std::string> paths;
  dl_iterate_phdr(&collect, &paths);
  std::sort(paths.begin(), paths.end());
  std::uint64_t h = kFnvOffset;
  for (const std::string& p : paths) h = fnv1a(described(p) + "\n", h);
  return hex64(h);
}

}  // namespace tritri
