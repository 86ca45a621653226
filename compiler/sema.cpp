// Semantic analysis (see sema.h). Varying inference is flow-insensitive and conservative: a
// variable is varying if it is declared so, or if any assignment to it has a varying value or
// happens under varying control flow. Lowering (lower.cpp) then classifies each SSA value
// exactly, which can only make more values uniform, never fewer.
#include "compiler/sema.h"

#include "compiler/builtins.h"

#include <algorithm>
#include <functional>
#include <set>
#include <vector>

namespace pf {
namespace {

struct Var {
  std::string name;
  Type type;
  Qualifier qualifier = Qualifier::None;
  SourceLoc loc;
  bool is_param = false;
  bool writable = true;
  bool varying = false;
  std::string why;  // why it is varying, for diagnostics
};

bool isNumericScalar(const Type& t) {
  return t.dims.empty() && (t.base == BaseType::Float || t.base == BaseType::Int);
}
bool isFloatLike(const Type& t) { return isNumericScalar(t); }
bool isBool(const Type& t) { return t.dims.empty() && t.base == BaseType::Bool; }
bool isInterp(const Type& t) { return t.dims.empty() && t.base == BaseType::InterpData; }
bool isAggregate(const Type& t) { return t.isAggregate() && t.base != BaseType::InterpData; }

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

// The program's functions, shared by the analyzers of all units.
struct FunctionTable {
  std::map<std::string, Unit*> units;
  // Whether a function's result can be varying even for uniform arguments (it reads X, Y, Z
  // or ztest, directly or through a call).
  std::map<std::string, bool> intrinsically_varying;
  // Calls between units, for the recursion check: caller -> (callee, call location).
  std::map<std::string, std::vector<std::pair<std::string, SourceLoc>>> calls;
  // Primitives a primitive may call: the context's and those defined earlier in the program;
  // and the program's primitives not defined yet (a call must follow the callee's definition).
  std::map<std::string, PrimitiveSignature> primitives;
  std::set<std::string> later_primitives;
};

class Analyzer {
 public:
  Analyzer(DiagnosticLog& log, FunctionTable& functions, bool reporting = true)
      : log_(log), functions_(functions), final_reporting_(reporting) {}

  // For a function: whether some `return` value was varying (with uniform parameters).
  bool returns_varying = false;

  void unit(Unit& u) {
    unit_ = &u;
    scopes_.clear();
    vars_.clear();
    scopes_.emplace_back();
    // Built-in pixel variables: visible in every primitive, whether or not the parameter list
    // names them (the paper's primitives list them as parameters; both forms are accepted).
    // Functions may read them; only a primitive writes Z.
    // A field sees none of them: it is a function of its point alone.
    builtin_count_ = 0;
    if (u.kind != UnitKind::Field) {
      declareBuiltin("X", false);
      declareBuiltin("Y", false);
      declareBuiltin("Z", u.kind == UnitKind::Primitive);
      // P: the surface point (eye space) a primitive sets for its shared interpolators, which read it.
      declareBuiltin("P", u.kind == UnitKind::Primitive, Type::of(BaseType::Point));
      // N: the surface normal (eye space); a primitive that sets it is lit per pixel.
      declareBuiltin("N", u.kind == UnitKind::Primitive, Type::of(BaseType::Normal));
    }
    if (u.kind == UnitKind::Function) {
      functionParams(u);
    } else if (u.kind == UnitKind::Field) {
      fieldParams(u);
    } else {
      unitParams(u);
    }
    // Fixpoint of varying inference: assignments can make variables varying, which can make
    // other assignments varying. Each pass re-types the whole body; at most one pass per variable.
    for (int pass = 0; pass < 64; ++pass) {
      changed_ = false;
      reporting_ = false;
      resetScopesForPass();
      scoped(u.body);
      if (!changed_) break;
    }
    reporting_ = final_reporting_;
    returns_varying = false;
    resetScopesForPass();
    scoped(u.body);
    if (!return_seen_in_interp_ && u.kind == UnitKind::Interpolator)
      err(u.loc, "interpolator '" + u.name + "' never reaches interpolator_return(value)");
    if ((u.kind == UnitKind::Function || u.kind == UnitKind::Field) && !alwaysReturns(u.body))
      err(u.loc, std::string(u.kind == UnitKind::Field ? "field '" : "function '") + u.name +
                     "' can reach its end without returning a " + typeName(u.return_type));
  }

