// Semantic analysis of expressions (the Analyzer, analyzer.h): types and varying-ness of
// literals, names, operators, components and indices (with the constant indices checked
// against their range), and of calls: of user functions, of built-ins (builtins.h) and of other
// primitives, whose calls must be uniform statements.
#include "compiler/analyzer.h"
#include "compiler/builtins.h"
#include "compiler/stack_guard.h"

#include <string>

namespace pf::analysis {
namespace {

int componentIndex(BaseType b, const std::string& f) {
  if (b == BaseType::Color) {
    const char* names = "rgba";
    for (int i = 0; i < 4; ++i)
      if (f.size() == 1 && f[0] == names[i]) return i;
    return -1;
  }
  const char* names = "xyzw";
  int n = Type::componentsOf(b);
  for (int i = 0; i < n; ++i)
    if (f.size() == 1 && f[0] == names[i]) return i;
  return -1;
}

}  // namespace

void fixedAsFloat(ExprPtr& e) {
  if (!e || !isFixed(e->type)) return;
  auto conv = std::make_unique<Expr>();
  conv->kind = ExprKind::Call;
  conv->loc = e->loc;
  conv->name = "float";
  conv->type = Type::of(BaseType::Float);
  conv->varying = e->varying;
  conv->args.push_back(std::move(e));
  e = std::move(conv);
}

void Analyzer::expr(Expr& e) {
  if (stackNearlyExhausted()) {
    err(e.loc, "nesting too deep for this thread's stack");
    throw CompileAbort{};  // (analyze catches it)
  }
  e.type = Type::of(BaseType::Void);
  e.varying = false;
  switch (e.kind) {
    case ExprKind::IntLit: e.type = Type::of(BaseType::Int); return;
    case ExprKind::FloatLit: e.type = Type::of(BaseType::Float); return;
    case ExprKind::BoolLit: e.type = Type::of(BaseType::Bool); return;
    case ExprKind::Name: {
      int vi = lookup(e.name);
      if (vi < 0) {
        const bool pixel_builtin = e.name == "X" || e.name == "Y" || e.name == "Z" || e.name == "P" || e.name == "N";
        if (unit_->kind == UnitKind::Field && pixel_builtin)
          err(e.loc, "'" + e.name + "' is a pixel's built-in, which a field does not see: a field is a function of its point alone");
        else
          err(e.loc, "'" + e.name + "' is not declared");
        return;
      }
      e.type = vars_[vi].type;
      e.varying = vars_[vi].varying;
      return;
    }
    case ExprKind::Unary: {
      Expr& a = *e.args[0];
      expr(a);
      e.varying = a.varying;
      if (a.type.base == BaseType::Void) return;
      if (e.name == "!") {
        if (!isBool(a.type)) err(e.loc, "'!' needs a bool, not " + typeName(a.type));
        e.type = Type::of(BaseType::Bool);
      } else {
        if (!(isNumericScalar(a.type) || isFixed(a.type) || isAggregate(a.type) || isInterp(a.type)))
          err(e.loc, "cannot negate a value of type " + typeName(a.type));
        e.type = a.type;
      }
      return;
    }
    case ExprKind::Binary: {
      Expr& a = *e.args[0];
      Expr& b = *e.args[1];
      expr(a);
      expr(b);
      e.varying = a.varying || b.varying;
      e.type = binaryType(e.name, a.type, b.type, e.loc);
      return;
    }
    case ExprKind::Ternary: {
      for (ExprPtr& a : e.args) expr(*a);
      e.varying = e.args[0]->varying || e.args[1]->varying || e.args[2]->varying;
      if (e.args[0]->type.base != BaseType::Void && !isBool(e.args[0]->type))
        err(e.args[0]->loc, "the condition of '?:' must be bool, not " + typeName(e.args[0]->type));
      const Type& t1 = e.args[1]->type;
      const Type& t2 = e.args[2]->type;
      if (t1.base == BaseType::Void || t2.base == BaseType::Void) return;
      if (t1 == t2) e.type = t1;
      else if (isNumericScalar(t1) && isNumericScalar(t2)) e.type = Type::of(BaseType::Float);
      else if ((isFixed(t1) && t2 == Type::of(BaseType::Int)) || (t1 == Type::of(BaseType::Int) && isFixed(t2)))
        e.type = isFixed(t1) ? t1 : t2;  // the int converts
      else if ((isFixed(t1) && t2 == Type::of(BaseType::Float)) || (t1 == Type::of(BaseType::Float) && isFixed(t2)))
        e.type = Type::of(BaseType::Float);  // the fixed value converts
      else err(e.loc, "the two results of '?:' have different types: " + typeName(t1) + " and " + typeName(t2));
      if (e.type.isArray())
        err(e.loc, "'?:' chooses between scalars, vectors or interpolator_data, not " + typeName(e.type));
      return;
    }
    case ExprKind::Member: {
      Expr& a = *e.args[0];
      expr(a);
      e.varying = a.varying;
      if (a.type.base == BaseType::Void) return;
      if (!isAggregate(a.type) || a.type.base == BaseType::Matrix) {
        err(e.loc, "'." + e.name + "' needs a point, vector, normal or color, not " + typeName(a.type) +
                       (a.type.base == BaseType::Matrix ? " (a matrix's elements are m[row][column])" : ""));
        return;
      }
      int ci = componentIndex(a.type.base, e.name);
      if (ci < 0) {
        err(e.loc, "a " + typeName(a.type) + " has no component '" + e.name + "'" +
                       (a.type.base == BaseType::Color ? " (components: r, g, b, a)"
                        : a.type.base == BaseType::Point ? " (components: x, y, z, w)"
                                                         : " (components: x, y, z)"));
        return;
      }
      e.number = ci;
      e.type = Type::of(BaseType::Float);
      return;
    }
    case ExprKind::Index: {
      Expr& base = *e.args[0];
      Expr& index = *e.args[1];
      expr(base);
      expr(index);
      e.varying = base.varying || index.varying;
      if (base.type.base == BaseType::Void) return;
      int limit;
      if (base.type.isArray()) {
        e.type = base.type.element();
        limit = base.type.dims[0];
      } else if (base.type.base == BaseType::Matrix) {  // a row, as a point: m[row][column]
        e.type = Type::of(BaseType::Point);
        limit = 4;
      } else if (isAggregate(base.type)) {
        e.type = Type::of(BaseType::Float);
        limit = Type::componentsOf(base.type.base);
      } else {
        err(e.loc, "cannot index a value of type " + typeName(base.type));
        return;
      }
      if (index.type.base != BaseType::Void && (index.type.base != BaseType::Int || index.type.isArray())) {
        err(index.loc, "an index must be an int, not " + typeName(index.type));
        return;
      }
      // A parameter-sized array (`point vertex[]`) lives in the instance's parameters, which
      // only setup reads: its index must be the same for every pixel.
      const bool parameter_sized = base.type.isArray() && base.type.dims[0] == 0;
      if (parameter_sized && index.varying) {
        err(index.loc, "a parameter-sized array is read once per instance, so its index must be uniform; this index is varying: " + whyOf(index));
        return;
      }
      long value;
      if (!constantInt(index, value)) {
        e.number = -1;  // computed at run time (lowering: a select over the elements, or a load)
        return;
      }
      if (value < 0 || (!parameter_sized && value >= limit)) {
        err(index.loc, "index " + std::to_string(value) + " is out of range " +
                           (parameter_sized ? std::string("(an index is never negative)")
                                            : "[0, " + std::to_string(limit - 1) + "]"));
        return;
      }
      e.number = static_cast<double>(value);
      return;
    }
    case ExprKind::Call: call(e); return;
  }
}

bool Analyzer::constantInt(const Expr& e, long& out) {
  switch (e.kind) {
    case ExprKind::IntLit: out = static_cast<long>(e.number); return true;
    case ExprKind::Unary:
      if (e.name == "-" && constantInt(*e.args[0], out)) { out = -out; return true; }
      return false;
    case ExprKind::Binary: {
      long a, b;
      if (!constantInt(*e.args[0], a) || !constantInt(*e.args[1], b)) return false;
      if (e.name == "+") out = a + b;
      else if (e.name == "-") out = a - b;
      else if (e.name == "*") out = a * b;
      else return false;
      return out > -(1L << 30) && out < (1L << 30);
    }
    default: return false;
  }
}

Type Analyzer::binaryType(const std::string& op, const Type& a, const Type& b, SourceLoc loc) {
  Type voidT = Type::of(BaseType::Void);
  if (a.base == BaseType::Void || b.base == BaseType::Void) return voidT;
  auto bad = [&] {
    err(loc, "operator '" + op + "' cannot combine " + typeName(a) + " and " + typeName(b));
    return voidT;
  };
  if (op == "&&" || op == "||") {
    if (!isBool(a) || !isBool(b)) return bad();
    return Type::of(BaseType::Bool);
  }
  const bool comparison = op == "<" || op == "<=" || op == ">" || op == ">=" || op == "==" || op == "!=";
  if (isFixed(a) || isFixed(b)) {
    // docs/language.md, "Fixed-point numbers": one format, or an int that converts to it, stays
    // fixed; with a float (or a vector, ...) the fixed value takes part as a float.
    if (op == "%") return bad();
    if (isFixed(a) && isFixed(b) && a != b) {
      err(loc, "operator '" + op + "' cannot combine " + typeName(a) + " and " + typeName(b) +
                   ": values of two fixed-point formats meet only after a conversion, e.g. " + typeName(a) + "(x)");
      return voidT;
    }
    const Type& other = isFixed(a) ? b : a;
    const Type& fixed = isFixed(a) ? a : b;
    if (isFixed(other) || other == Type::of(BaseType::Int)) return comparison ? Type::of(BaseType::Bool) : fixed;
    if (other == Type::of(BaseType::Float)) return comparison ? Type::of(BaseType::Bool) : other;
    if (isAggregate(other) || isInterp(other))
      return binaryType(op, isFixed(a) ? Type::of(BaseType::Float) : a, isFixed(b) ? Type::of(BaseType::Float) : b, loc);
    return bad();
  }
  if (op == "<" || op == "<=" || op == ">" || op == ">=") {
    if (!isNumericScalar(a) || !isNumericScalar(b)) return bad();
    return Type::of(BaseType::Bool);
  }
  if (op == "==" || op == "!=") {
    if ((isNumericScalar(a) && isNumericScalar(b)) || (isBool(a) && isBool(b))) return Type::of(BaseType::Bool);
    return bad();
  }
  // arithmetic
  if (isNumericScalar(a) && isNumericScalar(b)) {
    if (a.base == BaseType::Int && b.base == BaseType::Int) return a;
    return Type::of(BaseType::Float);
  }
  if (op == "%") return bad();
  // Matrices: products with a matrix, point, vector or normal on the right (m * p transforms p);
  // otherwise only + and - between two, and scaling by a number (the rules below).
  const Type matrix = Type::of(BaseType::Matrix);
  if (a == matrix && op == "*" && b.dims.empty() &&
      (b.base == BaseType::Matrix || b.base == BaseType::Point || b.base == BaseType::Vector || b.base == BaseType::Normal))
    return b;
  if ((a == matrix || b == matrix) && a == b && op != "+" && op != "-") return bad();
  if (isAggregate(a) && a == b) return a;
  // A point moved by a vector (or normal) is a point, its w unchanged.
  const auto isDirection = [](const Type& t) {
    return t == Type::of(BaseType::Vector) || t == Type::of(BaseType::Normal);
  };
  if (a == Type::of(BaseType::Point) && isDirection(b) && (op == "+" || op == "-")) return a;
  if (isDirection(a) && b == Type::of(BaseType::Point) && op == "+") return b;
  if (isAggregate(a) && isNumericScalar(b) && (op == "*" || op == "/")) return a;
  if (isNumericScalar(a) && isAggregate(b) && op == "*") return b;
  if (isInterp(a) && isInterp(b) && (op == "+" || op == "-")) return a;
  if (isInterp(a) && isNumericScalar(b) && (op == "*" || op == "/")) return a;
  if (isNumericScalar(a) && isInterp(b) && op == "*") return b;
  return bad();
}

void Analyzer::primitiveCall(Expr& e, const PrimitiveSignature& callee) {
  e.type = Type::of(BaseType::Void);
  const std::string what = "'" + e.name + "' is a primitive: calling it submits an instance of it";
  if (unit_->kind != UnitKind::Primitive) {
    err(e.loc, what + ", which only a primitive can do");
    return;
  }
  if (&e != statement_call_) err(e.loc, what + "; the call is a statement and has no value");
  if (varying_control_ > 0)
  {
    std::string why = varying_control_why_;  // "it is assigned under / in ..."
    if (why.rfind("it is assigned ", 0) == 0) why = "it is " + why.substr(15);
    err(e.loc, what + ", so the call must be under uniform control flow; here " + why);
  }
  if (interp_depth_ > 0) err(e.loc, what + ", which cannot happen inside 'interpolation'");
  if (e.args.size() != callee.size()) {
    err(e.loc, "'" + e.name + "' takes " + std::to_string(callee.size()) + " argument" +
                   (callee.size() == 1 ? "" : "s") + ", not " + std::to_string(e.args.size()));
    return;
  }
  for (size_t i = 0; i < e.args.size(); ++i) {
    const Type& to = callee[i].second;
    if (to.isParameterSized()) {
      err(e.args[i]->loc, "'" + e.name + "' takes a parameter-sized array ('" + callee[i].first + "[]'): it can only be drawn through the API");
      continue;
    }
    checkAssignable(to, *e.args[i], "pass '" + callee[i].first + "' to '" + e.name + "'");
    if (e.args[i]->varying)
      err(e.args[i]->loc, "argument '" + callee[i].first + "' of '" + e.name + "' must be uniform (an instance has one value); " + whyOf(*e.args[i]));
  }
}

void Analyzer::call(Expr& e) {
  for (ExprPtr& a : e.args) expr(*a);
  auto f = functions_.units.find(e.name);
  if (f == functions_.units.end() && functions_.later_primitives.count(e.name)) {
    err(e.loc, "primitive '" + e.name + "' is defined further down: define a primitive before the primitives that call it");
    return;
  }
  auto prim = functions_.primitives.find(e.name);
  if (f == functions_.units.end() && prim != functions_.primitives.end()) {
    primitiveCall(e, prim->second);
    return;
  }
  if (f == functions_.units.end()) {
    if (fixedCall(e)) return;
    for (ExprPtr& a : e.args) fixedAsFloat(a);
    typeBuiltinCall(e, unit_->kind, [this](SourceLoc loc, const std::string& msg) { err(loc, msg); });
    if (e.name == "facing" || e.name == "depth_bound") {
      // Effects on the whole instance: uniform, and statements.
      const std::string what = e.name == "facing" ? "facing" : "depth bound";
      if (&e != statement_call_) err(e.loc, e.name + "() is a statement: it sets the instance's " + what + " and has no value");
      if (unit_->kind != UnitKind::Primitive) err(e.loc, e.name + "() is only available in a primitive");
      const Expr* varying_arg = nullptr;
      for (const ExprPtr& a : e.args)
        if (a->varying && !varying_arg) varying_arg = a.get();
      if (varying_control_ > 0 || varying_arg)
        err(e.loc, e.name + "() sets the " + what + " of the whole instance, so it must be uniform; " +
                       (varying_control_ > 0 ? varying_control_why_ : whyOf(*varying_arg)));
    }
    return;
  }
  const Unit& fn = *f->second;
  functions_.calls[unit_->name].push_back({fn.name, e.loc});  // (the varying analysis reads them too)
  e.type = fn.return_type;
  e.varying = functions_.intrinsically_varying[fn.name];
  if (e.args.size() != fn.params.size()) {
    err(e.loc, "'" + fn.name + "' takes " + std::to_string(fn.params.size()) + " argument" +
                   (fn.params.size() == 1 ? "" : "s") + ", not " + std::to_string(e.args.size()));
    return;
  }
  for (size_t i = 0; i < e.args.size(); ++i) {
    checkAssignable(fn.params[i].type, *e.args[i], "pass argument " + std::to_string(i + 1) + " to '" + fn.name + "'");
    e.varying = e.varying || e.args[i]->varying;
  }
}

bool Analyzer::fixedCall(Expr& e) {
  const std::string& f = e.name;
  bool any_fixed = false, any_void = false;
  for (const ExprPtr& a : e.args) {
    any_fixed = any_fixed || isFixed(a->type);
    any_void = any_void || a->type.base == BaseType::Void;
    e.varying = e.varying || a->varying;
  }
  if (f == "fixed") {  // fixed<bits,frac>(x): x a number or another format
    e.type = e.conversion;
    if (e.args.size() != 1) {
      err(e.loc, typeName(e.conversion) + "() converts one number, not " + std::to_string(e.args.size()));
    } else if (!any_void && !isNumericScalar(e.args[0]->type) && !isFixed(e.args[0]->type)) {
      err(e.args[0]->loc, typeName(e.conversion) + "() converts an int, a float or another fixed-point value, not " +
                              typeName(e.args[0]->type));
    }
    return true;
  }
  if (!any_fixed) return false;
  if ((f == "float" || f == "int") && e.args.size() == 1) {
    e.type = Type::of(f == "float" ? BaseType::Float : BaseType::Int);
    return true;
  }
  // abs, min, max and clamp of fixed values (and ints, which convert) are exact and stay fixed.
  if (f != "abs" && f != "min" && f != "max" && f != "clamp") return false;
  const Type* format = nullptr;
  for (const ExprPtr& a : e.args) {
    const Type& t = a->type;
    if (isFixed(t) && format && t != *format) {
      err(a->loc, f + "() cannot mix " + typeName(*format) + " and " + typeName(t) +
                      ": values of two fixed-point formats meet only after a conversion, e.g. " + typeName(*format) + "(x)");
      e.type = Type::of(BaseType::Void);
      return true;
    }
    if (isFixed(t)) format = &t;
    else if (t != Type::of(BaseType::Int)) return false;  // a float or a vector: computed in floats
  }
  const size_t arity = f == "abs" ? 1 : f == "clamp" ? 3 : 2;
  if (e.args.size() != arity) return false;  // typeBuiltinCall reports it
  e.type = *format;
  return true;
}

}  // namespace pf::analysis
