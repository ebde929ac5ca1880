#include "harness/bench/pool_cache.hpp"

#include "cases/util/atomic_file.hpp"
#include "harness/bench/workloads/family.hpp"

#include <CGAL/version.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <stdexcept>
#include <type_traits>

namespace tritri::bench {
namespace {

static_assert(std::is_trivially_copyable_v<Truth>, "labels are stored as their bytes");

// Pairs as their 18 coordinates (Eigen's vectors are not trivially copyable to the type system).
std::vector<double> coordinates(const std::vector<TrianglePair>& pairs) {
  std::vector<double> out;
  out.reserve(18 * pairs.size());
  for (const TrianglePair& p : pairs)
    for (const auto* t : {&p.t1, &p.t2})
      for (const auto& v : t->v) out.insert(out.end(), {v.x(), v.y(), v.z()});
  return out;
}

std::vector<TrianglePair> pairs_of(const std::vector<double>& xs) {
  if (xs.size() % 18 != 0) throw std::runtime_error("malformed pairs");
  std::vector<TrianglePair> out(xs.size() / 18);
  std::size_t k = 0;
  for (TrianglePair& p : out)
    for (auto* t : {&p.t1, &p.t2})
      for (auto& v : t->v) {
        v = {xs[k], xs[k + 1], xs[k + 2]};
        k += 3;
      }
  return out;
}

constexpr char kMagic[] = "tritri-pool-cache/3\n";  // 3: a pool's query level

// ---- a flat byte encoding: lengths as 64-bit words, in this machine's byte order (the cache
// is this machine's) ----
void put_u64(std::string& out, std::uint64_t x) { out.append(reinterpret_cast<const char*>(&x), sizeof x); }
void put_bytes(std::string& out, const void* data, std::size_t size) {
  put_u64(out, size);
  out.append(static_cast<const char*>(data), size);
}
void put_string(std::string& out, const std::string& s) { put_bytes(out, s.data(), s.size()); }

struct Reader {
  std::string_view data;
  std::size_t at = 0;
  std::uint64_t u64() {
    if (data.size() - at < 8) throw std::runtime_error("truncated");
    std::uint64_t x;
    std::memcpy(&x, data.data() + at, 8);
    at += 8;
    return x;
  }
  std::string_view bytes() {
    const std::uint64_t n = u64();
    if (data.size() - at < n) throw std::runtime_error("truncated");
    std::string_view v(data.data() + at, n);
    at += n;
    return v;
  }
  template <class T>
  std::vector<T> array() {
    const auto v = bytes();
    if (v.size() % sizeof(T) != 0) throw std::runtime_error("malformed array");
    std::vector<T> out(v.size() / sizeof(T));
    std::memcpy(static_cast<void*>(out.data()), v.data(), v.size());
    return out;
  }
};

std::string encode(const Planned& planned) {
  std::string out;
  put_u64(out, planned.pools.size());
  for (const PlannedPool& p : planned.pools) {
    put_string(out, p.pool.workload);
    put_string(out, p.pool.value);
    put_u64(out, p.pool.seed);
    const std::uint64_t query = p.pool.query ? 1u + static_cast<unsigned>(*p.pool.query) : 0u;
    put_u64(out, (p.levels ? 1u : 0u) | (p.stages ? 2u : 0u) | query << 2);
    const auto xs = coordinates(p.pool.pairs);
    put_bytes(out, xs.data(), xs.size() * sizeof(double));
    put_bytes(out, p.pool.truth.data(), p.pool.truth.size() * sizeof(Truth));
  }
  put_u64(out, planned.context.size());
  for (const auto& [k, v] : planned.context) {
    put_string(out, k);
    put_string(out, v);
  }
  return out;
}

Planned decode(std::string_view payload) {
  Reader r{payload};
  Planned planned;
  const std::uint64_t pools = r.u64();
  for (std::uint64_t i = 0; i < pools; ++i) {
    PlannedPool p;
    p.pool.workload = std::string(r.bytes());
    p.pool.value = std::string(r.bytes());
    p.pool.seed = r.u64();
    const std::uint64_t flags = r.u64();
    p.levels = flags & 1u;
    p.stages = flags & 2u;
    if (const std::uint64_t query = flags >> 2; query > 0) {
      if (query > 1u + static_cast<unsigned>(Level::segment)) throw std::runtime_error("unknown query level");
      p.pool.query = static_cast<Level>(query - 1u);
    }
    p.pool.pairs = pairs_of(r.array<double>());
    p.pool.truth = r.array<Truth>();
    if (p.pool.pairs.size() != p.pool.truth.size()) throw std::runtime_error("pairs and labels differ in number");
    planned.pools.push_back(std::move(p));
  }
  const std::uint64_t keys = r.u64();
  for (std::uint64_t i = 0; i < keys; ++i) {
    std::string k(r.bytes());
    planned.context.emplace_back(std::move(k), std::string(r.bytes()));
  }
  if (r.at != payload.size()) throw std::runtime_error("trailing bytes");
  return planned;
}

// The entry: magic, key, payload, checksum of everything before it. Throws with the reason the
// entry cannot be used.
Planned read_entry(const std::string& path, const std::string& key) {
  // One read of the whole entry: hundreds of megabytes with the default family pools.
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw std::runtime_error("no entry");
  std::string data(static_cast<std::size_t>(in.tellg()), '\0');
  in.seekg(0);
  if (!in.read(data.data(), static_cast<std::streamsize>(data.size()))) throw std::runtime_error("truncated");
  const std::size_t magic = sizeof kMagic - 1;
  if (data.size() < magic + 8 || data.compare(0, magic, kMagic) != 0) throw std::runtime_error("not a pool cache entry");
  std::uint64_t stored;
  std::memcpy(&stored, data.data() + data.size() - 8, 8);
  if (hash_bytes(data.data(), data.size() - 8) != stored) throw std::runtime_error("checksum mismatch (corrupt)");
  Reader r{std::string_view(data).substr(magic, data.size() - magic - 8)};
  if (r.bytes() != key) throw std::runtime_error("stale (made for other settings)");
  return decode(r.bytes());
}

void write_entry(const std::string& path, const std::string& key, const Planned& planned) {
  std::string data = kMagic;
  put_string(data, key);
  put_string(data, encode(planned));
  put_u64(data, hash_bytes(data.data(), data.size()));
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  write_file_atomically(path, [&](std::ostream& out) { out.write(data.data(), static_cast<std::streamsize>(data.size())); });
}

}  // namespace

std::string default_cache_directory() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/tritri";
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/tritri";
  return "";
}

