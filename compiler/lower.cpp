// Lowering from the AST to the IR. Variables do not exist in the IR: each assignment binds the
// variable's name to new Values, and an `if` ends with merge copies wherever the two branches
// left different bindings (SSA with the phis already placed as copies). A branch that ends in
// `return` contributes nothing to the merge: its pixels (or, when uniform, its instance) are gone.
//
// This file: the entry points (lowerPrimitive, lowerField), the set-up of a unit (built-ins,
// parameters, sequence points, the commits at its end) and the Lowerer's bindings and values
// (constants, instructions, parameter loads, conversions). The Lowerer is declared in lowerer.h.
#include "compiler/lower.h"

#include "compiler/lowerer.h"
#include "compiler/stack_guard.h"

#include <map>

namespace pf {
namespace lowering {

bool Lowerer::run(const Unit& u) {
  f_.name = u.name;
  interpolator_ = u.kind == UnitKind::Interpolator;
  scopes_.emplace_back();
  // Built-ins.
  bindBuiltin("X", kRegX, false);
  bindBuiltin("Y", kRegY, false);
  bindBuiltin("Z", kRegZ, true);
  bindBuiltin("P", kRegP, u.kind == UnitKind::Primitive, Type::of(BaseType::Point));
  bindBuiltin("N", kRegN, u.kind == UnitKind::Primitive, Type::of(BaseType::Normal));
  z_initial_ = bindings_[lookup("Z")].comps[0];
  n_initial_ = bindings_[lookup("N")].comps;
  scopes_.emplace_back();  // the parameters' scope: functions see scope 0 (built-ins) only
  // Parameters: array parameters are per sequence point (outermost index), the rest per
  // primitive. All per-sequence-point parameters must agree on the count; parameter-sized
  // ones (`[]`) take the instance's count, which an `int NAME_count` parameter receives.
  int seq = 0;
  bool sized = false;
  SourceLoc seq_loc;
  std::string seq_name;
  for (const Param& p : u.params) {
    if (p.name == "X" || p.name == "Y" || p.name == "Z" || !p.type.isArray()) continue;
    if (seq_name.empty()) {
      seq = p.type.dims[0];
      sized = p.type.isParameterSized();
      seq_loc = p.loc;
      seq_name = p.name;
    } else if (p.type.dims[0] != seq) {
      auto count = [](int n) { return n == 0 ? std::string("as many as given ([])") : std::to_string(n); };
      log_.error(p.loc, "parameter '" + p.name + "' has " + count(p.type.dims[0]) +
                            " sequence points, but '" + seq_name + "' at line " +
                            std::to_string(seq_loc.line) + " has " + count(seq) +
                            ": all array parameters are indexed by the instance's sequence points");
      return false;
    }
  }
  f_.sequence_points = sized ? 0 : seq > 0 ? seq : 1;
  blocks_.push_back(&f_.body);
  zero_interp_ = emit(Op::XLoadVertexAt, ValueClass::Interp, false, constI(-1));
  // The fixed part of the parameter block first, then (per instance) the parameter-sized arrays.
  std::vector<std::pair<const Param*, int>> later;  // parameter-sized, and their binding
  for (const Param& p : u.params) {
    if (p.name == "X" || p.name == "Y" || p.name == "Z") continue;
    Binding b;
    b.type = p.type;
    b.writable = false;
    if (p.type.isParameterSized()) {
      later.push_back({&p, static_cast<int>(bindings_.size())});
    } else if (p.type.base == BaseType::InterpData) {
      f_.has_interp_data = true;
      // The channels of every sequence point, loaded once at entry (dead ones are dropped).
      for (int i = 0; i < p.type.dims[0]; ++i)
        b.comps.push_back(emit(Op::XLoadVertex, ValueClass::Interp, false, -1, -1, -1, i));
    } else {
      ParamInfo info;
      info.name = p.name;
      info.type = p.type;
      info.per_sequence_point = p.type.isArray();
      info.offset = f_.param_floats;
      info.components = info.per_sequence_point ? p.type.slotCount() / p.type.dims[0] : p.type.slotCount();
      ValueClass cls = classOf(p.type.base);
      for (int k = 0; k < p.type.slotCount(); ++k) b.comps.push_back(paramValue(f_.param_floats + k, cls));
      f_.param_floats += p.type.slotCount();
      f_.params.push_back(info);
    }
    scopes_.back()[p.name] = static_cast<int>(bindings_.size());
    bindings_.push_back(std::move(b));
  }
  if (sized) {
    for (const ParamInfo& info : f_.params)
      if (info.type == Type::of(BaseType::Int) && info.name == seq_name + "_count") f_.count_slot = info.offset;
    if (f_.count_slot < 0) f_.count_slot = f_.param_floats++;  // not declared: a hidden slot
    for (auto [p, bind] : later) {
      if (p->type.base == BaseType::InterpData) {
        f_.has_interp_data = true;  // fed as the vertex channels, not in the parameter block
        bindings_[static_cast<size_t>(bind)].sized_param = kSizedInterpData;
        continue;
      }
      ParamInfo info{p->name, p->type, true, f_.sized_floats, p->type.element().slotCount(), true};
      f_.sized_floats += info.components;
      bindings_[static_cast<size_t>(bind)].sized_param = static_cast<int>(f_.params.size());
      f_.params.push_back(info);
    }
  }
  bool terminated = statements(u.body);
  if (!terminated) {
    int z = bindings_[lookup("Z")].comps[0];
    if (z != z_initial_) emitEffect(Op::ZCommit, z, -1, -1, -1, 0, u.loc);
    // A primitive that sets its normal N is lit per pixel: the surface point and normal of
    // each pixel go to the G-buffer for the shading pass.
    const std::vector<int>& n = bindings_[lookup("N")].comps;
    if (u.kind == UnitKind::Primitive && n != n_initial_) {
      const std::vector<int>& p = bindings_[lookup("P")].comps;
      emitEffect(Op::SurfaceCommit, p[0], p[1], p[2], p[3], 0, u.loc);
      emitEffect(Op::SurfaceCommit, n[0], n[1], n[2], -1, 1, u.loc);
      f_.writes_normal = true;
    }
  }
  return !log_.hasErrors();
}

bool Lowerer::runField(const Unit& u) {
  f_.name = u.name;
  scopes_.emplace_back();
  bindBuiltin("X", kRegX, false);
  bindBuiltin("Y", kRegY, false);
  bindBuiltin("Z", kRegZ, false);
  bindBuiltin("P", kRegP, false, Type::of(BaseType::Point));
  bindBuiltin("N", kRegN, false, Type::of(BaseType::Normal));
  blocks_.push_back(&f_.body);
  zero_interp_ = emit(Op::XLoadVertexAt, ValueClass::Interp, false, constI(-1));
  std::vector<Binding> args(u.params.size());
  args[0].type = Type::of(BaseType::Point);
  for (int k = 0; k < 3; ++k) {
    Value v;
    v.cls = ValueClass::F32;
    v.varying = true;
    v.origin = Value::Origin::FieldPoint;
    v.index = k;
    args[0].comps.push_back(newValue(v));
  }
  args[0].comps.push_back(constF(1.0f));
  for (size_t i = 1; i < u.params.size(); ++i) {
    ParamInfo info;
    info.name = u.params[i].name;
    info.type = u.params[i].type;
    info.per_sequence_point = false;
    info.offset = f_.param_floats;
    info.components = 1;
    args[i].type = u.params[i].type;
    args[i].comps.push_back(paramValue(f_.param_floats++, ValueClass::F32));
    f_.params.push_back(info);
  }
  Binding value = inlineFunction(u, args, u.loc);
  if (log_.hasErrors()) return false;
  emitEffect(Op::ShadeOut, value.comps[0], -1, -1, -1, 0, u.loc);
  return true;
}

int Lowerer::newValue(const Value& v) {
  f_.values.push_back(v);
  return static_cast<int>(f_.values.size()) - 1;
}

void Lowerer::bindBuiltin(const std::string& name, uint32_t reg, bool writable, Type type) {
  Binding b;
  b.type = type;
  for (int k = 0; k < type.slotCount(); ++k) {
    Value v;
    v.cls = ValueClass::F32;
    v.varying = true;
    v.origin = Value::Origin::Builtin;
    v.index = static_cast<int>(reg) + k;
    b.comps.push_back(newValue(v));
  }
  b.writable = writable;
  b.may_vary = true;
  scopes_.back()[name] = static_cast<int>(bindings_.size());
  bindings_.push_back(std::move(b));
}

int Lowerer::lookup(const std::string& name) const {
  for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
    auto f = it->find(name);
    if (f != it->end()) return f->second;
  }
  return -1;
}

int Lowerer::constant(ValueClass cls, uint32_t bits) {
  auto key = std::make_pair(static_cast<int>(cls), bits);
  auto it = constants_.find(key);
  if (it != constants_.end()) return it->second;
  Value v;
  v.cls = cls;
  v.origin = Value::Origin::Const;
  v.bits = bits;
  int id = newValue(v);
  constants_[key] = id;
  return id;
}

int Lowerer::emit(Op op, ValueClass c, bool varying, int a, int b, int cc, int imm, SourceLoc loc) {
  if (!loc.file) loc = cur_loc_;
  Value v;
  v.cls = c;
  v.varying = varying || isVarying(a) || isVarying(b) || isVarying(cc);
  int dst = newValue(v);
  IrNode n;
  n.inst = IrInst{op, dst, a, b, cc, -1, imm, loc};
  blocks_.back()->push_back(std::move(n));
  return dst;
}

void Lowerer::emitEffect(Op op, int a, int b, int c, int d, int imm, SourceLoc loc) {
  IrNode n;
  n.inst = IrInst{op, -1, a, b, c, d, imm, loc};
  blocks_.back()->push_back(std::move(n));
}

Binding Lowerer::loadSized(const Binding& array, int index, const Type& element) {
  Binding out;
  out.type = element;
  if (array.sized_param == kSizedInterpData) {
    out.comps.push_back(emit(Op::XLoadVertexAt, ValueClass::Interp, false, index));
    return out;
  }
  const ParamInfo& p = f_.params[static_cast<size_t>(array.sized_param)];
  ValueClass c = classOf(p.type.base);
  int count = paramValue(f_.count_slot, ValueClass::I32);
  int base = emit(Op::IAdd, ValueClass::I32, false, constI(f_.param_floats),
                  emit(Op::IMul, ValueClass::I32, false, count, constI(p.offset)));
  // An index outside [0, count) reads zeros: slot -1.
  int inside = emit(Op::BAnd, ValueClass::Bool, false, emit(Op::ILe, ValueClass::Bool, false, constI(0), index),
                    emit(Op::ILt, ValueClass::Bool, false, index, count));
  int first = emit(Op::IAdd, ValueClass::I32, false, base, emit(Op::IMul, ValueClass::I32, false, index, constI(p.components)));
  int slot = emit(Op::Sel, ValueClass::I32, false, inside, first, constI(-1));
  for (int k = 0; k < p.components; ++k) out.comps.push_back(emit(Op::LoadParamAt, c, false, slot, -1, -1, k));
  return out;
}

int Lowerer::paramValue(int slot, ValueClass c) {
  Value v;
  v.cls = c;
  v.origin = Value::Origin::Param;
  v.index = slot;
  return newValue(v);
}

int Lowerer::toFloat(int v) {
  if (cls(v) == ValueClass::F32) return v;
  if (f_.values[v].origin == Value::Origin::Const)
    return constF(static_cast<float>(static_cast<int32_t>(f_.values[v].bits)));
  return emit(Op::I2F, ValueClass::F32, false, v);
}

std::vector<int> Lowerer::convert(const Binding& from, const Type& to) {
  if (to.isFixed()) return toFixed(from, to).comps;
  if (from.type.isFixed() && to.dims.empty())
    return {to.base == BaseType::Int ? fixedToInt(from) : asFloat(from).comps[0]};
  std::vector<int> out = from.comps;
  if (to.base == BaseType::Float || (to.isAggregate() && to.base != BaseType::InterpData))
    for (int& c : out)
      if (cls(c) == ValueClass::I32) c = toFloat(c);
  return out;
}

Lowerer::NestingGuard::NestingGuard(Lowerer& lowerer, SourceLoc loc) : l(lowerer) {
  if (++l.nesting_ > kMaxLoweredNesting)
    l.refuse(loc, "nesting too deep once functions are inlined (more than " + std::to_string(kMaxLoweredNesting) +
                      " levels)");
  if (stackNearlyExhausted()) l.refuse(loc, "nesting too deep for this thread's stack once functions are inlined");
}

void Lowerer::refuse(SourceLoc loc, const std::string& what) {
  std::string msg = what;
  if (!inlining_.empty()) {
    // The chain of inlined calls, its ends when it is long: "p -> f9 -> f8 -> ... -> f1 -> f0".
    msg += ": " + f_.name;
    const size_t n = inlining_.size();
    for (size_t i = 0; i < n; ++i) {
      if (n > 8 && i == 4) {
        msg += " -> ... (" + std::to_string(n - 8) + " more)";
        i = n - 4;
      }
      msg += " -> " + inlining_[i]->name;
    }
  }
  log_.error(loc, msg);
  throw LoweringAbort{};
}

}  // namespace lowering

using lowering::Lowerer;
using lowering::LoweringAbort;

bool lowerPrimitive(const Unit& unit, const std::map<std::string, const Unit*>& functions,
                    const PrimitiveTable& primitives, IrFunction& out, DiagnosticLog& log) {
  Lowerer l(out, log, functions, primitives);
  try {
    return l.run(unit);
  } catch (const LoweringAbort&) {
    return false;
  }
}

bool lowerField(const Unit& unit, const std::map<std::string, const Unit*>& functions, IrFunction& out,
                DiagnosticLog& log) {
  const PrimitiveTable none;
  Lowerer l(out, log, functions, none);
  try {
    return l.runField(unit);
  } catch (const LoweringAbort&) {
    return false;
  }
}

}  // namespace pf
