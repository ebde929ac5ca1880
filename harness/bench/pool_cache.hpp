// The pools of `tritri bench`, built once: labelled pools are kept under a cache directory and
// read back on the next run with the same settings, so a second run starts timing in seconds
// instead of minutes (drawing and labelling 65,536-pair pools by the exact oracle is most of a
// bench's set-up).
//
// An entry is keyed by everything its pools depend on: the workloads and values asked for, the
// seed, the pool size, --quick, the cases the family workload draws from (the content hashes of
// their files, cases/corpus_identity.hpp), kPoolGeneratorVersion and the oracle (CGAL's version). The key's full
// text is stored in the entry and compared on load, and the payload carries a checksum: an entry
// that is stale, truncated or corrupt is rebuilt, with a message, and never trusted. Entries are
// written atomically (cases/util/atomic_file.hpp), so an interrupted run leaves none half-written.
#pragma once

#include "harness/bench/workload.hpp"

#include <iosfwd>
#include <string>

namespace tritri::bench {

// Bump when anything that shapes the pools changes without changing the key's other parts: a
// workload's drawing, scrambling, shuffling, the generator's constructions.
inline constexpr int kPoolGeneratorVersion = 2;

struct PoolCacheOptions {
  bool enabled = true;
  std::string directory;  // empty: default_cache_directory()
};

// $XDG_CACHE_HOME/tritri, else $HOME/.cache/tritri, else "" (no cache).
std::string default_cache_directory();

// The text every entry is keyed by (see above).
std::string pool_cache_key(const std::vector<Selected>& selected, const WorkloadInput& input);

// build_pools(), through the cache: reads a valid entry, else builds and writes one. Says on `log`
// which it did (and why an entry was not used).
Planned build_pools_cached(const std::vector<Selected>& selected, const WorkloadInput& input,
                           const PoolCacheOptions& options, std::ostream& log);

}  // namespace tritri::bench
