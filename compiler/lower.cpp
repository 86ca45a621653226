// Lowering from the AST to the IR. Variables do not exist in the IR: each assignment binds the
// variable's name to new Values, and an `if` ends with merge copies wherever the two branches
// left different bindings (SSA with the phis already placed as copies). A branch that ends in
// `return` contributes nothing to the merge: its pixels (or, when uniform, its instance) are gone.
#include "compiler/lower.h"

#include "compiler/builtins.h"
#include "compiler/compiler.h"

#include <algorithm>
#include <bit>
#include <functional>
#include <map>

namespace pf {
namespace {

struct Binding {
  Type type;
  std::vector<int> comps;  // Value ids, one per scalar slot (per element for interpolator_data)
  bool writable = true;
  bool may_vary = false;   // sema's (conservative) verdict on the variable
  int sized_param = -1;    // a parameter-sized array (`T name[]`): its ParamInfo; no comps
};
constexpr int kSizedInterpData = -2;  // Binding::sized_param of `interpolator_data name[]`

// A loop being lowered: the values it carries from one iteration to the next, and what
// lowering learned about it (which decides whether it must be lowered again).
struct LoopContext {
  std::vector<std::pair<int, int>> slots;  // (binding, component)
  std::vector<int> merge;                   // the carried value of each slot
  bool function = false;        // the one-iteration loop of an inlined call: `return` leaves it
  int entry_varying_depth = 0;  // varying control around the loop
  bool varying_exit = false;    // a break / continue / return under varying control inside
  std::vector<size_t> violated; // slots classified uniform that received a varying value
};

// How a loop is lowered: its carried variables, and how to emit its parts.
struct LoopSpec {
  SourceLoc loc;
  bool varying = false;               // sema's first guess
  std::vector<int> carried_bindings;  // variables assigned in the loop
  bool function = false;
  std::function<int()> cond;          // emits the condition, returns its value (-1: always true)
  std::function<void()> body, step;
};

// The value class that holds one component of a base type.
ValueClass classOf(BaseType b) {
  return b == BaseType::Int ? ValueClass::I32 : b == BaseType::Bool ? ValueClass::Bool : ValueClass::F32;
}

// Whether a statement holds a `return` anywhere.
bool holdsReturn(const Stmt& s) {
  if (s.kind == StmtKind::Return) return true;
  for (const StmtPtr& c : s.body)
    if (holdsReturn(*c)) return true;
  for (const StmtPtr& c : s.else_body)
    if (holdsReturn(*c)) return true;
  for (const InterpolationCase& k : s.cases)
    for (const StmtPtr& c : k.body)
      if (holdsReturn(*c)) return true;
  return (s.init && holdsReturn(*s.init)) || (s.step && holdsReturn(*s.step));
}

// Whether a function body returns a value at its last statement and nowhere else.
bool returnsOnlyAtEnd(const std::vector<StmtPtr>& body) {
  if (body.empty() || body.back()->kind != StmtKind::Return || !body.back()->value) return false;
  for (size_t i = 0; i + 1 < body.size(); ++i)
    if (holdsReturn(*body[i])) return false;
  return true;
}

// Names assigned anywhere in a statement (targets' root variables).
void assignedNames(const Stmt& s, std::vector<std::string>& out) {
  if (s.kind == StmtKind::Assign) {
    const Expr* root = s.target.get();
    while (root->kind == ExprKind::Index || root->kind == ExprKind::Member) root = root->args[0].get();
    if (root->kind == ExprKind::Name) out.push_back(root->name);
  }
  for (const StmtPtr& c : s.body) assignedNames(*c, out);
  for (const StmtPtr& c : s.else_body) assignedNames(*c, out);
  for (const InterpolationCase& c : s.cases)
    for (const StmtPtr& b : c.body) assignedNames(*b, out);
  if (s.init) assignedNames(*s.init, out);
  if (s.step) assignedNames(*s.step, out);
}

class Lowerer {
 public:
  Lowerer(IrFunction& f, DiagnosticLog& log, const std::map<std::string, const Unit*>& functions,
          const PrimitiveTable& primitives)
      : f_(f), log_(log), functions_(functions), primitives_(primitives) {}