 private:
  // Function parameters are local variables initialised by the call (uniform here: the
  // function is checked as if every argument were uniform; each call site decides for itself).
  void functionParams(Unit& u) {
    std::set<std::string> seen;
    for (Param& p : u.params) {
      if (!seen.insert(p.name).second) err(p.loc, "parameter '" + p.name + "' is declared twice");
      if (p.qualifier != Qualifier::None)
        err(p.loc, "function parameters take no qualifier: they are copies of the arguments, uniform or varying as the call decides");
      declareParam(p, true);
    }
  }

  // A field: `field float name(point p, float a, ...)`. p is the point the field is evaluated
  // at, varying like a pixel's position; the other parameters are numbers fixed when the field
  // is compiled (pfglCompileFieldParamsEXT's values), so uniform.
  void fieldParams(Unit& u) {
    if (u.return_type != Type::of(BaseType::Float))
      err(u.loc, "field '" + u.name + "' must return float (its value: >= 0 inside, < 0 outside), not " + typeName(u.return_type));
    if (u.params.empty() || u.params[0].type != Type::of(BaseType::Point)) {
      err(u.params.empty() ? u.loc : u.params[0].loc,
          "a field's first parameter is the point it is evaluated at: declare it 'point p'");
    }
    std::set<std::string> seen;
    for (size_t i = 0; i < u.params.size(); ++i) {
      Param& p = u.params[i];
      if (!seen.insert(p.name).second) err(p.loc, "parameter '" + p.name + "' is declared twice");
      if (p.qualifier != Qualifier::None && !(i > 0 && p.qualifier == Qualifier::Uniform))
        err(p.loc, "a field's parameters take no qualifier: the point is varying, the others uniform numbers");
      if (i > 0 && p.type != Type::of(BaseType::Float))
        err(p.loc, "a field's parameters after its point are numbers set when it is compiled: declare '" + p.name +
                       "' as float, not " + typeName(p.type));
      Var v;
      v.name = p.name;
      v.type = p.type;
      v.loc = p.loc;
      v.is_param = true;
      v.writable = true;
      if (i == 0) {
        v.varying = true;
        v.why = "it depends on the field's point '" + p.name + "'";
      }
      declare(v);
    }
  }

  void declareParam(const Param& p, bool writable) {
    Var v;
    v.name = p.name;
    v.type = p.type;
    v.qualifier = writable ? Qualifier::None : p.qualifier;
    v.loc = p.loc;
    v.is_param = true;
    v.writable = writable;
    declare(v);
  }

  static bool alwaysReturns(const std::vector<StmtPtr>& body) {
    for (const StmtPtr& s : body) {
      if (s->kind == StmtKind::Return) return true;
      if (s->kind == StmtKind::Block && alwaysReturns(s->body)) return true;
      if (s->kind == StmtKind::If && s->has_else && alwaysReturns(s->body) && alwaysReturns(s->else_body)) return true;
    }
    return false;
  }

  void unitParams(Unit& u) {
    std::set<std::string> seen;
    for (Param& p : u.params) {
      if (!seen.insert(p.name).second) {
        log_.error(p.loc, "parameter '" + p.name + "' is declared twice");
        continue;
      }
      if (p.name == "P" || p.name == "N") {
        log_.error(p.loc, "'" + p.name + "' is the built-in surface " + (p.name == "P" ? "point" : "normal") + ": it is not declared as a parameter");
        continue;
      }
      if (p.name == "X" || p.name == "Y" || p.name == "Z") {
        if (p.type != Type::of(BaseType::Float))
          log_.error(p.loc, "the built-in '" + p.name + "' has type float (declare it as 'varying float " + p.name + "')");
        if (p.name == "Z" && p.qualifier != Qualifier::InoutVarying && p.qualifier != Qualifier::Inout)
          log_.error(p.loc, "the built-in 'Z' is the depth buffer: declare it 'inout varying float Z'");
        if (p.name != "Z" && (p.qualifier == Qualifier::Uniform || p.qualifier == Qualifier::Inout))
          log_.error(p.loc, "the built-in '" + p.name + "' is the pixel position: it is 'varying', never 'uniform' or 'inout'");
        continue;
      }
      if (p.qualifier == Qualifier::Varying || p.qualifier == Qualifier::InoutVarying)
        log_.error(p.loc, "parameter '" + p.name + "' cannot be varying: parameters are bound per primitive or per sequence point, so they are uniform");
      if (u.kind == UnitKind::Interpolator && (p.type.isArray() || p.type.base == BaseType::InterpData))
        log_.error(p.loc, "a shared interpolator depends only on per-primitive parameters and P (paper section 3.4): '" + p.name + "' cannot be an array or interpolator_data");
      if (u.kind == UnitKind::Primitive && p.type.base == BaseType::InterpData &&
          p.type.dims.size() != 1)
        log_.error(p.loc, "an interpolator_data parameter is indexed by sequence point: declare it with one dimension, e.g. 'interpolator_data " + p.name + "[3]'");
      declareParam(p, false);
    }
  }

