// Semantic analysis (see sema.h). Varying inference is flow-insensitive and conservative: a
// variable is varying if it is declared so, or if any assignment to it has a varying value or
// happens under varying control flow. Lowering (lower.cpp) then classifies each SSA value
// exactly, which can only make more values uniform, never fewer.
//
// This file: the entry points (analyze, signatureOf), the analysis of a unit with its fixpoint
// of varying inference, the units' parameters, the Analyzer's variables and scopes, and the
// check for recursion. The Analyzer is declared in analyzer.h.
#include "compiler/sema.h"

#include "compiler/analyzer.h"
#include "compiler/builtins.h"

#include <algorithm>
#include <deque>
#include <functional>
#include <map>
#include <set>
#include <vector>

namespace pf {
namespace analysis {

void Analyzer::unit(Unit& u) {
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

void Analyzer::functionParams(Unit& u) {
  std::set<std::string> seen;
  for (Param& p : u.params) {
    if (!seen.insert(p.name).second) err(p.loc, "parameter '" + p.name + "' is declared twice");
    if (p.qualifier != Qualifier::None)
      err(p.loc, "function parameters take no qualifier: they are copies of the arguments, uniform or varying as the call decides");
    declareParam(p, true);
  }
}

void Analyzer::fieldParams(Unit& u) {
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

void Analyzer::declareParam(const Param& p, bool writable) {
  Var v;
  v.name = p.name;
  v.type = p.type;
  v.qualifier = writable ? Qualifier::None : p.qualifier;
  v.loc = p.loc;
  v.is_param = true;
  v.writable = writable;
  declare(v);
}

bool Analyzer::alwaysReturns(const std::vector<StmtPtr>& body) {
  for (const StmtPtr& s : body) {
    if (s->kind == StmtKind::Return) return true;
    if (s->kind == StmtKind::Block && alwaysReturns(s->body)) return true;
    if (s->kind == StmtKind::If && s->has_else && alwaysReturns(s->body) && alwaysReturns(s->else_body)) return true;
  }
  return false;
}

namespace {

// Every read of the built-ins in `fixed` (X, Y or Z, by name) in `e` becomes the conversion
// fixed<bits,frac>(name) into its declared format.
void convertPixelReads(ExprPtr& e, const std::map<std::string, Type>& fixed) {
  if (!e) return;
  if (e->kind == ExprKind::Name) {
    auto it = fixed.find(e->name);
    if (it == fixed.end()) return;
    auto call = std::make_unique<Expr>();
    call->kind = ExprKind::Call;
    call->loc = e->loc;
    call->name = "fixed";
    call->conversion = it->second;
    call->height = e->height + 1;
    call->args.push_back(std::move(e));
    e = std::move(call);
    return;
  }
  for (ExprPtr& a : e->args) convertPixelReads(a, fixed);
}

void convertPixelReads(std::vector<StmtPtr>& body, const std::map<std::string, Type>& fixed);

void convertPixelReads(Stmt& s, const std::map<std::string, Type>& fixed) {
  convertPixelReads(s.value, fixed);
  // An assignment's target stays the float built-in (a fixed value converts into it); only the
  // indices inside a target are reads.
  if (s.target && s.target->kind != ExprKind::Name)
    for (ExprPtr& a : s.target->args) convertPixelReads(a, fixed);
  for (ExprPtr& a : s.bound_args) convertPixelReads(a, fixed);
  convertPixelReads(s.body, fixed);
  convertPixelReads(s.else_body, fixed);
  for (InterpolationCase& c : s.cases) convertPixelReads(c.body, fixed);
  if (s.init) convertPixelReads(*s.init, fixed);
  if (s.step) convertPixelReads(*s.step, fixed);
}

void convertPixelReads(std::vector<StmtPtr>& body, const std::map<std::string, Type>& fixed) {
  for (StmtPtr& s : body)
    if (s) convertPixelReads(*s, fixed);
}

}  // namespace

// The paper's figures 6 and 7 declare the pixel built-ins in fixed point
// (`varying fixed<32,16> X, Y; inout varying fixed<32,32> Z`). The built-ins themselves are
// floats (the rasterizer's pixel centres and depth buffer); such a declaration makes every read
// of the name in the unit's own body a conversion into the declared format (rounded to nearest,
// saturated, as every conversion into a fixed type) and leaves writes to Z converting back into
// the float depth. Functions the unit calls see the float built-ins.
void Analyzer::fixedPixelBuiltins(Unit& u) {
  std::map<std::string, Type> fixed;
  for (Param& p : u.params)
    if ((p.name == "X" || p.name == "Y" || p.name == "Z") && p.type.base == BaseType::Fixed && !p.type.isArray()) {
      fixed[p.name] = p.type;
      p.type = Type::of(BaseType::Float);
    }
  if (!fixed.empty()) convertPixelReads(u.body, fixed);
}

void Analyzer::unitParams(Unit& u) {
  if (u.kind == UnitKind::Primitive || u.kind == UnitKind::Interpolator) fixedPixelBuiltins(u);
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
        log_.error(p.loc, "the built-in '" + p.name + "' has type float or fixed<bits,frac> (declare it as 'varying float " +
                              p.name + "' or, as the paper's figure 7, 'varying fixed<32,16> " + p.name + "')");
      if (p.name == "Z" && p.qualifier != Qualifier::InoutVarying && p.qualifier != Qualifier::Inout)
        log_.error(p.loc, "the built-in 'Z' is the depth buffer: declare it 'inout varying float Z'");
      if (p.name != "Z" && (p.qualifier == Qualifier::Uniform || p.qualifier == Qualifier::Inout))
        log_.error(p.loc, "the built-in '" + p.name + "' is the pixel position: it is 'varying', never 'uniform' or 'inout'");
      continue;
    }
    if (p.type.base == BaseType::Fixed)
      log_.error(p.loc, "parameter '" + p.name + "' cannot be " + typeName(p.type) +
                            ": parameters arrive from the API as floats; declare it float and convert inside (" +
                            typeName(p.type) + "(" + p.name + "))");
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

void Analyzer::err(SourceLoc loc, const std::string& msg) {
  if (reporting_) log_.error(loc, msg);
}

void Analyzer::declareBuiltin(const std::string& name, bool writable, Type type) {
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

int Analyzer::declare(const Var& v) {
  vars_.push_back(v);
  int idx = static_cast<int>(vars_.size()) - 1;
  scopes_.back()[v.name] = idx;
  return idx;
}

void Analyzer::resetScopesForPass() {
  // Keep variable records (their varying flags persist across passes), drop local scopes.
  scopes_.resize(1);
  varying_control_ = 0;
  interp_depth_ = 0;
  loops_.clear();
  return_seen_in_interp_ = false;
}

int Analyzer::lookup(const std::string& name) const {
  for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
    auto f = it->find(name);
    if (f != it->end()) return f->second;
  }
  return -1;
}

void Analyzer::markVarying(int vi, const std::string& why) {
  Var& v = vars_[vi];
  if (v.varying) return;
  v.varying = true;
  v.why = why;
  changed_ = true;
}

}  // namespace analysis

using analysis::Analyzer;
using analysis::FunctionTable;

namespace {

// Reports one call on every cycle of the call graph: functions are inlined, so they cannot
// call themselves, directly or through others. A depth-first walk with its own stack (a chain
// of 20,000 calls overflowed a thread's stack as a recursive one).
void checkRecursion(const FunctionTable& t, DiagnosticLog& log) {
  std::map<std::string, int> state;  // 0 unvisited, 1 on the path, 2 done
  static const std::vector<std::pair<std::string, SourceLoc>> kNone;
  struct Step {
    std::string function;
    const std::vector<std::pair<std::string, SourceLoc>>* calls;
    size_t next = 0;  // the next of its calls to follow
  };
  std::vector<Step> path;
  auto enter = [&](const std::string& f) {
    state[f] = 1;
    auto it = t.calls.find(f);
    path.push_back({f, it != t.calls.end() ? &it->second : &kNone, 0});
  };
  for (const auto& entry : t.units) {
    if (state[entry.first] != 0) continue;
    enter(entry.first);
    while (!path.empty()) {
      Step& top = path.back();
      if (top.next == top.calls->size()) {
        state[top.function] = 2;
        path.pop_back();
        continue;
      }
      const auto& call = (*top.calls)[top.next++];
      const std::string& callee = call.first;
      const SourceLoc loc = call.second;
      if (!t.units.count(callee)) continue;
      if (state[callee] == 1) {
        std::string chain;
        auto start = std::find_if(path.begin(), path.end(), [&](const Step& s) { return s.function == callee; });
        for (auto p = start; p != path.end(); ++p) chain += p->function + " -> ";
        log.error(loc, "recursion is not allowed (functions are inlined): " + chain + callee);
      } else if (state[callee] == 0) {
        enter(callee);
      }
    }
  }
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

namespace {
bool analyzeAll(Program& program, DiagnosticLog& log, const std::map<std::string, PrimitiveSignature>& callable,
                const std::set<std::string>& interpolators);
}  // namespace

bool analyze(Program& program, DiagnosticLog& log, const std::map<std::string, PrimitiveSignature>& callable,
             const std::set<std::string>& interpolators) {
  try {
    return analyzeAll(program, log, callable, interpolators);
  } catch (const CompileAbort&) {  // the thread's stack nearly used up (its error is logged)
    if (!log.hasErrors()) log.error({}, "nesting too deep for this thread's stack");
    return false;
  }
}

namespace {

bool analyzeAll(Program& program, DiagnosticLog& log, const std::map<std::string, PrimitiveSignature>& callable,
                const std::set<std::string>& interpolators) {
  FunctionTable functions;
  functions.primitives = callable;
  functions.interpolators = interpolators;
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
  // functions call each other. A worklist: each function is analyzed once, and again only when
  // one it calls turns out varying. (Rounds over every function in the order of their names
  // were quadratic in a chain of calls that runs against that order: 5,000 functions, 30 s.)
  std::deque<std::string> work;
  std::set<std::string> queued;
  for (const auto& [name, unit] : functions.units) {
    work.push_back(name);
    queued.insert(name);
  }
  std::map<std::string, std::set<std::string>> callers;  // callee -> the functions calling it
  while (!work.empty()) {
    const std::string name = std::move(work.front());
    work.pop_front();
    queued.erase(name);
    functions.calls[name].clear();
    DiagnosticLog quiet;
    Analyzer a(quiet, functions, false);
    a.unit(*functions.units[name]);
    for (const auto& [callee, loc] : functions.calls[name]) callers[callee].insert(name);
    if (a.returns_varying && !functions.intrinsically_varying[name]) {
      functions.intrinsically_varying[name] = true;
      for (const std::string& caller : callers[name])
        if (queued.insert(caller).second) work.push_back(caller);
    }
  }
  functions.calls.clear();
  for (Unit& u : program.units) {
    Analyzer a(log, functions);
    a.unit(u);
    if (u.kind == UnitKind::Interpolator) functions.interpolators.insert(u.name);
    if (u.kind == UnitKind::Primitive) {
      functions.later_primitives.erase(u.name);
      functions.primitives[u.name] = signatureOf(u);
    }
  }
  checkRecursion(functions, log);
  return !log.hasErrors();
}

}  // namespace
}  // namespace pf