  bool run(const Unit& u) {
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

  // A field unit (docs/language.md, "Fields"): its point p is three FieldPoint values (w = 1),
  // its other parameters are the parameter block's slots, and its body is inlined as a
  // function's. The field's value leaves through ShadeOut, which keeps it alive through the
  // passes. The pixel built-ins are bound as in a primitive, for the functions a field calls:
  // the field tape translation (compiler/field/field_unit.cpp) rejects any use of them.
  bool runField(const Unit& u) {
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

 private:
  IrFunction& f_;
  DiagnosticLog& log_;
  const std::map<std::string, const Unit*>& functions_;
  const PrimitiveTable& primitives_;
  std::vector<std::map<std::string, int>> scopes_;
  std::vector<Binding> bindings_;
  std::vector<IrBlock*> blocks_;
  std::vector<LoopContext> loops_;
  int varying_depth_ = 0;
  InterpKindSet interp_kinds_ = kAllInterpKinds;
  int z_initial_ = -1;
  std::vector<int> n_initial_;
  SourceLoc cur_loc_;
  std::map<std::pair<int, uint32_t>, int> constants_;
  int zero_interp_ = -1;
  bool interpolator_ = false;  // lowering a shared interpolator: interpolator_return is its value

  int newValue(const Value& v) {
    f_.values.push_back(v);
    return static_cast<int>(f_.values.size()) - 1;
  }

  void bindBuiltin(const std::string& name, uint32_t reg, bool writable, Type type = Type::of(BaseType::Float)) {
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

  int lookup(const std::string& name) const {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
      auto f = it->find(name);
      if (f != it->end()) return f->second;
    }
    return -1;
  }

  int constant(ValueClass cls, uint32_t bits) {
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
  int constF(float x) { return constant(ValueClass::F32, std::bit_cast<uint32_t>(x)); }
  int constI(int32_t x) { return constant(ValueClass::I32, static_cast<uint32_t>(x)); }
  int constB(bool x) { return constant(ValueClass::Bool, x ? 1u : 0u); }

  bool isVarying(int v) const { return v >= 0 && f_.values[v].varying; }
  ValueClass cls(int v) const { return f_.values[v].cls; }

  int emit(Op op, ValueClass c, bool varying, int a, int b = -1, int cc = -1, int imm = 0,
           SourceLoc loc = {}) {
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
  void emitEffect(Op op, int a, int b, int c, int d, int imm, SourceLoc loc) {
    IrNode n;
    n.inst = IrInst{op, -1, a, b, c, d, imm, loc};
    blocks_.back()->push_back(std::move(n));
  }

  // Zero of the class of value v (interpolator_data: zero in every channel).
  int zeroLike(int v) { return cls(v) == ValueClass::Interp ? zeroInterp() : constant(cls(v), 0); }
  // Loaded once at entry (sequence point -1 reads zeros), so setup computes it for every use;
  // dead-code removal drops it where nothing uses it. (Emitted before any statement: a node
  // inserted later at the front would upset a loop's rollback, which truncates its block.)
  int zeroInterp() const { return zero_interp_; }

  // Element `index` of a parameter-sized array: loads from the instance's parameters, which sit
  // after the fixed part at F + count * offset + index * components (CompiledPrimitive::paramOffset).
  Binding loadSized(const Binding& array, int index, const Type& element) {
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

  int paramValue(int slot, ValueClass c) {
    Value v;
    v.cls = c;
    v.origin = Value::Origin::Param;
    v.index = slot;
    return newValue(v);
  }

  int toFloat(int v) {
    if (cls(v) == ValueClass::F32) return v;
    if (f_.values[v].origin == Value::Origin::Const)
      return constF(static_cast<float>(static_cast<int32_t>(f_.values[v].bits)));
    return emit(Op::I2F, ValueClass::F32, false, v);
  }

  // Converts a lowered value to the declared type `to` (int -> float where needed).
  std::vector<int> convert(const Binding& from, const Type& to) {
    std::vector<int> out = from.comps;
    if (to.base == BaseType::Float || (to.isAggregate() && to.base != BaseType::InterpData))
      for (int& c : out)
        if (cls(c) == ValueClass::I32) c = toFloat(c);
    return out;
  }

  // ---- statements: return true if the block always ends in `return` ----
  bool statements(const std::vector<StmtPtr>& body) {
    for (const StmtPtr& s : body)
      if (statement(*s)) return true;  // the rest is unreachable
    return false;
  }

  bool scoped(const std::vector<StmtPtr>& body) {
    scopes_.emplace_back();
    bool t = statements(body);
    scopes_.pop_back();
    return t;
  }

  bool statement(const Stmt& s) {
    switch (s.kind) {
      case StmtKind::Block:
        return s.op == "decls" ? statements(s.body) : scoped(s.body);
      case StmtKind::Decl: {
        Binding b;
        b.type = s.decl_type;
        b.may_vary = s.inferred_varying;
        if (s.value) {
          Binding v = expr(*s.value);
          b.comps = convert(v, s.decl_type);
        } else if (s.decl_type.base == BaseType::InterpData) {
          b.comps.assign(static_cast<size_t>(s.decl_type.elementCount()), zeroInterp());
        } else {
          // Locals start at zero, so no path can read an undefined value.
          ValueClass c = classOf(s.decl_type.base);
          int zero = constant(c, 0);
          b.comps.assign(s.decl_type.slotCount(), zero);
        }
        scopes_.back()[s.name] = static_cast<int>(bindings_.size());
        bindings_.push_back(std::move(b));
        return false;
      }
      case StmtKind::Assign: assign(s); return false;
      case StmtKind::ExprStmt: expr(*s.value); return false;
      case StmtKind::If: return ifStatement(s);
      case StmtKind::Return:
        if (s.value) return functionReturn(s);
        emitEffect(Op::Retire, -1, -1, -1, -1, 0, s.loc);
        return true;
      case StmtKind::Loop: loop(s); return false;
      case StmtKind::Break:
      case StmtKind::Continue:
        noteExit(1);
        carryCopies(s.loc);
        emitEffect(s.kind == StmtKind::Break ? Op::Break : Op::Continue, -1, -1, -1, -1, 1, s.loc);
        return true;
      case StmtKind::Bound: {
        int v[4];
        for (int i = 0; i < 4; ++i) v[i] = toFloat(expr(*s.bound_args[i]).comps[0]);
        emitEffect(Op::Bound, v[0], v[1], v[2], v[3], 0, s.loc);
        return false;
      }
      case StmtKind::Interpolation: {
        for (const InterpolationCase& c : s.cases) {
          InterpKindSet set = 0;
          for (InterpKind k : c.kinds) set |= 1u << static_cast<int>(k);
          f_.kinds_handled |= set;
          InterpKindSet save = interp_kinds_;
          interp_kinds_ = set;
          // The branch runs only for instances with channels of its kinds: a uniform if, so
          // neither setup nor the pixel program pays for interpolations nobody asked for.
          int has = emit(Op::HasKinds, ValueClass::Bool, false, -1, -1, -1, static_cast<int>(set), c.label_locs.front());
          bool t = false;
          branch(has, c.label_locs.front(), [&] { return t = scoped(c.body); }, [] { return false; });
          interp_kinds_ = save;
          if (t) {
            log_.error(c.label_locs.front(), "an interpolation branch cannot end in 'return': the other branches must still run");
            return false;
          }
        }
        return false;
      }
      case StmtKind::InterpReturn:
        if (interpolator_) {
          // A shared interpolator's value: 4 floats, missing components (0, 0, 0, 1).
          Binding b = expr(*s.value);
          int c[4] = {constF(0.0f), constF(0.0f), constF(0.0f), constF(1.0f)};
          for (size_t k = 0; k < b.comps.size() && k < 4; ++k) c[k] = toFloat(b.comps[k]);
          emitEffect(Op::ShadeOut, c[0], c[1], c[2], c[3], 0, s.loc);
          return false;
        }
        if (s.value) {
          int v = expr(*s.value).comps[0];
          emitEffect(Op::InterpReturn, v, -1, -1, -1, static_cast<int>(interp_kinds_), s.loc);
        } else {
          // The shared interpolators read the surface point P as it is here.
          const std::vector<int>& p = bindings_[lookup("P")].comps;
          emitEffect(Op::InterpShared, p[0], p[1], p[2], p[3], static_cast<int>(interp_kinds_), s.loc);
        }
        return false;
    }
    return false;
  }

  // The carried values of loop `index` (default: the innermost) take the current bindings.
  void carryCopies(SourceLoc loc, int index = -1) {
    if (loops_.empty()) return;
    LoopContext& l = loops_[index < 0 ? loops_.size() - 1 : static_cast<size_t>(index)];
    for (size_t i = 0; i < l.slots.size(); ++i) {
      int cur = bindings_[l.slots[i].first].comps[l.slots[i].second];
      int m = l.merge[i];
      if (cur == m) continue;
      if (isVarying(cur) && !isVarying(m)) l.violated.push_back(i);  // lowered again, varying
      IrNode n;
      n.inst = IrInst{cls(m) == ValueClass::Interp ? Op::XMov : Op::Mov, m, cur, -1, -1, -1,
                      static_cast<int>(kAllInterpKinds), loc};
      blocks_.back()->push_back(std::move(n));
    }
  }

  // Leaving `levels` loops under varying control makes each of them varying.
  void noteExit(int levels) {
    for (int k = 0; k < levels && k < static_cast<int>(loops_.size()); ++k) {
      LoopContext& l = loops_[loops_.size() - 1 - k];
      if (varying_depth_ > l.entry_varying_depth) l.varying_exit = true;
    }
  }

  // `return value;` in an inlined function: set the result and leave every loop up to the call.
  bool functionReturn(const Stmt& s) {
    int levels = 0, target = -1;
    for (int k = static_cast<int>(loops_.size()) - 1; k >= 0; --k) {
      ++levels;
      if (loops_[k].function) {
        target = k;
        break;
      }
    }
    if (target < 0) return false;  // sema reports a value returned from a primitive
    int result = lookup("$result");
    Binding v = expr(*s.value);
    bindings_[result].comps = convert(v, bindings_[result].type);
    noteExit(levels);
    carryCopies(s.loc, target);
    emitEffect(Op::Break, -1, -1, -1, -1, levels, s.loc);
    return true;
  }

  // Lowers a loop. Whether it is varying, and which carried values are, is first guessed from
  // sema; if lowering finds a varying value reaching a value guessed uniform, or a varying exit
  // from a loop guessed uniform, it lowers the loop again with that corrected (at most once per
  // carried value). That makes the classification exact per call site of inlined functions.
  void lowerLoop(const LoopSpec& spec) {
    bool loop_varying = spec.varying;
    std::vector<bool> forced;
    for (int attempt = 0;; ++attempt) {
      std::vector<Binding> saved = bindings_;
      size_t saved_size = blocks_.back()->size();
      LoopContext ctx;
      ctx.function = spec.function;
      ctx.entry_varying_depth = varying_depth_;
      size_t slot = 0;
      for (int b : spec.carried_bindings) {
        for (size_t k = 0; k < bindings_[b].comps.size(); ++k, ++slot) {
          if (forced.size() <= slot) forced.push_back(false);
          int cur = bindings_[b].comps[k];
          Value m;
          m.cls = cls(cur);
          m.varying = loop_varying || bindings_[b].may_vary || isVarying(cur) || forced[slot];
          int mid = newValue(m);
          IrNode init;
          init.inst = IrInst{m.cls == ValueClass::Interp ? Op::XMov : Op::Mov, mid, cur, -1, -1, -1,
                             static_cast<int>(kAllInterpKinds), spec.loc};
          blocks_.back()->push_back(std::move(init));
          bindings_[b].comps[k] = mid;
          ctx.slots.push_back({b, static_cast<int>(k)});
          ctx.merge.push_back(mid);
        }
      }
      IrNode node;
      node.kind = IrNode::Kind::Loop;
      node.inst.loc = spec.loc;
      node.varying_loop = loop_varying;
      node.cond_block = std::make_unique<IrBlock>();
      node.body_block = std::make_unique<IrBlock>();
      node.step_block = std::make_unique<IrBlock>();
      loops_.push_back(ctx);
      if (loop_varying) ++varying_depth_;
      blocks_.push_back(node.cond_block.get());
      int cond = spec.cond ? spec.cond() : -1;
      node.cond = cond >= 0 ? cond : constB(true);
      blocks_.pop_back();
      blocks_.push_back(node.body_block.get());
      spec.body();
      blocks_.pop_back();
      for (size_t i = 0; i < ctx.slots.size(); ++i)  // the continue point
        bindings_[ctx.slots[i].first].comps[ctx.slots[i].second] = ctx.merge[i];
      blocks_.push_back(node.step_block.get());
      if (spec.step) spec.step();
      carryCopies(spec.loc);
      blocks_.pop_back();
      if (loop_varying) --varying_depth_;
      LoopContext done = std::move(loops_.back());
      loops_.pop_back();

      bool again = false;
      if (!loop_varying && (isVarying(node.cond) || done.varying_exit)) {
        loop_varying = true;
        again = true;
      }
      for (size_t i : done.violated)
        if (!forced[i]) {
          forced[i] = true;
          again = true;
        }
      if (again && attempt < 64) {
        bindings_ = std::move(saved);
        blocks_.back()->resize(saved_size);
        continue;
      }
      for (size_t i = 0; i < done.slots.size(); ++i)  // after the loop
        bindings_[done.slots[i].first].comps[done.slots[i].second] = done.merge[i];
      blocks_.back()->push_back(std::move(node));
      return;
    }
  }

  // The variables among `names` visible here, once each.
  std::vector<int> visibleBindings(const std::vector<std::string>& names) const {
    std::vector<int> out;
    for (const std::string& n : names) {
      int b = lookup(n);
      if (b >= 0 && std::find(out.begin(), out.end(), b) == out.end()) out.push_back(b);
    }
    return out;
  }

  void loop(const Stmt& s) {
    scopes_.emplace_back();
    if (s.init) statement(*s.init);
    std::vector<std::string> names;
    assignedNames(s, names);
    LoopSpec spec;
    spec.loc = s.loc;
    spec.varying = s.varying_loop;
    spec.carried_bindings = visibleBindings(names);
    if (s.value) spec.cond = [&] { return expr(*s.value).comps[0]; };
    spec.body = [&] {
      if (!scoped(s.body)) carryCopies(s.loc);
    };
    if (s.step) spec.step = [&] { statement(*s.step); };
    lowerLoop(spec);
    scopes_.pop_back();
  }

  // A call of a user function, inlined: the body runs as a loop of one iteration whose result
  // is a carried value, so `return` anywhere (under varying control too) is a break.
  Binding callFunction(const Expr& e, const Unit& fn) {
    std::vector<Binding> args;
    for (const ExprPtr& a : e.args) args.push_back(expr(*a));
    return inlineFunction(fn, args, e.loc);
  }

  // The body of function (or field) `fn` inlined with `args` as its parameters' values.
  Binding inlineFunction(const Unit& fn, const std::vector<Binding>& args, SourceLoc call_loc) {
    Binding result;
    result.type = fn.return_type;
    if (fn.return_type.base == BaseType::InterpData) {
      log_.error(call_loc, "functions cannot return interpolator_data in this version of the language");
      return result;
    }
    // The function sees the built-ins (scope 0) and its own parameters, nothing of the caller.
    std::vector<std::map<std::string, int>> saved_scopes = std::move(scopes_);
    scopes_.clear();
    scopes_.push_back(saved_scopes.front());
    scopes_.emplace_back();
    for (size_t i = 0; i < fn.params.size(); ++i) {
      Binding b;
      b.type = fn.params[i].type;
      b.comps = convert(args[i], b.type);
      b.writable = true;
      scopes_.back()[fn.params[i].name] = static_cast<int>(bindings_.size());
      bindings_.push_back(std::move(b));
    }
    ValueClass rc = classOf(fn.return_type.base);
    result.comps.assign(fn.return_type.slotCount(), constant(rc, 0));
    scopes_.back()["$result"] = static_cast<int>(bindings_.size());
    bindings_.push_back(std::move(result));

    // A body whose only `return` is its last statement needs no loop: lowered straight, its
    // uniform work stays uniform (hoisted into setup), as if written at the call.
    if (returnsOnlyAtEnd(fn.body)) {
      scopes_.emplace_back();
      for (size_t i = 0; i + 1 < fn.body.size(); ++i) statement(*fn.body[i]);
      Binding value = expr(*fn.body.back()->value);
      scopes_.pop_back();
      Binding out = bindings_[lookup("$result")];
      out.comps = convert(value, out.type);
      out.writable = true;
      scopes_ = std::move(saved_scopes);
      return out;
    }
    std::vector<std::string> names = {"$result"};
    for (const StmtPtr& st : fn.body) assignedNames(*st, names);
    LoopSpec spec;
    spec.loc = call_loc;
    spec.function = true;
    spec.carried_bindings = visibleBindings(names);
    spec.body = [&] {
      if (!scoped(fn.body)) {  // sema makes every path return; stay safe regardless
        carryCopies(call_loc);
        emitEffect(Op::Break, -1, -1, -1, -1, 1, call_loc);
      }
    };
    lowerLoop(spec);
    Binding out = bindings_[lookup("$result")];
    out.writable = true;
    scopes_ = std::move(saved_scopes);
    return out;
  }

  bool ifStatement(const Stmt& s) {
    int cond = expr(*s.value).comps[0];
    return branch(cond, s.loc, [&] { return scoped(s.body); }, [&] { return scoped(s.else_body); });
  }

  // An if node on `cond`: each part lowers its branch and says whether it always returns;
  // variables the branches leave different get merge copies.
  bool branch(int cond, SourceLoc loc, const std::function<bool()>& then_part, const std::function<bool()>& else_part) {
    bool vary = isVarying(cond);
    IrNode node;
    node.kind = IrNode::Kind::If;
    node.cond = cond;
    node.inst.loc = loc;
    node.then_block = std::make_unique<IrBlock>();
    node.else_block = std::make_unique<IrBlock>();
    std::vector<Binding> before = bindings_;
    if (vary) ++varying_depth_;
    blocks_.push_back(node.then_block.get());
    bool then_done = then_part();
    blocks_.pop_back();
    std::vector<Binding> after_then = bindings_;
    bindings_ = before;
    blocks_.push_back(node.else_block.get());
    bool else_done = else_part();
    blocks_.pop_back();
    std::vector<Binding> after_else = std::move(bindings_);
    if (vary) --varying_depth_;

    bindings_ = before;
    for (size_t i = 0; i < before.size(); ++i) {
      for (size_t k = 0; k < before[i].comps.size(); ++k) {
        int t = after_then[i].comps[k], e = after_else[i].comps[k];
        if (then_done && else_done) break;
        if (then_done) { bindings_[i].comps[k] = e; continue; }
        if (else_done) { bindings_[i].comps[k] = t; continue; }
        if (t == e) { bindings_[i].comps[k] = t; continue; }
        // Merge: a new value assigned at the end of each branch.
        Value m;
        m.cls = cls(t);
        m.varying = vary || isVarying(t) || isVarying(e);
        int mid = newValue(m);
        Op mov = m.cls == ValueClass::Interp ? Op::XMov : Op::Mov;
        IrNode ct, ce;
        ct.inst = IrInst{mov, mid, t, -1, -1, -1, static_cast<int>(kAllInterpKinds), loc};
        ce.inst = IrInst{mov, mid, e, -1, -1, -1, static_cast<int>(kAllInterpKinds), loc};
        node.then_block->push_back(std::move(ct));
        node.else_block->push_back(std::move(ce));
        bindings_[i].comps[k] = mid;
      }
    }
    blocks_.back()->push_back(std::move(node));
    return then_done && else_done;
  }

  // Resolves an assignment target to its binding and the slots it may write: one candidate
  // range per element a run-time index can select, each with the condition (-1: always) under
  // which it is the one written. An index outside the array selects none: the write is lost.
  struct TargetSlots {
    int first;
    int cond;
  };
  bool target(const Expr& e, int& bind, std::vector<TargetSlots>& slots, int& count) {
    if (e.kind == ExprKind::Name) {
      bind = lookup(e.name);
      if (bind < 0) return false;
      slots = {{0, -1}};
      count = static_cast<int>(bindings_[bind].comps.size());
      return true;
    }
    if (!target(*e.args[0], bind, slots, count)) return false;
    const Type& bt = e.args[0]->type;
    if (e.kind == ExprKind::Member) {
      for (TargetSlots& t : slots) t.first += static_cast<int>(e.number);
      count = 1;
      return true;
    }
    int esz = bt.isArray() ? (bt.base == BaseType::InterpData ? 1 : bt.element().slotCount()) : 1;
    int elements = bt.isArray() ? bt.dims[0] : Type::componentsOf(bt.base);
    count = esz;
    if (e.number >= 0) {
      for (TargetSlots& t : slots) t.first += static_cast<int>(e.number) * esz;
      return true;
    }
    int index = expr(*e.args[1]).comps[0];
    std::vector<TargetSlots> out;
    for (const TargetSlots& t : slots)
      for (int k = 0; k < elements; ++k) {
        int hit = emit(Op::IEq, ValueClass::Bool, false, index, constI(k));
        int cond = t.cond < 0 ? hit : emit(Op::BAnd, ValueClass::Bool, false, t.cond, hit);
        out.push_back({t.first + k * esz, cond});
      }
    slots = std::move(out);
    return true;
  }

  // dst = cond ? a : b, for a value of any class.
  int select(int cond, int a, int b) {
    if (cls(a) == ValueClass::Interp)
      return emit(Op::XSel, ValueClass::Interp, false, cond, a, b, static_cast<int>(interp_kinds_));
    return emit(Op::Sel, cls(a), false, cond, a, b);
  }

  void assign(const Stmt& s) {
    int bind, count;
    std::vector<TargetSlots> slots;
    if (!target(*s.target, bind, slots, count)) return;
    Binding value;
    if (s.op == "=") {
      value = expr(*s.value);
    } else {
      Binding cur = expr(*s.target);
      Binding rhs = expr(*s.value);
      value = arith(s.op.substr(0, 1), cur, rhs, s.target->type, s.loc);
    }
    std::vector<int> comps = convert(value, s.target->type);
    if (static_cast<int>(comps.size()) != count) return;  // type error already reported
    std::vector<int>& dst = bindings_[bind].comps;
    for (const TargetSlots& t : slots)
      for (int k = 0; k < count; ++k)
        dst[t.first + k] = t.cond < 0 ? comps[k] : select(t.cond, comps[k], dst[t.first + k]);
  }

  // ---- expressions ----
  Binding scalar(Type t, int v) {
    Binding b;
    b.type = t;
    b.comps.push_back(v);
    return b;
  }

  Binding expr(const Expr& e) {
    SourceLoc saved = cur_loc_;
    cur_loc_ = e.loc;  // instructions carry the expression they come from
    Binding b = exprAt(e);
    cur_loc_ = saved;
    return b;
  }

  Binding exprAt(const Expr& e) {
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
        int esz = b.type.isArray() ? (b.type.base == BaseType::InterpData ? 1 : b.type.element().slotCount()) : 1;
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

  Binding binary(const Expr& e) {
    const std::string& op = e.name;
    Binding a = expr(*e.args[0]);
    Binding b = expr(*e.args[1]);
    if (op == "&&" || op == "||")
      return scalar(e.type, emit(op == "&&" ? Op::BAnd : Op::BOr, ValueClass::Bool, false, a.comps[0], b.comps[0]));
    if (op == "<" || op == "<=" || op == ">" || op == ">=" || op == "==" || op == "!=") {
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
    return arith(op, a, b, e.type, e.loc);
  }

  // + - * / % on scalars, aggregates (componentwise, scalars broadcast) and interpolator_data.
  Binding arith(const std::string& op, const Binding& a, const Binding& b, const Type& result, SourceLoc loc) {
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

  int fadd(int a, int b) { return emit(Op::FAdd, ValueClass::F32, false, a, b); }
  int fsub(int a, int b) { return emit(Op::FSub, ValueClass::F32, false, a, b); }
  int fmul(int a, int b) { return emit(Op::FMul, ValueClass::F32, false, a, b); }
  Binding vec(const Type& t, std::vector<int> comps) {
    Binding b;
    b.type = t;
    b.comps = std::move(comps);
    return b;
  }
  // x*x' + y*y' + z*z' of two points, vectors or normals (a point's w is not part of it).
  int dot3(const Binding& a, const Binding& b) {
    int s = fmul(toFloat(a.comps[0]), toFloat(b.comps[0]));
    for (int i = 1; i < 3; ++i) s = fadd(s, fmul(toFloat(a.comps[i]), toFloat(b.comps[i])));
    return s;
  }
  Binding sub3(const Binding& a, const Binding& b) {
    Binding d;
    d.type = Type::of(BaseType::Vector);
    for (int i = 0; i < 3; ++i) d.comps.push_back(fsub(toFloat(a.comps[i]), toFloat(b.comps[i])));
    return d;
  }

  // Componentwise maths over scalars and aggregates (a scalar argument applies to every
  // component). The result type was decided by sema.
  Binding componentwise(const Expr& e, const std::vector<Binding>& args, int arity) {
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

  int state(StateValue s) { return emit(Op::LoadState, ValueClass::F32, false, -1, -1, -1, static_cast<int>(s)); }

  // The state's column-major matrix `m` (its upper n x n; transposed if asked) times the n
  // components of v.
  // Whether value v is the constant x.
  bool isConstF(int v, float x) const {
    return v >= 0 && f_.values[v].origin == Value::Origin::Const && f_.values[v].bits == std::bit_cast<uint32_t>(x);
  }
  // a * b for the transforms below, where b may be a literal: a literal 0 contributes nothing
  // (-1: no term), a literal 1 contributes a itself. So a direction (w = 0) or a unit vector
  // costs only the columns it uses: object(eye(unscreen(point(1, 0, 0, 0)))) is one column's
  // worth of work, all of it in setup.
  int transformTerm(int a, int b) {
    if (isConstF(b, 0.0f)) return -1;
    if (isConstF(b, 1.0f)) return a;
    return emit(Op::FMul, ValueClass::F32, false, a, b);
  }
  int sumTerms(int sum, int term) {
    if (term < 0) return sum;
    return sum < 0 ? term : emit(Op::FAdd, ValueClass::F32, false, sum, term);
  }

  Binding scalarMatrixTimes(const Type& type, StateValue m, const std::vector<int>& v, int n, bool transposed) {
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
  int stateOn(StateValue s) { return emit(Op::FLt, ValueClass::Bool, false, constF(0.5f), state(s)); }

  // GL's front face for a window-space orientation (> 0: counter-clockwise):
  // (orientation > 0) == (glFrontFace is GL_CCW).
  int frontFacing(int orientation) {
    int ccw_area = emit(Op::FLt, ValueClass::Bool, false, constF(0.0f), orientation);
    int ccw_front = stateOn(StateValue::FrontFaceCCW);
    return emit(Op::BOr, ValueClass::Bool, false, emit(Op::BAnd, ValueClass::Bool, false, ccw_area, ccw_front),
                emit(Op::BAnd, ValueClass::Bool, false, emit(Op::BNot, ValueClass::Bool, false, ccw_area),
                     emit(Op::BNot, ValueClass::Bool, false, ccw_front)));
  }

  // A call of another primitive (sema checked it is uniform): the arguments fill the outgoing
  // parameter block and sequence points, then Emit submits the callee's instance.
  Binding callPrimitive(const Expr& e, const CompiledPrimitive& callee) {
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

  Binding call(const Expr& e) {
    const std::string& f = e.name;
    auto user = functions_.find(f);
    if (user != functions_.end()) return callFunction(e, *user->second);
    auto prim = primitives_.find(f);
    if (prim != primitives_.end()) return callPrimitive(e, *prim->second);
    std::vector<Binding> args;
    for (const ExprPtr& a : e.args) args.push_back(expr(*a));
    auto arg = [&](size_t i) { return args[i].comps[0]; };
    auto farg = [&](size_t i) { return toFloat(args[i].comps[0]); };
    if (int k = componentwiseArity(f)) return componentwise(e, args, k);
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
    if (f == "ztest") return scalar(e.type, emit(Op::ZTest, ValueClass::Bool, true, farg(0), -1, -1, 0, e.loc));
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
    if (f == "culled") {
      int front = frontFacing(farg(0));
      return scalar(e.type, emit(Op::Sel, ValueClass::Bool, false, front, stateOn(StateValue::CullFront),
                                 stateOn(StateValue::CullBack)));
    }
    if (f == "facing") {
      emitEffect(Op::BackFacing, emit(Op::BNot, ValueClass::Bool, false, frontFacing(farg(0))), -1, -1, -1, 0, e.loc);
      Binding none;
      none.type = Type::of(BaseType::Void);
      return none;
    }
    if (f == "flat_shading") return scalar(e.type, stateOn(StateValue::FlatShading));
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
};

}  // namespace

bool lowerPrimitive(const Unit& unit, const std::map<std::string, const Unit*>& functions,
                    const PrimitiveTable& primitives, IrFunction& out, DiagnosticLog& log) {
  Lowerer l(out, log, functions, primitives);
  return l.run(unit);
}

bool lowerField(const Unit& unit, const std::map<std::string, const Unit*>& functions, IrFunction& out,
                DiagnosticLog& log) {
  const PrimitiveTable none;
  Lowerer l(out, log, functions, none);
  return l.runField(unit);
}

}  // namespace pf
