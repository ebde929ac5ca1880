// An operation-counting scalar: a double that counts what is done with it.
//
// A port written as a template on its scalar (see algorithms/README.md) is instantiated on
// `Counted` to count, per pair, the arithmetic a test performs: Tropp et al. compare tests by
// operation counts, and counts do not depend on the machine or on its load.
//
// What is counted, in the thread-local `op_counts()`:
//   add   a + b, a - b, a += b, a -= b   (a subtraction is an addition)
//   mul   a * b, a *= b
//   div   a / b, a /= b
//   cmp   a < b, a <= b, a > b, a >= b, a == b, a != b (a comparison with a literal counts too:
//         the literal becomes a Counted)
//   sqrt  sqrt(a)
// Not counted: unary minus and abs (sign-bit operations), construction from a double, copies,
// and conversion back to double (explicit: `static_cast<double>(x)` or `x.value()`).
//
// Eigen sees `Counted` as a real scalar (NumTraits below), so `Vec3<Counted>` arithmetic, dot()
// (3 mul + 2 add) and cross() (6 mul + 3 add) are counted operation by operation, exactly as
// Eigen evaluates them for a scalar type it cannot vectorise.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <type_traits>

namespace tritri {

struct OpCounts {
  std::uint64_t add = 0;
  std::uint64_t mul = 0;
  std::uint64_t div = 0;
  std::uint64_t cmp = 0;
  std::uint64_t sqrt = 0;

  std::uint64_t arithmetic() const { return add + mul + div + sqrt; }
  std::uint64_t total() const { return arithmetic() + cmp; }
  friend bool operator==(const OpCounts&, const OpCounts&) = default;
};

// The counts of the calling thread. Reset before the computation to be counted.
inline OpCounts& op_counts() {
  static thread_local OpCounts counts;
  return counts;
}

class Counted {
 public:
  constexpr Counted() = default;
  // Implicit from any arithmetic type, so `T x = 0;` and `T(1e-6)` read as they do for double.
  template <class A, class = std::enable_if_t<std::is_arithmetic_v<A>>>
  constexpr Counted(A v) : v_(static_cast<double>(v)) {}  // NOLINT(google-explicit-constructor)

  constexpr double value() const { return v_; }
  explicit constexpr operator double() const { return v_; }
  explicit constexpr operator float() const { return static_cast<float>(v_); }

  Counted& operator+=(Counted b) { ++op_counts().add; v_ += b.v_; return *this; }
  Counted& operator-=(Counted b) { ++op_counts().add; v_ -= b.v_; return *this; }
  Counted& operator*=(Counted b) { ++op_counts().mul; v_ *= b.v_; return *this; }
  Counted& operator/=(Counted b) { ++op_counts().div; v_ /= b.v_; return *this; }

  friend Counted operator+(Counted a, Counted b) { return a += b; }
  friend Counted operator-(Counted a, Counted b) { return a -= b; }
  friend Counted operator*(Counted a, Counted b) { return a *= b; }
  friend Counted operator/(Counted a, Counted b) { return a /= b; }
  friend constexpr Counted operator-(Counted a) { return Counted(-a.v_); }
  friend constexpr Counted operator+(Counted a) { return a; }

  friend bool operator<(Counted a, Counted b) { ++op_counts().cmp; return a.v_ < b.v_; }
  friend bool operator<=(Counted a, Counted b) { ++op_counts().cmp; return a.v_ <= b.v_; }
  friend bool operator>(Counted a, Counted b) { ++op_counts().cmp; return a.v_ > b.v_; }
  friend bool operator>=(Counted a, Counted b) { ++op_counts().cmp; return a.v_ >= b.v_; }
  friend bool operator==(Counted a, Counted b) { ++op_counts().cmp; return a.v_ == b.v_; }
  friend bool operator!=(Counted a, Counted b) { ++op_counts().cmp; return a.v_ != b.v_; }

 private:
  double v_ = 0.0;
};

// Found by argument-dependent lookup after `using std::abs;` (likewise sqrt) in a port.
inline Counted abs(Counted a) { return Counted(std::fabs(a.value())); }
inline Counted sqrt(Counted a) {
  ++op_counts().sqrt;
  return Counted(std::sqrt(a.value()));
}
inline bool isfinite(Counted a) { return std::isfinite(a.value()); }
inline bool isnan(Counted a) { return std::isnan(a.value()); }
inline bool isinf(Counted a) { return std::isinf(a.value()); }

}  // namespace tritri

namespace Eigen {
template <>
struct NumTraits<tritri::Counted> : NumTraits<double> {
  using Real = tritri::Counted;
  using NonInteger = tritri::Counted;
  using Literal = tritri::Counted;
  using Nested = tritri::Counted;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 1,
    AddCost = 1,
    MulCost = 1,
  };
  static inline tritri::Counted epsilon() { return NumTraits<double>::epsilon(); }
  static inline tritri::Counted dummy_precision() { return NumTraits<double>::dummy_precision(); }
  static inline tritri::Counted highest() { return NumTraits<double>::highest(); }
  static inline tritri::Counted lowest() { return NumTraits<double>::lowest(); }
  static inline int digits10() { return NumTraits<double>::digits10(); }
};
}  // namespace Eigen

namespace Eigen::internal {
// Sums of Counted coefficients are added in storage order, (x + y) + z, which is the order Eigen
// uses for the doubles of a fixed-size Vec3 here. Its own unrolled reduction for a type it cannot
// vectorise pairs them the other way, x + (y + z): a different last bit in a dot product, enough
// to flip an answer that the last bit decides, and then the counts would be of another run.
template <class Evaluator>
struct redux_impl<scalar_sum_op<tritri::Counted, tritri::Counted>, Evaluator, DefaultTraversal, CompleteUnrolling> {
  using Scalar = tritri::Counted;
  template <class Xpr>
  static Scalar run(const Evaluator& eval, const scalar_sum_op<Scalar, Scalar>& sum, const Xpr& xpr) {
    Scalar total = eval.coeffByOuterInner(0, 0);
    for (Index outer = 0; outer < xpr.outerSize(); ++outer)
      for (Index inner = outer == 0 ? 1 : 0; inner < xpr.innerSize(); ++inner)
        total = sum(total, eval.coeffByOuterInner(outer, inner));
    return total;
  }
};
}  // namespace Eigen::internal
