// The checks of `tritri bench`, done once: before timing, every algorithm runs over every pool
// in a child process and is scored against the oracle (and its operations counted), minutes on
// the default pools. A run on the same pools with the same code reuses those results.
//
// An entry is keyed by the pools' cache key (pool_cache.hpp), the identity of the code loaded
// into the process (harness/run/code_identity.hpp: tritri, its libraries, the plug-ins), and the
// settings that shape a check (isolation, its stall time, whether operations are counted). Only
// clean results are kept: an entry that crashed or hung is checked again on every run, and a
// process plug-in (whose program tritri cannot identify) is never cached. The file carries its
// key and a checksum; a stale or corrupt one is ignored, with a message, and rewritten.
#pragma once

#include "harness/bench/bench.hpp"

#include <iosfwd>
#include <map>
#include <optional>
#include <string>

namespace tritri::bench {

struct CachedCheck {
  Score score;
  std::optional<OpCounts> ops;
};

class CheckCache {
 public:
  // Disabled (finds nothing, keeps nothing) when the pools were not cached (empty pools_key).
  CheckCache(const PoolCacheOptions& cache, const std::string& pools_key, const Options& options, std::ostream& log);

  const CachedCheck* find(const std::string& entry) const;
  void put(const std::string& entry, const CachedCheck& check);
  // Writes the file (atomically) when anything was added; says so on `log`.
  void save(std::ostream& log) const;
  std::size_t hits() const { return hits_; }

 private:
  std::string path_, key_;
  std::map<std::string, CachedCheck> checks_;
  bool changed_ = false;
  mutable std::size_t hits_ = 0;
};

}  // namespace tritri::bench
