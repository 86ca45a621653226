// Printable names of the language's types.
#include "compiler/types.h"

namespace pf {

std::string baseTypeName(BaseType b) {
  switch (b) {
    case BaseType::Void: return "void";
    case BaseType::Float: return "float";
    case BaseType::Int: return "int";
    case BaseType::Bool: return "bool";
    case BaseType::Point: return "point";
    case BaseType::Vector: return "vector";
    case BaseType::Normal: return "normal";
    case BaseType::Color: return "color";
    case BaseType::Matrix: return "matrix";
    case BaseType::InterpData: return "interpolator_data";
    case BaseType::Fixed: return "fixed";
  }
  return "?";
}

std::string typeName(const Type& t) {
  std::string s = baseTypeName(t.base);
  if (t.base == BaseType::Fixed) s += "<" + std::to_string(t.fixed_bits) + "," + std::to_string(t.fixed_frac) + ">";
  for (int d : t.dims) s += d == 0 ? std::string("[]") : "[" + std::to_string(d) + "]";
  return s;
}

const char* interpKindName(InterpKind k) {
  switch (k) {
    case InterpKind::PerspectiveLinear: return "perspective_linear";
    case InterpKind::Linear: return "linear";
    case InterpKind::Shared: return "default";
  }
  return "?";
}

}  // namespace pf