  DiagnosticLog& log_;
  FunctionTable& functions_;
  bool final_reporting_ = true;
  Unit* unit_ = nullptr;
  std::vector<std::map<std::string, int>> scopes_;
  std::vector<Var> vars_;
  std::map<std::pair<int, int>, int> decl_var_;  // (line, col) of a Decl -> var index across passes
  bool changed_ = false;
  bool reporting_ = true;  // errors are reported only on the final pass (no duplicates)
  int varying_control_ = 0;       // depth of varying if-conditions around the current statement
  std::string varying_control_why_;
  int interp_depth_ = 0;
  InterpKindSet interp_kinds_ = 0;
  // Enclosing loops: the statement, and the varying-control depth at its entry.
  struct LoopFrame {
    Stmt* loop;
    int control_depth;
    int interp_depth;
  };
  std::vector<LoopFrame> loops_;
  bool return_seen_in_interp_ = false;
  size_t builtin_count_ = 0;
  const Expr* statement_call_ = nullptr;  // the call an expression statement consists of

  void err(SourceLoc loc, const std::string& msg) {
    if (reporting_) log_.error(loc, msg);
  }

  void declareBuiltin(const std::string& name, bool writable, Type type = Type::of(BaseType::Float)) {
    Var v;
    v.name = name;
    v.type = type;
    v.qualifier = writable ? Qualifier::InoutVarying : Qualifier::Varying;
    v.writable = writable;
    v.varying = true;
    v.why = name == "Z"   ? "it depends on the built-in Z (the depth buffer)"
            : name == "P" ? "it depends on the built-in P (the surface point)"
            : name == "N" ? "it depends on the built-in N (the surface normal)"
                          : "it depends on the built-in " + name + " (the pixel position)";
    declare(v);
    builtin_count_ = vars_.size();
  }

  int declare(const Var& v) {
    vars_.push_back(v);
    int idx = static_cast<int>(vars_.size()) - 1;
    scopes_.back()[v.name] = idx;
    return idx;
  }

  void resetScopesForPass() {
    // Keep variable records (their varying flags persist across passes), drop local scopes.
    scopes_.resize(1);
    varying_control_ = 0;
    interp_depth_ = 0;
    loops_.clear();
    return_seen_in_interp_ = false;
  }

  int lookup(const std::string& name) const {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
      auto f = it->find(name);
      if (f != it->end()) return f->second;
    }
    return -1;
  }

  void markVarying(int vi, const std::string& why) {
    Var& v = vars_[vi];
    if (v.varying) return;
    v.varying = true;
    v.why = why;
    changed_ = true;
  }

  // ---- statements ----
  void statements(std::vector<StmtPtr>& body) {
    for (StmtPtr& s : body) statement(*s);
  }

  void scoped(std::vector<StmtPtr>& body) {
    scopes_.emplace_back();
    statements(body);
    scopes_.pop_back();
  }

