// Types and qualifiers of the primitive language.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace pf {

// Matrix: 4x4 floats, 16 slots in row-major order (slot 4 r + c holds row r, column c).
// Fixed: fixed<bits,frac> (compiler/fixed_point.h), a scalar held in two 32-bit slots (the
// raw integer's low and high words); Type::fixed_bits and fixed_frac give its format.
enum class BaseType { Void, Float, Int, Bool, Point, Vector, Normal, Color, Matrix, InterpData, Fixed };

// How a shading parameter is interpolated: the labels of `interpolation { ... }`.
// Channels of an instance are ordered by kind so that each kind is one contiguous range.
enum class InterpKind : int { PerspectiveLinear = 0, Linear = 1, Shared = 2 };
constexpr int kInterpKindCount = 3;
using InterpKindSet = unsigned;  // bit (1 << kind)
constexpr InterpKindSet kAllInterpKinds = 7;

enum class Qualifier { None, Uniform, Varying, Inout, InoutVarying };

struct Type {
  BaseType base = BaseType::Void;
  // Array dimensions, outermost first. 0 (only outermost, only for a primitive's parameters):
  // parameter-sized, `point vertex[]`, as many elements as the instance has sequence points.
  std::vector<int> dims;
  int fixed_bits = 0, fixed_frac = 0;  // BaseType::Fixed: the format

  bool isArray() const { return !dims.empty(); }
  bool isParameterSized() const { return !dims.empty() && dims[0] == 0; }
  bool isScalar() const { return dims.empty() && (base == BaseType::Float || base == BaseType::Int || base == BaseType::Bool); }
  bool isAggregate() const { return dims.empty() && componentsOf(base) > 1 && base != BaseType::Fixed; }
  bool isFixed() const { return dims.empty() && base == BaseType::Fixed; }
  Type element() const { Type t = *this; t.dims.erase(t.dims.begin()); return t; }
  int elementCount() const { int n = 1; for (int d : dims) n *= d; return n; }
  // Scalar slots the whole value occupies: components of the base times array elements.
  int slotCount() const { return componentsOf(base) * elementCount(); }
  bool operator==(const Type& o) const {
    return base == o.base && dims == o.dims && fixed_bits == o.fixed_bits && fixed_frac == o.fixed_frac;
  }
  bool operator!=(const Type& o) const { return !(*this == o); }

  static int componentsOf(BaseType b) {
    switch (b) {
      case BaseType::Point: return 4;   // homogeneous (x, y, z, w)
      case BaseType::Vector: return 3;
      case BaseType::Normal: return 3;
      case BaseType::Color: return 4;   // (r, g, b, a)
      case BaseType::Matrix: return 16;  // row-major
      case BaseType::Fixed: return 2;    // low and high words
      case BaseType::Void: return 0;
      default: return 1;
    }
  }
  static Type of(BaseType b) { Type t; t.base = b; return t; }
  static Type fixed(int bits, int frac) {
    Type t;
    t.base = BaseType::Fixed;
    t.fixed_bits = bits;
    t.fixed_frac = frac;
    return t;
  }
  // What `value[i]` reads: an array's element; a matrix's row i (a point of 4 floats); a point's,
  // vector's, normal's or colour's component. Slots per element and how many elements.
  int indexedSlots() const { return isArray() ? (base == BaseType::InterpData ? 1 : element().slotCount()) : base == BaseType::Matrix ? 4 : 1; }
  int indexedCount() const { return isArray() ? dims[0] : base == BaseType::Matrix ? 4 : componentsOf(base); }
};

// A primitive's parameters as declared (name, type), X, Y and Z left out: how another
// primitive calls it.
using PrimitiveSignature = std::vector<std::pair<std::string, Type>>;

std::string typeName(const Type& t);
std::string baseTypeName(BaseType b);
const char* interpKindName(InterpKind k);

}  // namespace pf
