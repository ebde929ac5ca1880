// Triangles and pairs of triangles: the input every algorithm receives.
//
// Templated on the scalar so that one port can be instantiated for double (the reference),
// float (the stability report) and an operation-counting scalar (the timing work).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()

#include <array>
#include <vector>

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

// A triangle's vertices in each of their six orders: the identity, two rotations, three reflections.
inline constexpr std::array<std::array<int, 3>, 6> kVertexOrders{
    {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};
inline Triangle permuted(const Triangle& t, const std::array<int, 3>& o) { return {{t[o[0]], t[o[1]], t[o[2]]}}; }

// The 72 orders of a pair: both argument orders times the six vertex orders of each triangle;
// the first is the pair as given.
inline std::vector<TrianglePair> every_order(const TrianglePair& pair) {
  std::vector<TrianglePair> out;
  for (bool swap : {false, true})
    for (const auto& o1 : kVertexOrders)
      for (const auto& o2 : kVertexOrders) {
        const TrianglePair p{permuted(pair.t1, o1), permuted(pair.t2, o2)};
        out.push_back(swap ? swapped(p) : p);
      }
  return out;
}

}  // namespace tritri