  void statement(Stmt& s) {
    switch (s.kind) {
      case StmtKind::Block:
        if (s.op == "decls") statements(s.body);
        else scoped(s.body);
        break;
      case StmtKind::Decl: declaration(s); break;
      case StmtKind::Assign: assignment(s); break;
      case StmtKind::ExprStmt:
        statement_call_ = s.value.get();
        expr(*s.value);
        statement_call_ = nullptr;
        if (s.value->kind != ExprKind::Call)
          err(s.loc, "this expression has no effect");
        break;
      case StmtKind::If: {
        expr(*s.value);
        if (!isBool(s.value->type) && s.value->type.base != BaseType::Void)
          err(s.value->loc, "the condition of 'if' must be bool, not " + typeName(s.value->type));
        bool vary = s.value->varying;
        std::string save_why = varying_control_why_;
        if (vary) {
          if (varying_control_ == 0) varying_control_why_ = "it is assigned under an 'if' whose condition is varying (line " + std::to_string(s.value->loc.line) + ")";
          ++varying_control_;
        }
        scoped(s.body);
        scoped(s.else_body);
        if (vary) --varying_control_;
        varying_control_why_ = save_why;
        break;
      }
      case StmtKind::Loop: loop(s); break;
      case StmtKind::Break:
      case StmtKind::Continue: {
        const char* what = s.kind == StmtKind::Break ? "'break'" : "'continue'";
        if (loops_.empty()) {
          err(s.loc, std::string(what) + " is only allowed inside a loop");
          break;
        }
        LoopFrame& f = loops_.back();
        if (interp_depth_ > f.interp_depth)
          err(s.loc, std::string(what) + " cannot leave an interpolation branch");
        // Under varying control, some pixels leave the loop and others do not: the loop's
        // iteration count becomes varying.
        if (varying_control_ > f.control_depth && !f.loop->varying_loop) {
          f.loop->varying_loop = true;
          changed_ = true;
        }
        break;
      }
      case StmtKind::Return:
        if (unit_->kind == UnitKind::Interpolator) {
          err(s.loc, "an interpolator ends with interpolator_return(value), not 'return'");
        } else if (unit_->kind == UnitKind::Primitive) {
          if (s.value)
            err(s.value->loc, "a primitive's 'return' takes no value (use interpolator_return to return a shading value)");
        } else if (!s.value) {
          err(s.loc, "function '" + unit_->name + "' must return a " + typeName(unit_->return_type));
        } else {
          expr(*s.value);
          checkAssignable(unit_->return_type, *s.value, "return from '" + unit_->name + "'");
          if (s.value->varying || varying_control_ > 0) returns_varying = true;
          if (interp_depth_ > 0) err(s.loc, "'return' cannot leave an interpolation branch");
        }
        break;
      case StmtKind::Bound:
        if (unit_->kind != UnitKind::Primitive) err(s.loc, "'bound' is only allowed in a primitive");
        if (varying_control_ > 0) err(s.loc, "'bound' must be reached by every pixel alike: it cannot be under varying control flow");
        for (ExprPtr& a : s.bound_args) {
          expr(*a);
          if (!isFloatLike(a->type)) err(a->loc, "bound() takes float screen coordinates, not " + typeName(a->type));
          else if (a->varying) err(a->loc, "bound() needs a uniform value (the same for every pixel), but this one is varying: " + whyOf(*a));
        }
        break;
      case StmtKind::Interpolation: {
        if (unit_->kind != UnitKind::Primitive) err(s.loc, "the interpolation construct is only allowed in a primitive");
        if (interp_depth_ > 0) err(s.loc, "interpolation constructs cannot be nested");
        InterpKindSet seen = 0;
        for (InterpolationCase& c : s.cases) {
          InterpKindSet set = 0;
          for (size_t i = 0; i < c.kinds.size(); ++i) {
            InterpKindSet bit = 1u << static_cast<int>(c.kinds[i]);
            if (seen & bit) err(c.label_locs[i], std::string("interpolation label '") + interpKindName(c.kinds[i]) + "' appears twice");
            seen |= bit;
            set |= bit;
          }
          ++interp_depth_;
          InterpKindSet save = interp_kinds_;
          interp_kinds_ = set;
          scoped(c.body);
          interp_kinds_ = save;
          --interp_depth_;
        }
        break;
      }
      case StmtKind::InterpReturn:
        if (unit_->kind == UnitKind::Interpolator) {
          if (!s.value) {
            err(s.loc, "an interpolator must return a value: interpolator_return(value)");
          } else {
            expr(*s.value);
            const Type& t = s.value->type;
            if (t.base != BaseType::Void && (t.isArray() || !(isNumericScalar(t) || isAggregate(t))))
              err(s.value->loc, "an interpolator returns a float, point, vector, normal or color (its shading parameter's value), not " + typeName(t));
          }
          return_seen_in_interp_ = true;
          break;
        }
        if (interp_depth_ == 0) {
          err(s.loc, "interpolator_return is only allowed inside an interpolation { ... } construct");
          break;
        }
        if (s.value) {
          expr(*s.value);
          if (!isInterp(s.value->type))
            err(s.value->loc, "interpolator_return(value) in a primitive returns interpolator_data (the shading parameters), not " + typeName(s.value->type));
          if (interp_kinds_ & (1u << static_cast<int>(InterpKind::Shared)))
            err(s.loc, "in the 'default:' branch use 'interpolator_return;' (no value): it runs the shared interpolators");
        } else if (!(interp_kinds_ & (1u << static_cast<int>(InterpKind::Shared)))) {
          err(s.loc, "'interpolator_return;' without a value runs shared interpolators: it belongs in the 'default:' branch");
        }
        break;
    }
  }

