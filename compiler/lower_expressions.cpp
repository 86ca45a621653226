// Lowering of expressions (the Lowerer, lowerer.h): literals, names, components and elements
// (run-time indices as selects), operators and arithmetic, the built-in functions -- the
// componentwise maths, geometry, noise, fields, facing, the coordinate transforms by the
// state's matrices -- constructors, and calls of user functions and of other primitives.
#include "compiler/builtins.h"
#include "compiler/compiler.h"
#include "compiler/lowerer.h"

#include <algorithm>
#include <bit>

namespace pf::lowering {

Binding Lowerer::scalar(Type t, int v) {
  Binding b;
  b.type = t;
  b.comps.push_back(v);
  return b;
}

Binding Lowerer::expr(const Expr& e) {
  NestingGuard guard(*this, e.loc);
  if (++lowered_expressions_ > kMaxLoweredExpressions)
    refuse(e.loc, "the program grows past " + std::to_string(kMaxLoweredExpressions) +
                      " operations once its functions are inlined");
  SourceLoc saved = cur_loc_;
  cur_loc_ = e.loc;  // instructions carry the expression they come from
  Binding b = exprAt(e);
  cur_loc_ = saved;
  return b;
}

Binding Lowerer::exprAt(const Expr& e) {
  switch (e.kind) {
    case ExprKind::IntLit: return scalar(e.type, constI(static_cast<int32_t>(e.number)));
    case ExprKind::FloatLit: return scalar(e.type, constF(static_cast<float>(e.number)));
    case ExprKind::BoolLit: return scalar(e.type, constB(e.boolean));
    case ExprKind::Name: return bindings_[lookup(e.name)];
    case ExprKind::Member: {
      Binding b = expr(*e.args[0]);
      return scalar(e.type, b.comps[static_cast<size_t>(e.number)]);
    }
    case ExprKind::Index: {
      Binding b = expr(*e.args[0]);
      if (b.sized_param != -1) return loadSized(b, expr(*e.args[1]).comps[0], e.type);
      Binding out;
      out.type = e.type;
      int esz = b.type.indexedSlots();
      if (e.number >= 0) {
        int idx = static_cast<int>(e.number);
        out.comps.assign(b.comps.begin() + idx * esz, b.comps.begin() + (idx + 1) * esz);
        return out;
      }
      // A run-time index: a select over the elements, from zero (what an index outside the
      // array reads).
      int index = expr(*e.args[1]).comps[0];
      int elements = static_cast<int>(b.comps.size()) / esz;
      for (int k = 0; k < esz; ++k) out.comps.push_back(zeroLike(b.comps[k]));
      for (int i = 0; i < elements; ++i) {
        int hit = emit(Op::IEq, ValueClass::Bool, false, index, constI(i));
        for (int k = 0; k < esz; ++k) out.comps[k] = select(hit, b.comps[i * esz + k], out.comps[k]);
      }
      return out;
    }
    case ExprKind::Unary: {
      Binding a = expr(*e.args[0]);
      if (e.name == "!") return scalar(e.type, emit(Op::BNot, ValueClass::Bool, false, a.comps[0]));
      if (a.type.isFixed()) return fixedNegate(a);
      Binding out;
      out.type = e.type;
      for (int c : a.comps) {
        ValueClass k = cls(c);
        Op op = k == ValueClass::Interp ? Op::XNeg : k == ValueClass::I32 ? Op::INeg : Op::FNeg;
        out.comps.push_back(emit(op, k, false, c, -1, -1, op == Op::XNeg ? static_cast<int>(interp_kinds_) : 0));
      }
      return out;
    }
    case ExprKind::Binary: return binary(e);
    case ExprKind::Ternary: {
      int c = expr(*e.args[0]).comps[0];
      Binding a = expr(*e.args[1]);
      Binding b = expr(*e.args[2]);
      std::vector<int> ac = convert(a, e.type), bc = convert(b, e.type);
      Binding out;
      out.type = e.type;
      for (size_t k = 0; k < ac.size(); ++k) out.comps.push_back(select(c, ac[k], bc[k]));
      return out;
    }
    case ExprKind::Call: return call(e);
  }
  return {};
}

Binding Lowerer::binary(const Expr& e) {
  const std::string& op = e.name;
  Binding a = expr(*e.args[0]);
  Binding b = expr(*e.args[1]);
  if (op == "&&" || op == "||")
    return scalar(e.type, emit(op == "&&" ? Op::BAnd : Op::BOr, ValueClass::Bool, false, a.comps[0], b.comps[0]));
  if (op == "<" || op == "<=" || op == ">" || op == ">=" || op == "==" || op == "!=") {
    if (a.type.isFixed() || b.type.isFixed()) return scalar(e.type, fixedCompare(op, a, b));
    int x = a.comps[0], y = b.comps[0];
    bool ints = (cls(x) == ValueClass::I32 && cls(y) == ValueClass::I32) ||
                (cls(x) == ValueClass::Bool && cls(y) == ValueClass::Bool);
    if (!ints) {
      x = toFloat(x);
      y = toFloat(y);
    }
    if (op == ">" || op == ">=") std::swap(x, y);
    Op o = op == "<" || op == ">"   ? (ints ? Op::ILt : Op::FLt)
           : op == "<=" || op == ">=" ? (ints ? Op::ILe : Op::FLe)
           : op == "=="               ? (ints ? Op::IEq : Op::FEq)
                                      : (ints ? Op::INe : Op::FNe);
    return scalar(e.type, emit(o, ValueClass::Bool, false, x, y));
  }
  // A matrix times a matrix, point, vector or normal (sema typed it as the right operand).
  if (op == "*" && e.args[0]->type.base == BaseType::Matrix && e.args[1]->type.base != BaseType::Float &&
      e.args[1]->type.base != BaseType::Int)
    return matrixTimes(a, b, e.type);
  return arith(op, a, b, e.type, e.loc);
}

Binding Lowerer::arith(const std::string& op, const Binding& a, const Binding& b, const Type& result, SourceLoc loc) {
  if (a.type.isFixed() || b.type.isFixed()) return fixedArith(op, a, b, result, loc);
  Binding out;
  out.type = result;
  if (result.base == BaseType::Void) return out;
  if (result.base == BaseType::InterpData) {
    int x = a.comps[0], y = b.comps[0];
    int kinds = static_cast<int>(interp_kinds_);
    if (cls(x) != ValueClass::Interp) std::swap(x, y);  // float * interp
    Op o = op == "+" ? Op::XAdd : op == "-" ? Op::XSub : op == "*" ? Op::XMulF : Op::XDivF;
    if (o == Op::XMulF || o == Op::XDivF) y = toFloat(y);
    out.comps.push_back(emit(o, ValueClass::Interp, false, x, y, -1, kinds, loc));
    return out;
  }
  bool ints = result.base == BaseType::Int;
  size_t n = std::max(a.comps.size(), b.comps.size());
  // point +/- vector: x, y, z move, w is the point's.
  int point_w = -1;
  if (result.base == BaseType::Point && std::min(a.comps.size(), b.comps.size()) == 3) {
    point_w = (a.comps.size() == 4 ? a : b).comps[3];
    n = 3;
  }
  for (size_t k = 0; k < n; ++k) {
    int x = a.comps[a.comps.size() == 1 ? 0 : k];
    int y = b.comps[b.comps.size() == 1 ? 0 : k];
    if (!ints) {
      x = toFloat(x);
      y = toFloat(y);
    }
    Op o;
    if (op == "+") o = ints ? Op::IAdd : Op::FAdd;
    else if (op == "-") o = ints ? Op::ISub : Op::FSub;
    else if (op == "*") o = ints ? Op::IMul : Op::FMul;
    else if (op == "/") o = ints ? Op::IDiv : Op::FDiv;
    else o = Op::IMod;
    if (o == Op::IMod && !ints) {
      // float remainder: x - y * floor(x / y)
      int q = emit(Op::FFloor, ValueClass::F32, false, emit(Op::FDiv, ValueClass::F32, false, x, y));
      out.comps.push_back(emit(Op::FSub, ValueClass::F32, false, x, emit(Op::FMul, ValueClass::F32, false, y, q)));
      continue;
    }
    out.comps.push_back(emit(o, ints ? ValueClass::I32 : ValueClass::F32, false, x, y));
  }
  if (point_w >= 0) out.comps.push_back(point_w);
  return out;
}

Binding Lowerer::vec(const Type& t, std::vector<int> comps) {
  Binding b;
  b.type = t;
  b.comps = std::move(comps);
  return b;
}

int Lowerer::dot3(const Binding& a, const Binding& b) {
  int s = fmul(toFloat(a.comps[0]), toFloat(b.comps[0]));
  for (int i = 1; i < 3; ++i) s = fadd(s, fmul(toFloat(a.comps[i]), toFloat(b.comps[i])));
  return s;
}

Binding Lowerer::sub3(const Binding& a, const Binding& b) {
  Binding d;
  d.type = Type::of(BaseType::Vector);
  for (int i = 0; i < 3; ++i) d.comps.push_back(fsub(toFloat(a.comps[i]), toFloat(b.comps[i])));
  return d;
}

Binding Lowerer::componentwise(const Expr& e, const std::vector<Binding>& args, int arity) {
  const std::string& f = e.name;
  bool ints = e.type.base == BaseType::Int;
  int n = e.type.base == BaseType::Float || ints ? 1 : Type::componentsOf(e.type.base);
  Binding out;
  out.type = e.type;
  for (int k = 0; k < n; ++k) {
    int x[3];
    for (int i = 0; i < arity; ++i) {
      const std::vector<int>& c = args[static_cast<size_t>(i)].comps;
      x[i] = c.size() == 1 ? c[0] : c[static_cast<size_t>(k)];
      if (!ints) x[i] = toFloat(x[i]);
    }
    int r;
    if (f == "abs") r = emit(ints ? Op::IAbs : Op::FAbs, ints ? ValueClass::I32 : ValueClass::F32, false, x[0]);
    else if (f == "min") r = emit(ints ? Op::IMin : Op::FMin, ints ? ValueClass::I32 : ValueClass::F32, false, x[0], x[1]);
    else if (f == "max") r = emit(ints ? Op::IMax : Op::FMax, ints ? ValueClass::I32 : ValueClass::F32, false, x[0], x[1]);
    else if (f == "floor") r = emit(Op::FFloor, ValueClass::F32, false, x[0]);
    else if (f == "ceil") r = emit(Op::FCeil, ValueClass::F32, false, x[0]);
    else if (f == "fract") r = fsub(x[0], emit(Op::FFloor, ValueClass::F32, false, x[0]));
    else if (f == "sqrt") r = emit(Op::FSqrt, ValueClass::F32, false, x[0]);
    else if (f == "sign") r = emit(Op::FSign, ValueClass::F32, false, x[0]);
    else if (f == "sin") r = emit(Op::FSin, ValueClass::F32, false, x[0]);
    else if (f == "cos") r = emit(Op::FCos, ValueClass::F32, false, x[0]);
    else if (f == "tan") r = emit(Op::FTan, ValueClass::F32, false, x[0]);
    else if (f == "asin") r = emit(Op::FAsin, ValueClass::F32, false, x[0]);
    else if (f == "acos") r = emit(Op::FAcos, ValueClass::F32, false, x[0]);
    else if (f == "atan") r = emit(Op::FAtan, ValueClass::F32, false, x[0]);
    else if (f == "exp") r = emit(Op::FExp, ValueClass::F32, false, x[0]);
    else if (f == "log") r = emit(Op::FLog, ValueClass::F32, false, x[0]);
    else if (f == "pow") r = emit(Op::FPow, ValueClass::F32, false, x[0], x[1]);
    else if (f == "atan2") r = emit(Op::FAtan2, ValueClass::F32, false, x[0], x[1]);
    else if (f == "mod") {  // x - y floor(x / y), as GLSL
      r = fsub(x[0], fmul(x[1], emit(Op::FFloor, ValueClass::F32, false, emit(Op::FDiv, ValueClass::F32, false, x[0], x[1]))));
    } else if (f == "step") {  // x < edge ? 0 : 1
      r = emit(Op::Sel, ValueClass::F32, false, emit(Op::FLt, ValueClass::Bool, false, x[1], x[0]), constF(0.0f), constF(1.0f));
    } else if (f == "clamp") {
      r = emit(Op::FMin, ValueClass::F32, false, emit(Op::FMax, ValueClass::F32, false, x[0], x[1]), x[2]);
    } else if (f == "mix") {  // a + (b - a) t
      r = fadd(x[0], fmul(fsub(x[1], x[0]), x[2]));
    } else {  // smoothstep(e0, e1, x): t = clamp((x - e0) / (e1 - e0)); t t (3 - 2 t)
      int t = emit(Op::FDiv, ValueClass::F32, false, fsub(x[2], x[0]), fsub(x[1], x[0]));
      t = emit(Op::FMin, ValueClass::F32, false, emit(Op::FMax, ValueClass::F32, false, t, constF(0.0f)), constF(1.0f));
      r = fmul(fmul(t, t), fsub(constF(3.0f), fmul(constF(2.0f), t)));
    }
    out.comps.push_back(r);
  }
  return out;
}

bool Lowerer::isConstF(int v, float x) const {
  return v >= 0 && f_.values[v].origin == Value::Origin::Const && f_.values[v].bits == std::bit_cast<uint32_t>(x);
}

int Lowerer::transformTerm(int a, int b) {
  if (isConstF(b, 0.0f)) return -1;
  if (isConstF(b, 1.0f)) return a;
  return emit(Op::FMul, ValueClass::F32, false, a, b);
}

int Lowerer::sumTerms(int sum, int term) {
  if (term < 0) return sum;
  return sum < 0 ? term : emit(Op::FAdd, ValueClass::F32, false, sum, term);
}

Binding Lowerer::scalarMatrixTimes(const Type& type, StateValue m, const std::vector<int>& v, int n, bool transposed) {
  Binding out;
  out.type = type;
  for (int row = 0; row < n; ++row) {
    int sum = -1;
    for (int col = 0; col < n; ++col) {
      const int element = transposed ? row * 4 + col : col * 4 + row;
      sum = sumTerms(sum, transformTerm(state(static_cast<StateValue>(static_cast<int>(m) + element)), v[col]));
    }
    out.comps.push_back(sum < 0 ? constF(0.0f) : sum);
  }
  return out;
}

int Lowerer::frontFacing(int orientation) {
  int ccw_area = emit(Op::FLt, ValueClass::Bool, false, constF(0.0f), orientation);
  int ccw_front = stateOn(StateValue::FrontFaceCCW);
  return emit(Op::BOr, ValueClass::Bool, false, emit(Op::BAnd, ValueClass::Bool, false, ccw_area, ccw_front),
              emit(Op::BAnd, ValueClass::Bool, false, emit(Op::BNot, ValueClass::Bool, false, ccw_area),
                   emit(Op::BNot, ValueClass::Bool, false, ccw_front)));
}

Binding Lowerer::callPrimitive(const Expr& e, const CompiledPrimitive& callee) {
  std::vector<Binding> args;
  for (const ExprPtr& a : e.args) args.push_back(expr(*a));
  auto found = std::find(f_.callees.begin(), f_.callees.end(), callee.name);
  int index = static_cast<int>(found - f_.callees.begin());
  if (found == f_.callees.end()) f_.callees.push_back(callee.name);
  for (size_t i = 0; i < callee.signature.size() && i < args.size(); ++i) {
    const Type& type = callee.signature[i].second;
    if (type.base == BaseType::InterpData) {
      for (int j = 0; j < type.dims[0]; ++j) emitEffect(Op::OutVertex, args[i].comps[j], -1, -1, -1, j, e.loc);
      continue;
    }
    const ParamInfo* info = callee.findParam(callee.signature[i].first);
    std::vector<int> comps = convert(args[i], type);
    for (size_t k = 0; info && k < comps.size(); ++k)
      emitEffect(Op::OutParam, comps[k], -1, -1, -1, info->offset + static_cast<int>(k), e.loc);
  }
  emitEffect(Op::Emit, -1, -1, -1, -1, index, e.loc);
  Binding none;
  none.type = Type::of(BaseType::Void);
  return none;
}

Binding Lowerer::call(const Expr& e) {
  const std::string& f = e.name;
  auto user = functions_.find(f);
  if (user != functions_.end()) return callFunction(e, *user->second);
  auto prim = primitives_.find(f);
  if (prim != primitives_.end()) return callPrimitive(e, *prim->second);
  std::vector<Binding> args;
  for (const ExprPtr& a : e.args) args.push_back(expr(*a));
  auto arg = [&](size_t i) { return args[i].comps[0]; };
  auto farg = [&](size_t i) { return toFloat(args[i].comps[0]); };
  if (std::optional<Binding> q = fixedCall(e, args)) return *q;
  if (int k = componentwiseArity(f)) return componentwise(e, args, k);
  if (std::optional<Binding> m = matrixCall(f, e, args)) return *m;
  if (f == "cross_sign") {
    // sign(a * d - b * c), exact: the robust orientation test for edges.
    Value v;
    v.cls = ValueClass::F32;
    int a0 = farg(0), a1 = farg(1), a2 = farg(2), a3 = farg(3);
    v.varying = isVarying(a0) || isVarying(a1) || isVarying(a2) || isVarying(a3);
    int dst = newValue(v);
    IrNode n;
    n.inst = IrInst{Op::CrossSign, dst, a0, a1, a2, a3, 0, e.loc};
    blocks_.back()->push_back(std::move(n));
    return scalar(e.type, dst);
  }
  if (f == "dot") return scalar(e.type, dot3(args[0], args[1]));
  if (f == "length") return scalar(e.type, emit(Op::FSqrt, ValueClass::F32, false, dot3(args[0], args[0])));
  if (f == "distance") {
    Binding d = sub3(args[0], args[1]);
    return scalar(e.type, emit(Op::FSqrt, ValueClass::F32, false, dot3(d, d)));
  }
  if (f == "cross") {
    auto c = [&](int i) { return toFloat(args[0].comps[i]); };
    auto d = [&](int i) { return toFloat(args[1].comps[i]); };
    auto diff = [&](int a0, int b0, int a1, int b1) {
      return fsub(fmul(c(a0), d(b0)), fmul(c(a1), d(b1)));
    };
    return vec(e.type, {diff(1, 2, 2, 1), diff(2, 0, 0, 2), diff(0, 1, 1, 0)});
  }
  if (f == "normalize") {
    int inv = emit(Op::FDiv, ValueClass::F32, false, constF(1.0f),
                   emit(Op::FSqrt, ValueClass::F32, false, dot3(args[0], args[0])));
    std::vector<int> out;
    for (int i = 0; i < 3; ++i) out.push_back(fmul(toFloat(args[0].comps[i]), inv));
    return vec(e.type, out);
  }
  if (f == "reflect") {  // I - 2 dot(N, I) N
    int k = fmul(constF(2.0f), dot3(args[1], args[0]));
    std::vector<int> out;
    for (int i = 0; i < 3; ++i) out.push_back(fsub(toFloat(args[0].comps[i]), fmul(k, toFloat(args[1].comps[i]))));
    return vec(e.type, out);
  }
  if (f == "refract") {  // GLSL: 0 on total internal reflection
    int eta = farg(2);
    int ni = dot3(args[1], args[0]);
    int k = fsub(constF(1.0f), fmul(fmul(eta, eta), fsub(constF(1.0f), fmul(ni, ni))));
    int tir = emit(Op::FLt, ValueClass::Bool, false, k, constF(0.0f));
    int m = fadd(fmul(eta, ni), emit(Op::FSqrt, ValueClass::F32, false, emit(Op::FMax, ValueClass::F32, false, k, constF(0.0f))));
    std::vector<int> out;
    for (int i = 0; i < 3; ++i) {
      int r = fsub(fmul(eta, toFloat(args[0].comps[i])), fmul(m, toFloat(args[1].comps[i])));
      out.push_back(emit(Op::Sel, ValueClass::F32, false, tir, constF(0.0f), r));
    }
    return vec(e.type, out);
  }
  if (f == "faceforward") {  // dot(Nref, I) < 0 ? N : -N
    int front = emit(Op::FLt, ValueClass::Bool, false,
                     dot3(args[2], args[1]), constF(0.0f));
    std::vector<int> out;
    for (int i = 0; i < 3; ++i) {
      int n = toFloat(args[0].comps[i]);
      out.push_back(emit(Op::Sel, ValueClass::F32, false, front, n, emit(Op::FNeg, ValueClass::F32, false, n)));
    }
    return vec(e.type, out);
  }
  if (f == "noise" || f == "snoise") {
    const std::vector<int>& c = args[0].comps;
    int x = toFloat(c[0]);
    int y = c.size() > 1 ? toFloat(c[1]) : constF(0.0f);
    int z = c.size() > 2 ? toFloat(c[2]) : constF(0.0f);
    int v = emit(Op::FNoise, ValueClass::F32, false, x, y, z);
    if (f == "noise") v = fadd(fmul(v, constF(0.5f)), constF(0.5f));  // [0, 1]
    return scalar(e.type, v);
  }
  if (f == "float") return scalar(e.type, farg(0));
  if (f == "int")
    return scalar(e.type, cls(arg(0)) == ValueClass::I32 ? arg(0) : emit(Op::F2I, ValueClass::I32, false, arg(0)));
  // (imm 1: a polygon's fragment, which the polygon stipple tests too.)
  if (f == "ztest" || f == "polygon_ztest")
    return scalar(e.type, emit(Op::ZTest, ValueClass::Bool, true, farg(0), -1, -1, f == "ztest" ? 0 : 1, e.loc));
  if (f == "field_hit") {
    // The box goes to the executor first (FieldBox), then the search (FieldHit), in order.
    for (int end = 0; end < 2; ++end) {
      const std::vector<int>& c = args[1 + end].comps;
      emitEffect(Op::FieldBox, toFloat(c[0]), toFloat(c[1]), toFloat(c[2]), -1, end, e.loc);
    }
    return scalar(e.type, emit(Op::FieldHit, ValueClass::F32, true, farg(0), farg(3), farg(4), 0, e.loc));
  }
  if (f == "field_gradient" || f == "field_gradient_fd") {
    const std::vector<int>& c = args[1].comps;
    const int field = farg(0);
    const int by_differences = f == "field_gradient_fd" ? 4 : 0;
    std::vector<int> out;
    for (int k = 0; k < 3; ++k) {
      int g = emit(Op::FieldGradient, ValueClass::F32, true, toFloat(c[0]), toFloat(c[1]), toFloat(c[2]),
                   k | by_differences, e.loc);
      blocks_.back()->back().inst.d = field;  // the field: the fourth operand
      out.push_back(g);
    }
    return vec(e.type, out);
  }
  if (f == "field_color") {
    const std::vector<int>& c = args[1].comps;
    const int field = farg(0);
    std::vector<int> out;
    for (int k = 0; k < 3; ++k) {
      int v = emit(Op::FieldColor, ValueClass::F32, true, toFloat(c[0]), toFloat(c[1]), toFloat(c[2]), k, e.loc);
      blocks_.back()->back().inst.d = field;  // the field: the fourth operand
      out.push_back(v);
    }
    out.push_back(constF(1.0f));
    return vec(e.type, out);
  }
  if (f == "culled") {
    int front = frontFacing(farg(0));
    return scalar(e.type, emit(Op::Sel, ValueClass::Bool, false, front, stateOn(StateValue::CullFront),
                               stateOn(StateValue::CullBack)));
  }
  if (f == "depth_bound") {
    emitEffect(Op::DepthBound, farg(0), farg(1), -1, -1, 0, e.loc);
    Binding none;
    none.type = Type::of(BaseType::Void);
    return none;
  }
  if (f == "facing") {
    emitEffect(Op::BackFacing, emit(Op::BNot, ValueClass::Bool, false, frontFacing(farg(0))), -1, -1, -1, 0, e.loc);
    Binding none;
    none.type = Type::of(BaseType::Void);
    return none;
  }
  if (f == "flat_shading") return scalar(e.type, stateOn(StateValue::FlatShading));
  if (f == "polygon_stipple") return scalar(e.type, stateOn(StateValue::PolygonStippleOn));
  if (f == "line_width") return scalar(e.type, state(StateValue::LineWidth));
  if (f == "point_size") return scalar(e.type, state(StateValue::PointSize));
  if (f == "unscreen") {
    // x = (X - w * offset) / scale, per axis; w stays.
    const std::vector<int>& p = args[0].comps;
    // (A literal 0 for w skips its term, and then a literal 0 component stays 0.)
    auto inverse = [&](int comp, StateValue scale, StateValue offset) {
      const int o = transformTerm(state(offset), p[3]);
      if (o < 0 && isConstF(p[comp], 0.0f)) return p[comp];
      const int shifted = o < 0 ? p[comp] : emit(Op::FSub, ValueClass::F32, false, p[comp], o);
      return emit(Op::FDiv, ValueClass::F32, false, shifted, state(scale));
    };
    Binding out;
    out.type = e.type;
    out.comps = {inverse(0, StateValue::ViewportScaleX, StateValue::ViewportOffsetX),
                 inverse(1, StateValue::ViewportScaleY, StateValue::ViewportOffsetY),
                 inverse(2, StateValue::DepthScale, StateValue::DepthOffset), p[3]};
    return out;
  }
  if (f == "eye" || f == "clip" || f == "object" || f == "eye_from_object") {
    // A 4x4 matrix of the state times the point (homogeneous; divide by w).
    const StateValue m = f == "eye" ? StateValue::InvProjection : f == "clip" ? StateValue::Projection
                         : f == "object" ? StateValue::InvModelview : StateValue::Modelview;
    return scalarMatrixTimes(e.type, m, args[0].comps, 4, false);
  }
  if (f == "eye_normal") {
    // The transpose of the inverse modelview's upper 3x3 times the normal.
    return scalarMatrixTimes(e.type, StateValue::InvModelview, args[0].comps, 3, true);
  }
  if (f == "polygon_mode") {
    return scalar(e.type, emit(Op::Sel, ValueClass::F32, false, frontFacing(farg(0)), state(StateValue::PolygonModeFront),
                               state(StateValue::PolygonModeBack)));
  }
  if (f == "polygon_offset") {
    Binding out;
    out.type = e.type;
    out.comps = {state(StateValue::OffsetFactor), state(StateValue::OffsetUnits), constF(0.0f)};
    return out;
  }
  if (f == "polygon_offset_modes") {
    Binding out;
    out.type = e.type;
    out.comps = {state(StateValue::OffsetFill), state(StateValue::OffsetLine), state(StateValue::OffsetPoint)};
    return out;
  }
  if (f == "line_stipple") {
    Binding out;
    out.type = e.type;
    out.comps = {state(StateValue::LineStipplePattern), state(StateValue::LineStippleFactor),
                 state(StateValue::LineStippleOn)};
    return out;
  }
  if (f == "depth_range") {
    Binding out;
    out.type = e.type;
    out.comps = {state(StateValue::DepthNear), state(StateValue::DepthFar), constF(0.0f)};
    return out;
  }
  if (f == "screen") {
    // Homogeneous screen space: the viewport transform applied to (x, y, z, w) without the
    // division by w, so that 2D-homogeneous rasterization works for vertices behind the eye.
    const std::vector<int>& p = args[0].comps;
    auto affine = [&](int comp, StateValue scale, StateValue offset) {
      const int sum = sumTerms(transformTerm(state(scale), p[comp]), transformTerm(state(offset), p[3]));
      return sum < 0 ? constF(0.0f) : sum;
    };
    Binding out;
    out.type = e.type;
    out.comps = {affine(0, StateValue::ViewportScaleX, StateValue::ViewportOffsetX),
                 affine(1, StateValue::ViewportScaleY, StateValue::ViewportOffsetY),
                 affine(2, StateValue::DepthScale, StateValue::DepthOffset), p[3]};
    return out;
  }
  // constructors: point(x, y, z[, w]), vector(x, y, z), normal(x, y, z), color(r, g, b[, a])
  Binding out;
  out.type = e.type;
  int comps = Type::componentsOf(e.type.base);
  if (args.size() == 1 && e.type.base != BaseType::Point) {  // vector(f), color(g): broadcast
    int v = farg(0);
    for (int i = 0; i < comps; ++i) out.comps.push_back(e.type.base == BaseType::Color && i == 3 ? constF(1.0f) : v);
    return out;
  }
  for (size_t i = 0; i < args.size(); ++i) out.comps.push_back(farg(i));
  while (static_cast<int>(out.comps.size()) < comps) out.comps.push_back(constF(1.0f));
  return out;
}

}  // namespace pf::lowering
