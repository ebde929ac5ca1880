// The answer levels as types: each level's answer type, the scalar types a port is instantiated
// on, sets of levels, and a loop over the levels for code that handles each with its own type.
#pragma once

#include "tritri/answers.hpp"

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string_view>
#include <type_traits>

namespace tritri {

template <Level L>
struct LevelAnswer;
template <>
struct LevelAnswer<Level::overlap> {
  using type = Overlap;
};
template <>
struct LevelAnswer<Level::relation> {
  using type = RelationAnswer;
};
template <>
struct LevelAnswer<Level::segment> {
  using type = SegmentAnswer;
};
template <Level L>
using AnswerOf = typename LevelAnswer<L>::type;

inline constexpr Level kLevels[] = {Level::overlap, Level::relation, Level::segment};

// Calls f(std::integral_constant<Level, L>{}) for each level: code that must handle each level
// with its own answer type writes one generic lambda instead of a switch.
template <class F>
void for_each_level(F&& f) {
  f(std::integral_constant<Level, Level::overlap>{});
  f(std::integral_constant<Level, Level::relation>{});
  f(std::integral_constant<Level, Level::segment>{});
}

// A set of levels, e.g. those a run asks for.
class LevelSet {
 public:
  constexpr LevelSet() = default;
  constexpr LevelSet(std::initializer_list<Level> levels) {
    for (Level l : levels) insert(l);
  }
  constexpr void insert(Level l) { bits_ |= bit(l); }
  constexpr bool contains(Level l) const { return (bits_ & bit(l)) != 0; }
  constexpr bool empty() const { return bits_ == 0; }
  static constexpr LevelSet all() { return {Level::overlap, Level::relation, Level::segment}; }

 private:
  static constexpr std::uint8_t bit(Level l) { return static_cast<std::uint8_t>(1u << static_cast<unsigned>(l)); }
  std::uint8_t bits_ = 0;
};

// The scalar type a port is instantiated on. `double` is the port itself (what check and bench
// judge and time); `float` rounds each pair to float inside the call (the stability report);
// `counted` is the operation-counting scalar of tritri/counting.hpp (bench's operation counts).
enum class Scalar : std::uint8_t { double_, float_, counted };
inline constexpr Scalar kScalars[] = {Scalar::double_, Scalar::float_, Scalar::counted};
inline constexpr std::size_t kScalarCount = std::size(kScalars);
std::string_view to_string(Scalar);  // "double", "float", "counted"

}  // namespace tritri