  // for (init; cond; step) body / while (cond) body. A varying loop puts everything in it under
  // varying control (pixels iterate different numbers of times).
  void loop(Stmt& s) {
    scopes_.emplace_back();
    if (s.init) statement(*s.init);
    if (s.value) {
      expr(*s.value);
      if (s.value->type.base != BaseType::Void && !isBool(s.value->type))
        err(s.value->loc, "the condition of a loop must be bool, not " + typeName(s.value->type));
      if (s.value->varying && !s.varying_loop) {
        s.varying_loop = true;
        changed_ = true;
      }
    }
    std::string save_why = varying_control_why_;
    bool vary = s.varying_loop;
    if (vary) {
      if (varying_control_ == 0)
        varying_control_why_ = "it is assigned in a loop whose number of iterations is varying (line " + std::to_string(s.loc.line) + ")";
      ++varying_control_;
    }
    // The condition was typed before the loop was known to be varying: type it again so that
    // variables it reads get their final classification.
    if (s.value && vary) expr(*s.value);
    loops_.push_back({&s, varying_control_ - (vary ? 1 : 0), interp_depth_});
    scoped(s.body);
    if (s.step) statement(*s.step);
    loops_.pop_back();
    if (vary) --varying_control_;
    varying_control_why_ = save_why;
    scopes_.pop_back();
  }

  void declaration(Stmt& s) {
    if (lookupInInnermost(s.name) >= 0)
      err(s.loc, "'" + s.name + "' is already declared in this scope");
    if (s.qualifier == Qualifier::Inout || s.qualifier == Qualifier::InoutVarying)
      err(s.loc, "'inout' applies to parameters, not to local variables");
    if (s.decl_type.base == BaseType::InterpData && s.decl_type.dims.size() > 1)
      err(s.loc, "interpolator_data arrays have one dimension");
    // The same Decl keeps its Var across passes so inferred varying-ness accumulates.
    auto key = std::make_pair(s.loc.line, s.loc.col);
    int vi;
    auto found = decl_var_.find(key);
    if (found == decl_var_.end()) {
      Var v;
      v.name = s.name;
      v.type = s.decl_type;
      v.qualifier = s.qualifier;
      v.loc = s.loc;
      if (s.qualifier == Qualifier::Varying) {
        v.varying = true;
        v.why = "it is declared varying";
      }
      vi = declare(v);
      decl_var_[key] = vi;
    } else {
      vi = found->second;
      scopes_.back()[s.name] = vi;
    }
    if (s.value) {
      expr(*s.value);
      checkAssignable(s.decl_type, *s.value, "initialise '" + s.name + "'");
      flowInto(vi, *s.value, s.value->loc);
    }
    s.inferred_varying = vars_[vi].varying;
  }

  int lookupInInnermost(const std::string& name) const {
    auto f = scopes_.back().find(name);
    return f == scopes_.back().end() ? -1 : f->second;
  }

  // The value `e` flows into variable vi at `loc`: update inference, or report a uniform
  // variable receiving a varying value.
  void flowInto(int vi, const Expr& e, SourceLoc loc) {
    Var& v = vars_[vi];
    bool vary = e.varying || varying_control_ > 0;
    if (!vary) return;
    std::string why = e.varying ? whyOf(e) : varying_control_why_;
    if (v.qualifier == Qualifier::Uniform) {
      err(loc, "'" + v.name + "' is declared uniform, but the value it receives here is varying: " + why);
      return;
    }
    markVarying(vi, "it is assigned a varying value at line " + std::to_string(loc.line) + ": " + why);
  }

