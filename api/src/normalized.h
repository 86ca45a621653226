// GL's conversion of integer colour and normal components to floats (GL 1.5 table 2.9), shared
// by the glColor / glNormal forms and the vertex arrays.
#pragma once

#include <limits>
#include <type_traits>

namespace pf {

// Unsigned c: c / (2^b - 1), in [0, 1]; signed c: (2c + 1) / (2^b - 1), in [-1, 1]; floating
// point as it is. In double, rounded once by the caller.
template <class T>
double normalized(T c) {
  if constexpr (std::is_floating_point_v<T>) {
    return c;
  } else if constexpr (std::is_signed_v<T>) {
    return (2.0 * c + 1.0) / (2.0 * std::numeric_limits<T>::max() + 1.0);
  } else {
    return c / static_cast<double>(std::numeric_limits<T>::max());
  }
}

}  // namespace pf
