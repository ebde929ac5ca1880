// The instruction sets a lane algorithm (one that decides several pairs per SIMD instruction:
// algorithms/exact, algorithms/lanes) may use, and the one way to ask every lane algorithm for a
// narrower one than the machine has: the environment variable TRITRI_ISA (scalar, sse2, avx2,
// avx512 on x86-64; scalar, neon on aarch64), read once, when a lane algorithm is first used.
// `tritri bench --isa NAME` sets it before any algorithm runs, so that a user with an older CPU
// can see the times they would get. Unset: the widest the machine runs; a set the machine lacks:
// said on stderr, and the widest it runs; an unknown name: said, and exit status 2 (bad input).
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string_view>

namespace tritri {

// Ordered by width within an architecture (x86-64: scalar < sse2 < avx2 < avx512; aarch64:
// scalar < neon); the order of the lane layer's per-ISA tables (algorithms/lanes/isa.hpp).
enum class Isa : std::uint8_t { scalar, sse2, avx2, avx512, neon };
inline constexpr std::array<Isa, 5> kIsas = {Isa::scalar, Isa::sse2, Isa::avx2, Isa::avx512, Isa::neon};
inline constexpr const char* kIsaVariable = "TRITRI_ISA";

constexpr std::string_view to_string(Isa isa) {
  constexpr std::array<std::string_view, 5> kNames = {"scalar", "sse2", "avx2", "avx512", "neon"};
  return kNames[static_cast<std::size_t>(isa)];
}

inline std::optional<Isa> parse_isa(std::string_view name) {
  for (Isa i : kIsas)
    if (to_string(i) == name) return i;
  return std::nullopt;
}

// The widest instruction set this machine runs (x86-64: __builtin_cpu_supports, which also
// checks that the OS saves the wider registers).
inline Isa machine_isa() {
#if defined(__x86_64__) || defined(__i386__)
  static const Isa isa = [] {
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx512f")) return Isa::avx512;
    if (__builtin_cpu_supports("avx2")) return Isa::avx2;
    return Isa::sse2;
  }();
  return isa;
#elif defined(__aarch64__) && defined(__ARM_NEON)
  return Isa::neon;
#else
  return Isa::scalar;
#endif
}

// `isa` can run here: scalar always; otherwise a set of this machine's architecture no wider
// than machine_isa().
inline bool isa_runs_here(Isa isa) {
  const Isa best = machine_isa();
  if (isa == Isa::scalar || isa == best) return true;
  if (best == Isa::neon || isa == Isa::neon) return false;
  return static_cast<int>(isa) < static_cast<int>(best);
}

// The set a TRITRI_ISA value asks for, as the header comment says.
inline Isa isa_from_setting(std::string_view setting) {
  const std::optional<Isa> asked = parse_isa(setting);
  if (!asked) {
    std::fprintf(stderr, "tritri: %s=%.*s: unknown instruction set (scalar, sse2, avx2, avx512, neon)\n",
                 kIsaVariable, static_cast<int>(setting.size()), setting.data());
    std::exit(2);
  }
  if (isa_runs_here(*asked)) return *asked;
  const std::string_view best = to_string(machine_isa());
  std::fprintf(stderr, "tritri: %s=%.*s is not supported by this CPU; the lane algorithms use %.*s\n", kIsaVariable,
               static_cast<int>(setting.size()), setting.data(), static_cast<int>(best.size()), best.data());
  return machine_isa();
}

// What TRITRI_ISA asks for, or the machine's widest; read once.
inline Isa requested_isa() {
  static const Isa isa = [] {
    const char* setting = std::getenv(kIsaVariable);
    return setting && *setting ? isa_from_setting(setting) : machine_isa();
  }();
  return isa;
}

}  // namespace tritri
