#include "harness/bench/check_cache.hpp"

#include "cases/util/atomic_file.hpp"
#include "cases/util/random.hpp"
#include "cases/util/text.hpp"
#include "harness/run/code_identity.hpp"

#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace tritri::bench {
namespace {

constexpr std::string_view kMagic = "tritri-check-cache/1";

std::string record(const std::string& name, const CachedCheck& c) {
  std::string ops = "-";
  if (c.ops)
    ops = std::to_string(c.ops->add) + "," + std::to_string(c.ops->mul) + "," + std::to_string(c.ops->div) + "," +
          std::to_string(c.ops->cmp) + "," + std::to_string(c.ops->sqrt);
  return name + "\t" + std::to_string(c.score.wrong) + "\t" + std::to_string(c.score.unsupported) + "\t" + ops + "\n";
}

std::uint64_t number(std::string_view text) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos)
    throw std::runtime_error("malformed number '" + std::string(text) + "'");
  return std::stoull(std::string(text));
}

std::pair<std::string, CachedCheck> parse_record(std::string_view line) {
  const auto f = split_fields(line, '\t');
  if (f.size() != 4) throw std::runtime_error("malformed record");
  CachedCheck c;
  c.score.wrong = number(f[1]);
  c.score.unsupported = number(f[2]);
  if (f[3] != "-") {
    const auto o = split_fields(f[3], ',');
    if (o.size() != 5) throw std::runtime_error("malformed operation counts");
    c.ops = OpCounts{number(o[0]), number(o[1]), number(o[2]), number(o[3]), number(o[4])};
  }
  return {std::string(f[0]), c};
}

// The whole file: magic, key, records, then the checksum of everything before it. Throws with
// the reason it cannot be used.
std::map<std::string, CachedCheck> read_checks(const std::string& path, const std::string& key) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string data = buffer.str();
  const std::size_t last = data.rfind("checksum ");
  if (last == std::string::npos || data.compare(last + 9, 16, hex64(hash_bytes(data.data(), last))) != 0)
    throw std::runtime_error("checksum mismatch (corrupt or truncated)");
  std::istringstream lines(data.substr(0, last));
  std::string line;
  if (!std::getline(lines, line) || line != kMagic) throw std::runtime_error("not a check cache file");
  if (!std::getline(lines, line) || line != "key " + key) throw std::runtime_error("stale (other code or settings)");
  std::map<std::string, CachedCheck> checks;
  while (std::getline(lines, line)) checks.insert(parse_record(line));
  return checks;
}

}  // namespace

CheckCache::CheckCache(const PoolCacheOptions& cache, const std::string& pools_key, const Options& options,
                       std::ostream& log) {
  if (pools_key.empty()) return;
  const std::string directory = cache.directory.empty() ? default_cache_directory() : cache.directory;
  const std::string settings = pools_key + "code " + loaded_code_identity() + "\nisolation " +
                               std::to_string(options.isolation.enabled) + " " +
                               std::to_string(options.isolation.stall_seconds) + "\noperations " +
                               std::to_string(options.count_operations) + "\n";
  key_ = hex64(fnv1a(settings));
  path_ = directory + "/checks-" + hex64(fnv1a(pools_key)) + ".txt";
  try {
    checks_ = read_checks(path_, key_);
  } catch (const std::exception& e) {
    log << "checks: cache file " << path_ << " not used: " << e.what() << "; checking again\n";
  }
}

const CachedCheck* CheckCache::find(const std::string& entry) const {
  const auto it = checks_.find(entry);
  if (it == checks_.end()) return nullptr;
  ++hits_;
  return &it->second;
}

void CheckCache::put(const std::string& entry, const CachedCheck& check) {
  if (path_.empty()) return;
  checks_[entry] = check;
  changed_ = true;
}

void CheckCache::save(std::ostream& log) const {
  if (path_.empty()) return;
  if (hits_) log << "checks: " << hits_ << " read from the cache, " << path_ << " (same pools, same code)\n";
  if (!changed_) return;
  std::string data = std::string(kMagic) + "\nkey " + key_ + "\n";
  for (const auto& [name, check] : checks_) data += record(name, check);
  data += "checksum " + hex64(hash_bytes(data.data(), data.size())) + "\n";
  try {
    std::filesystem::create_directories(std::filesystem::path(path_).parent_path());
    write_file_atomically(path_, [&](std::ostream& out) { out << data; });
  } catch (const std::exception& e) {
    log << "checks: could not write " << path_ << " (" << e.what() << "); continuing without\n";
  }
}

}  // namespace tritri::bench
