// The instruction sets a lane algorithm (one that decides several pairs per SIMD instruction,
// e.g. algorithms/exact) may use, and the one way to ask every lane algorithm for a narrower one
// than the machine has: the environment variable TRITRI_ISA (scalar, sse2, avx2, avx512), read
// once, when a lane algorithm is first used. `tritri bench --isa NAME` sets it before any
// algorithm runs, so that a user with an older CPU can see the times they would get.
// Unset, unknown, or wider than the machine: the widest the machine runs.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string_view>

namespace tritri {

enum class Isa : std::uint8_t { scalar, sse2, avx2, avx512 };  // narrowest first
inline constexpr Isa kIsas[] = {Isa::scalar, Isa::sse2, Isa::avx2, Isa::avx512};
inline constexpr const char* kIsaVariable = "TRITRI_ISA";

inline std::string_view to_string(Isa isa) {
  constexpr std::string_view kNames[] = {"scalar", "sse2", "avx2", "avx512"};  // in Isa's order
  return kNames[static_cast<std::size_t>(isa)];
}

inline std::optional<Isa> parse_isa(std::string_view name) {
  for (Isa i : kIsas)
    if (to_string(i) == name) return i;
  return std::nullopt;
}

// The widest instruction set this machine runs.
inline Isa machine_isa() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f")) return Isa::avx512;
  if (__builtin_cpu_supports("avx2")) return Isa::avx2;
  return Isa::sse2;
#else
  return Isa::scalar;
#endif
}

// What TRITRI_ISA asks for, capped at the machine's; read once.
inline Isa requested_isa() {
  static const Isa isa = [] {
    const Isa best = machine_isa();
    const char* env = std::getenv(kIsaVariable);
    const std::optional<Isa> asked = env ? parse_isa(env) : std::nullopt;
    return asked && *asked < best ? *asked : best;
  }();
  return isa;
}

}  // namespace tritri