std::string pool_cache_key(const std::vector<Selected>& selected, const WorkloadInput& input) {
  std::string key = "generator " + std::to_string(kPoolGeneratorVersion) + "\noracle CGAL " CGAL_VERSION_STR "\n";
  key += "seed " + std::to_string(input.pool.seed) + "\nsize " + std::to_string(input.pool.size) + "\nquick " +
         std::to_string(input.quick) + "\n";
  key += "family cases " + (input.corpus.files.empty() ? generator_source(input) : "files " + input.corpus.hash) + "\n";
  for (const Selected& s : selected) {
    key += "workload " + s.workload->kind() + " from " + s.workload->pools_from() +
           (s.workload->times_levels_and_stages() ? " levels+stages"
            : s.workload->times_stages()       ? " stages"
                                               : " levels") +
           ":";
    for (const auto& v : s.values) key += " " + v;
    key += "\n";
    if (const std::string id = s.workload->cache_identity(input); !id.empty()) key += "reads " + id + "\n";
  }
  return key;
}

Planned build_pools_cached(const std::vector<Selected>& selected, const WorkloadInput& input,
                           const PoolCacheOptions& options, std::ostream& log) {
  const std::string directory = options.directory.empty() ? default_cache_directory() : options.directory;
  if (!options.enabled || directory.empty()) return build_pools(selected, input);
  const std::string key = pool_cache_key(selected, input);
  const std::string path = directory + "/pools-" + hex64(fnv1a(key)) + ".bin";
  try {
    Planned planned = read_entry(path, key);
    planned.cache_key = key;
    log << "pools: read from the cache, " << path << " (--no-cache to rebuild)\n";
    return planned;
  } catch (const std::exception& e) {
    if (std::string(e.what()) != "no entry") log << "pools: cache entry " << path << " not used: " << e.what() << "; rebuilding\n";
  }
  Planned planned = build_pools(selected, input);
  planned.cache_key = key;
  try {
    write_entry(path, key, planned);
    log << "pools: kept in the cache, " << path << '\n';
  } catch (const std::exception& e) {
    log << "pools: could not write the cache entry (" << e.what() << "); continuing without\n";
  }
  return planned;
}

}  // namespace tritri::bench
