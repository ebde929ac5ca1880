// What CGAL::intersection returns holds one of several shapes: a boost::variant before CGAL 6,
// a std::variant from CGAL 6 on (Debian 12 ships 5.5, Debian 13 ships 6.0). One accessor for
// both, for the code that includes CGAL (the oracle, the scenes' exact check): a pointer to the
// alternative T, or null when the result holds another shape.
#pragma once

#include <CGAL/version.h>

#include <variant>

#if CGAL_VERSION_NR < 1060000000
#include <boost/variant.hpp>
#endif

namespace tritri {

template <class T, class... Shapes>
const T* alternative(const std::variant<Shapes...>& v) {
  return std::get_if<T>(&v);
}

#if CGAL_VERSION_NR < 1060000000
template <class T, class... Shapes>
const T* alternative(const boost::variant<Shapes...>& v) {
  return boost::get<T>(&v);
}
#endif

}  // namespace tritri