  void assignment(Stmt& s) {
    expr(*s.target);
    expr(*s.value);
    const Expr* root = s.target.get();
    while (root->kind == ExprKind::Index || root->kind == ExprKind::Member) root = root->args[0].get();
    if (root->kind != ExprKind::Name) {
      err(s.target->loc, "the left side of an assignment must be a variable, an element or a component");
      return;
    }
    int vi = lookup(root->name);
    if (vi < 0) return;  // already reported
    Var& v = vars_[vi];
    if (!v.writable) {
      err(root->loc, v.is_param ? "parameter '" + v.name + "' is read-only (copy it into a local variable to change it)"
                                : "'" + v.name + "' is read-only");
      return;
    }
    if (s.op != "=") {
      // x op= y is x = x op y: the same typing rules as the binary operator.
      Type t = binaryType(s.op.substr(0, 1), s.target->type, s.value->type, s.loc);
      if (t.base != BaseType::Void && t != s.target->type &&
          !(isNumericScalar(t) && isNumericScalar(s.target->type)))
        err(s.loc, "'" + s.op + "' gives " + typeName(t) + ", which cannot be stored in " + typeName(s.target->type));
    } else {
      checkAssignable(s.target->type, *s.value, "assign to '" + v.name + "'");
    }
    flowInto(vi, *s.value, s.value->loc);
    // Writing at a varying index changes different elements in different pixels.
    for (const Expr* t = s.target.get(); t->kind == ExprKind::Index || t->kind == ExprKind::Member; t = t->args[0].get())
      if (t->kind == ExprKind::Index && t->args[1]->varying) {
        if (v.qualifier == Qualifier::Uniform)
          err(t->args[1]->loc, "'" + v.name + "' is declared uniform, but it is written at a varying index: " + whyOf(*t->args[1]));
        else
          markVarying(vi, "it is written at a varying index at line " + std::to_string(t->loc.line) + ": " + whyOf(*t->args[1]));
      }
  }

  void checkAssignable(const Type& to, const Expr& from, const std::string& what) {
    if (from.type.base == BaseType::Void || to.base == BaseType::Void) return;
    if (to == from.type) return;
    if (to.dims.empty() && from.type.dims.empty()) {
      if (to.base == BaseType::Float && from.type.base == BaseType::Int) return;  // int -> float
      if (isAggregate(to) && isAggregate(from.type) &&
          Type::componentsOf(to.base) == Type::componentsOf(from.type.base) &&
          to.base != BaseType::Point && from.type.base != BaseType::Point)
        return;  // vector/normal/color with equal component counts convert
    }
    err(from.loc, "cannot " + what + ": expected " + typeName(to) + ", found " + typeName(from.type));
  }

  std::string whyOf(const Expr& e) const {
    // The first varying leaf of the expression explains it.
    if (!e.varying) return "";
    if (e.kind == ExprKind::Name) {
      int vi = lookup(e.name);
      if (vi >= 0) {
        const Var& v = vars_[vi];
        if (vi < static_cast<int>(builtin_count_)) return v.why;
        return "it depends on '" + v.name + "' (declared at line " + std::to_string(v.loc.line) + "), which " + stripIt(v.why);
      }
    }
    if (e.kind == ExprKind::Call && e.name == "ztest") return "it depends on ztest(), which reads the depth buffer";
    if (e.kind == ExprKind::Call && (e.name == "field_hit" || e.name.rfind("field_gradient", 0) == 0))
      return "it depends on " + e.name + "(), which is computed per pixel";
    for (const ExprPtr& a : e.args)
      if (a->varying) return whyOf(*a);
    return "it is varying";
  }
  static std::string stripIt(const std::string& s) {
    return s.rfind("it ", 0) == 0 ? s.substr(3) : s;
  }

