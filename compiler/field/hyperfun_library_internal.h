// Shared by the source files of HyperFun's library (hyperfun_library.cpp,
// hyperfun_convolution.cpp, hyperfun_sardf.cpp and the hyperfun_attribute*.cpp files), not by its users: the checks on a library call's arguments, which
// throw LibraryError with a message naming the argument, and the library functions defined
// outside hyperfun_library.cpp, for its table.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "compiler/field/hyperfun_library.h"

namespace pf::field::hyperfun {

[[noreturn]] inline void reject(int argument, std::string message) {
  throw LibraryError{argument, std::move(message)};
}

// "'center' (argument 2 of 'hfSphere')"
inline std::string paramLabel(const LibraryCall& c, int i) {
  std::string_view p = c.function.params;
  for (int k = 0; k < i; ++k) p = p.substr(p.find(", ") + 2);
  p = p.substr(0, p.find(", "));
  return "'" + std::string(p) + "' (argument " + std::to_string(i + 1) + " of '" + std::string(c.function.name) + "')";
}

// The items of array argument i, which must hold `size` items.
inline std::vector<Real>& items(LibraryCall& c, int i, size_t size) {
  std::vector<Real>& a = *c.arrays[i];
  if (a.size() != size)
    reject(i, paramLabel(c, i) + " must be an array of " + std::to_string(size) + " items; '" + c.array_names[i] +
                  "' has " + std::to_string(a.size()));
  return a;
}

// The items of array argument i, which must hold at least `n` items (HyperFun reads them unchecked).
inline std::vector<Real>& atLeast(LibraryCall& c, int i, size_t n) {
  std::vector<Real>& a = *c.arrays[i];
  if (a.size() < n)
    reject(i, paramLabel(c, i) + " must be an array of at least " + std::to_string(n) + " items; '" +
                  c.array_names[i] + "' has " + std::to_string(a.size()));
  return a;
}

// Array arguments [first, last] that must all hold as many items as argument `first`.
inline size_t sameSizes(LibraryCall& c, int first, int last) {
  const size_t n = c.arrays[first]->size();
  for (int i = first + 1; i <= last; ++i) items(c, i, n);
  return n;
}

// A real argument that must be known when the model is compiled.
inline double knownArg(LibraryCall& c, int i, std::string_view why) {
  if (!c.reals[i].is_known)
    reject(i, paramLabel(c, i) + " depends on the point x; it must be known when the model is compiled (" +
                  std::string(why) + ")");
  return c.reals[i].value;
}

// An item of an array argument that must be known when the model is compiled.
inline double knownItem(LibraryCall& c, int i, size_t k, std::string_view why) {
  const Real r = (*c.arrays[i])[k];
  if (!r.is_known)
    reject(i, "item " + std::to_string(k + 1) + " of " + paramLabel(c, i) + " depends on the point x; it must be known "
                  "when the model is compiled (" + std::string(why) + ")");
  return r.value;
}

// The convolution surfaces over triangles, arcs and radius-sized segments
// (hyperfun_convolution.cpp).
Real hfConvTriangle(LibraryCall& c);
Real hfConvMesh(LibraryCall& c);
Real hfConvArc(LibraryCall& c);
Real hfConvLineR(LibraryCall& c);

// The SARDF operations and hfDEllipsoid (hyperfun_sardf.cpp).
Real hfDUni(LibraryCall& c);
Real hfDInt(LibraryCall& c);
Real hfDSub(LibraryCall& c);
Real hfDBlendUni(LibraryCall& c);
Real hfDBlendInt(LibraryCall& c);
Real hfDEllipsoid(LibraryCall& c);

// The attribute library: what writes or computes the s array (hyperfun_attributes.cpp).
Real hfASetColor(LibraryCall& c);
Real hfASetAttributes(LibraryCall& c);
Real hfALerp(LibraryCall& c);
Real hfAClamp(LibraryCall& c);
Real hfAPulse(LibraryCall& c);
Real hfAStep(LibraryCall& c);
Real hfASmoothStep(LibraryCall& c);
Real hfAWave(LibraryCall& c);
Real hfAUnion(LibraryCall& c);
Real hfAFloor(LibraryCall& c);
Real hfAModulo(LibraryCall& c);
// The patterns (hyperfun_attribute_patterns.cpp).
Real hfACheckerBoard(LibraryCall& c);
Real hfACircles(LibraryCall& c);
Real hfACrackles(LibraryCall& c);
Real hfANoiseG(LibraryCall& c);
// HyperFun's Perlin noise (hyperfun_attribute_noise.cpp).
Real hfANoiseP(LibraryCall& c);
Real hfATurbulence(LibraryCall& c);
// The tables and colour spaces (hyperfun_attribute_tables.cpp).
Real hfALookUpTable(LibraryCall& c);
Real hfASmoothLookUpTable(LibraryCall& c);
Real hfASpline(LibraryCall& c);
Real hfARGBToHSV(LibraryCall& c);
Real hfAHSVToRGB(LibraryCall& c);

}  // namespace pf::field::hyperfun
