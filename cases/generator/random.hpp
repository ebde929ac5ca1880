// A small deterministic random source for the corpus.
//
// The standard library's distributions are implementation-defined (libstdc++ and libc++ turn the
// same engine output into different numbers), so a corpus drawn through them would change from
// one toolchain to the next. Everything here is spelled out, so a seed names the same bytes
// everywhere, provided callers never draw twice in one expression: the order in which C++
// evaluates function arguments (and the operands of +) is unspecified, so f(rng.next(),
// rng.next()) may differ between compilers. Draw into named variables, one per declarator.
#pragma once

#include <cstdint>
#include <string_view>

namespace tritri::corpus {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}

  // SplitMix64: every seed, including 0, gives a full-period stream.
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }

  // Uniform in [lo, hi], both included; rejection keeps it unbiased.
  int between(int lo, int hi) {
    const std::uint64_t span = static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) - lo) + 1;
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % span;
    std::uint64_t x;
    do x = next();
    while (x >= limit);
    return static_cast<int>(lo + static_cast<std::int64_t>(x % span));
  }

  int nonzero_between(int lo, int hi) {
    for (;;)
      if (int x = between(lo, hi); x != 0) return x;
  }

  int sign() { return (next() >> 63) ? 1 : -1; }

  // Uniform on the 2^53 doubles k·2^-53 in [0, 1).
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

 private:
  std::uint64_t state_;
};

// An independent stream per (seed, family, base case), so cases can be generated in any order
// and on any number of threads and still come out the same.
inline std::uint64_t stream_seed(std::uint64_t seed, std::string_view family, std::uint64_t index) {
  std::uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a over the family name
  for (unsigned char c : family) h = (h ^ c) * 0x100000001b3ull;
  Rng mix(seed ^ (h * 0x9e3779b97f4a7c15ull) ^ (index * 0xd1b54a32d192ed03ull));
  mix.next();
  return mix.next();
}

}  // namespace tritri::corpus
