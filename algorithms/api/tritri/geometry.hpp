// Triangles and pairs of triangles: the input every algorithm receives.
//
// Templated on the scalar so that one port can be instantiated for double (the reference),
// float (the stability report) and an operation-counting scalar (the timing work).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()

#include <array>

namespace tritri {

template <class T>
using Vec3 = Eigen::Matrix<T, 3, 1>;

template <class T>
struct TriangleT {
  std::array<Vec3<T>, 3> v;

  const Vec3<T>& operator[](int i) const { return v[static_cast<std::size_t>(i)]; }
  Vec3<T>& operator[](int i) { return v[static_cast<std::size_t>(i)]; }
};

template <class T>
struct PairT {
  TriangleT<T> t1;
  TriangleT<T> t2;
};

using Triangle = TriangleT<double>;
using TrianglePair = PairT<double>;

template <class To, class From>
TriangleT<To> cast(const TriangleT<From>& t) {
  return {{t[0].template cast<To>(), t[1].template cast<To>(), t[2].template cast<To>()}};
}

template <class To, class From>
PairT<To> cast(const PairT<From>& p) {
  return {cast<To>(p.t1), cast<To>(p.t2)};
}

inline TrianglePair swapped(const TrianglePair& p) { return {p.t2, p.t1}; }

}  // namespace tritri