  // ---- expressions ----
  void expr(Expr& e) {
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
          if (!(isNumericScalar(a.type) || isAggregate(a.type) || isInterp(a.type)))
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
        if (!isAggregate(a.type)) {
          err(e.loc, "'." + e.name + "' needs a point, vector, normal or color, not " + typeName(a.type));
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

 public:
  static bool constantInt(const Expr& e, long& out) {
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

 private:
  Type binaryType(const std::string& op, const Type& a, const Type& b, SourceLoc loc) {
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

  // A call of another primitive: a statement that submits an instance of it, so everything
  // about it must be the same for every pixel (paper section 5: polygon -> screen_triangle).
  void primitiveCall(Expr& e, const PrimitiveSignature& callee) {
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

  void call(Expr& e) {
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
      typeBuiltinCall(e, unit_->kind, [this](SourceLoc loc, const std::string& msg) { err(loc, msg); });
      if (e.name == "facing") {
        // An effect on the whole instance: uniform, and a statement.
        if (&e != statement_call_) err(e.loc, "facing() is a statement: it sets the instance's facing and has no value");
        if (unit_->kind != UnitKind::Primitive) err(e.loc, "facing() is only available in a primitive");
        if (varying_control_ > 0 || (!e.args.empty() && e.args[0]->varying))
          err(e.loc, "facing() sets the facing of the whole instance, so it must be uniform; " +
                         (varying_control_ > 0 ? varying_control_why_ : whyOf(*e.args[0])));
      }
      return;
    }
    const Unit& fn = *f->second;
    if (reporting_) functions_.calls[unit_->name].push_back({fn.name, e.loc});
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
};

}  // namespace

namespace {

// Reports one call on every cycle of the call graph: functions are inlined, so they cannot
// call themselves, directly or through others.
void checkRecursion(const FunctionTable& t, DiagnosticLog& log) {
  std::map<std::string, int> state;  // 0 unvisited, 1 on the stack, 2 done
  std::vector<std::string> path;
  std::function<void(const std::string&)> visit = [&](const std::string& f) {
    state[f] = 1;
    path.push_back(f);
    auto it = t.calls.find(f);
    if (it != t.calls.end()) {
      for (const auto& [callee, loc] : it->second) {
        if (!t.units.count(callee)) continue;
        if (state[callee] == 1) {
          std::string chain;
          auto start = std::find(path.begin(), path.end(), callee);
          for (auto p = start; p != path.end(); ++p) chain += *p + " -> ";
          log.error(loc, "recursion is not allowed (functions are inlined): " + chain + callee);
        } else if (state[callee] == 0) {
          visit(callee);
        }
      }
    }
    path.pop_back();
    state[f] = 2;
  };
  for (const auto& entry : t.units)
    if (state[entry.first] == 0) visit(entry.first);
}

bool isBuiltinName(const std::string& name) {
  Expr probe;
  probe.kind = ExprKind::Call;
  probe.name = name;
  bool unknown = false;
  typeBuiltinCall(probe, UnitKind::Primitive, [&](SourceLoc, const std::string& m) {
    if (m.find("is not a built-in function") != std::string::npos) unknown = true;
  });
  return !unknown;
}

}  // namespace

PrimitiveSignature signatureOf(const Unit& u) {
  PrimitiveSignature sig;
  for (const Param& p : u.params)
    if (p.name != "X" && p.name != "Y" && p.name != "Z") sig.push_back({p.name, p.type});
  return sig;
}

bool analyze(Program& program, DiagnosticLog& log, const std::map<std::string, PrimitiveSignature>& callable) {
  FunctionTable functions;
  functions.primitives = callable;
  for (const Unit& u : program.units)
    if (u.kind == UnitKind::Primitive) functions.later_primitives.insert(u.name);
  std::set<std::string> names;
  for (Unit& u : program.units) {
    if (!names.insert(u.name).second) log.error(u.loc, "'" + u.name + "' is defined twice");
    // A field is callable as a function too: another field (or a primitive) may evaluate it.
    if (u.kind != UnitKind::Function && u.kind != UnitKind::Field) continue;
    if (isBuiltinName(u.name)) log.error(u.loc, "'" + u.name + "' is the name of a built-in function");
    functions.units[u.name] = &u;
  }
  // Which functions can return varying values for uniform arguments: to a fixpoint, since
  // functions call each other.
  for (size_t round = 0; round <= functions.units.size(); ++round) {
    bool changed = false;
    for (auto& [name, unit] : functions.units) {
      DiagnosticLog quiet;
      Analyzer a(quiet, functions, false);
      a.unit(*unit);
      if (a.returns_varying && !functions.intrinsically_varying[name]) {
        functions.intrinsically_varying[name] = true;
        changed = true;
      }
    }
    if (!changed) break;
  }
  functions.calls.clear();
  for (Unit& u : program.units) {
    Analyzer a(log, functions);
    a.unit(u);
    if (u.kind == UnitKind::Primitive) {
      functions.later_primitives.erase(u.name);
      functions.primitives[u.name] = signatureOf(u);
    }
  }
  checkRecursion(functions, log);
  return !log.hasErrors();
}

}  // namespace pf
