// The one random source of tritri: corpus, bench pools and tests all draw from it.
//
// The standard library's distributions are implementation-defined (libstdc++ and libc++ turn the
// same engine output into different numbers), so anything drawn through them would change from
// one toolchain to the next. Everything here is spelled out, so a seed names the same bytes
// everywhere, provided callers never draw twice in one expression: the order in which C++
// evaluates function arguments (and the operands of +) is unspecified, so f(rng.next(),
// rng.next()) may differ between compilers. Draw into named variables, one per declarator.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

namespace tritri {

// 64-bit FNV-1a over bytes: the hash behind every derived seed and every content hash.
inline constexpr std::uint64_t kFnvOffset = 0xcbf29ce484222325ull;
inline std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t h = kFnvOffset) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 0x100000001b3ull;
  return h;
}
inline std::uint64_t fnv1a(std::string_view text, std::uint64_t h = kFnvOffset) {
  return fnv1a(text.data(), text.size(), h);
}

// A content hash for large byte blocks (cache entries, case files): FNV-1a's mixing a 64-bit word
// at a time, about eight times faster than fnv1a on hundreds of megabytes; the tail bytes and the
// length go in last, so blocks that differ only in length differ.
inline std::uint64_t hash_bytes(const void* data, std::size_t size, std::uint64_t h = kFnvOffset);

// hash_bytes' word loop alone, over the whole 8-byte words of `data` (size rounded down to a
// multiple of 8), so that a file can be hashed a block at a time (cases/corpus_identity.cpp):
// hash_words over every block but the last, then hash_tail with the total size.
inline std::uint64_t hash_words(const void* data, std::size_t size, std::uint64_t h) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i + 8 <= size; i += 8) {
    std::uint64_t word;
    __builtin_memcpy(&word, p + i, 8);
    h = (h ^ word) * 0x100000001b3ull;
    h ^= h >> 29;
  }
  return h;
}
// The last block (of any size) of `total` bytes in all.
inline std::uint64_t hash_tail(const void* data, std::size_t size, std::uint64_t h, std::uint64_t total) {
  const std::size_t whole = size - size % 8;
  return fnv1a(static_cast<const unsigned char*>(data) + whole, size - whole, hash_words(data, whole, h) ^ total);
}
inline std::uint64_t hash_bytes(const void* data, std::size_t size, std::uint64_t h) {
  return hash_tail(data, size, h, size);
}

// SplitMix64's output function: a bijection that scatters nearby inputs.
inline std::uint64_t splitmix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}

  // SplitMix64: every seed, including 0, gives a full-period stream.
  std::uint64_t next() {
    const std::uint64_t x = state_;
    state_ += 0x9e3779b97f4a7c15ull;
    return splitmix(x);
  }

  // Uniform in [lo, hi], both included; rejection keeps it unbiased.
  std::int64_t integer(std::int64_t lo, std::int64_t hi) {
    const std::uint64_t span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo) + 1;
    if (span == 0) return static_cast<std::int64_t>(next());  // the whole 64-bit range
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % span;
    std::uint64_t x;
    do x = next();
    while (x >= limit);
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(lo) + x % span);
  }
  int between(int lo, int hi) { return static_cast<int>(integer(lo, hi)); }

  int nonzero_between(int lo, int hi) {
    for (;;)
      if (int x = between(lo, hi); x != 0) return x;
  }

  int sign() { return (next() >> 63) ? 1 : -1; }
  bool coin() { return (next() >> 63) != 0; }

  // Uniform on the 2^53 doubles k·2^-53 in [0, 1).
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }

  // Fisher–Yates, drawing one index per step.
  template <class T>
  void shuffle(std::vector<T>& v) {
    for (std::size_t i = v.size(); i > 1; --i) {
      const auto j = static_cast<std::size_t>(integer(0, static_cast<std::int64_t>(i) - 1));
      std::swap(v[i - 1], v[j]);
    }
  }

 private:
  std::uint64_t state_;
};

// An independent seed per (seed, tag, index): streams that can be drawn in any order and on any
// number of threads and still come out the same.
inline std::uint64_t stream_seed(std::uint64_t seed, std::string_view tag, std::uint64_t index = 0) {
  Rng mix(seed ^ (fnv1a(tag) * 0x9e3779b97f4a7c15ull) ^ (index * 0xd1b54a32d192ed03ull));
  mix.next();
  return mix.next();
}

}  // namespace tritri
