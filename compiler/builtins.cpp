// Typing of built-in function calls (see builtins.h).
#include "compiler/builtins.h"

namespace pf {

namespace {
bool isNumericScalar(const Type& t) {
  return t.dims.empty() && (t.base == BaseType::Float || t.base == BaseType::Int);
}
}  // namespace

void typeBuiltinCall(Expr& e, UnitKind unit, const std::function<void(SourceLoc, const std::string&)>& err) {
  bool any_void = false;
  for (ExprPtr& a : e.args) {
    e.varying = e.varying || a->varying;
    any_void = any_void || a->type.base == BaseType::Void;
  }
  const std::string& f = e.name;
  size_t n = e.args.size();
  auto arity = [&](size_t lo, size_t hi) {
    if (n < lo || n > hi) {
      err(e.loc, f + "() takes " + (lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi)) +
                     " argument" + (hi == 1 ? "" : "s") + ", not " + std::to_string(n));
      return false;
    }
    return true;
  };
  auto needScalars = [&]() {
    for (ExprPtr& a : e.args)
      if (a->type.base != BaseType::Void && !isNumericScalar(a->type)) {
        err(a->loc, f + "() takes float arguments, not " + typeName(a->type));
        return false;
      }
    return true;
  };
  if (f == "min" || f == "max") {
    if (!arity(2, 2) || any_void || !needScalars()) return;
    bool all_int = e.args[0]->type.base == BaseType::Int && e.args[1]->type.base == BaseType::Int;
    e.type = Type::of(all_int ? BaseType::Int : BaseType::Float);
  } else if (f == "cross_sign") {
    if (!arity(4, 4) || any_void || !needScalars()) return;
    e.type = Type::of(BaseType::Float);
  } else if (f == "clamp") {
    if (!arity(3, 3) || any_void || !needScalars()) return;
    e.type = Type::of(BaseType::Float);
  } else if (f == "abs") {
    if (!arity(1, 1) || any_void || !needScalars()) return;
    e.type = e.args[0]->type;
  } else if (f == "floor" || f == "ceil" || f == "sqrt" || f == "sign") {
    if (!arity(1, 1) || any_void || !needScalars()) return;
    e.type = Type::of(BaseType::Float);
  } else if (f == "screen") {
    if (!arity(1, 1) || any_void) return;
    if (e.args[0]->type != Type::of(BaseType::Point)) {
      err(e.args[0]->loc, "screen() maps a point from clip space to homogeneous screen space; it takes a point, not " + typeName(e.args[0]->type));
      return;
    }
    e.type = Type::of(BaseType::Point);
  } else if (f == "depth_range") {
    if (!arity(0, 0)) return;
    e.type = Type::of(BaseType::Vector);
  } else if (f == "ztest") {
    if (unit != UnitKind::Primitive) {
      err(e.loc, "ztest() is only available in a primitive");
      return;
    }
    if (!arity(1, 1) || any_void || !needScalars()) return;
    e.type = Type::of(BaseType::Bool);
    e.varying = true;
  } else if (f == "float" || f == "int") {
    if (!arity(1, 1) || any_void || !needScalars()) return;
    e.type = Type::of(f == "float" ? BaseType::Float : BaseType::Int);
  } else if (f == "point" || f == "vector" || f == "normal" || f == "color") {
    BaseType b = f == "point" ? BaseType::Point : f == "vector" ? BaseType::Vector
                 : f == "normal" ? BaseType::Normal : BaseType::Color;
    size_t comps = Type::componentsOf(b);
    // point(x, y, z) has w = 1; color(r, g, b) has a = 1.
    size_t lo = (b == BaseType::Point || b == BaseType::Color) ? 3 : comps;
    if (!arity(lo, comps) || any_void || !needScalars()) return;
    e.type = Type::of(b);
  } else {
    err(e.loc, "'" + f + "' is not a built-in function (user functions come with a later version of the language)");
  }
}

}  // namespace pf
