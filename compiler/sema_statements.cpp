// Semantic analysis of statements (the Analyzer, analyzer.h): blocks, `if`, loops, break and
// continue, return, bound, the interpolation construct and interpolator_return; declarations
// and assignments, where values flow into variables (varying inference, and the errors of a
// uniform variable receiving a varying value); and whyOf, which explains why a value is varying.
#include "compiler/analyzer.h"
#include "compiler/stack_guard.h"

#include <string>

namespace pf::analysis {

void Analyzer::statements(std::vector<StmtPtr>& body) {
  for (StmtPtr& s : body) statement(*s);
}

void Analyzer::scoped(std::vector<StmtPtr>& body) {
  scopes_.emplace_back();
  statements(body);
  scopes_.pop_back();
}

void Analyzer::statement(Stmt& s) {
  if (stackNearlyExhausted()) {
    err(s.loc, "nesting too deep for this thread's stack");
    throw CompileAbort{};  // (analyze catches it)
  }
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
        fixedAsFloat(a);
        if (!isFloatLike(a->type)) err(a->loc, "bound() takes float screen coordinates, not " + typeName(a->type));
        else if (a->varying) err(a->loc, "bound() needs a uniform value (the same for every pixel), but this one is varying: " + whyOf(*a));
      }
      break;
    case StmtKind::Interpolation: {
      if (unit_->kind != UnitKind::Primitive) err(s.loc, "the interpolation construct is only allowed in a primitive");
      if (interp_depth_ > 0) err(s.loc, "interpolation constructs cannot be nested");
      InterpKindSet seen = 0;
      std::set<std::string> seen_names;
      for (InterpolationCase& c : s.cases) {
        InterpKindSet set = 0;
        for (size_t i = 0; i < c.kinds.size(); ++i) {
          InterpKindSet bit = 1u << static_cast<int>(c.kinds[i]);
          if (seen & bit) err(c.kind_locs[i], std::string("interpolation label '") + interpKindName(c.kinds[i]) + "' appears twice");
          seen |= bit;
          set |= bit;
        }
        for (size_t i = 0; i < c.interpolators.size(); ++i) {
          const std::string& name = c.interpolators[i];
          if (!seen_names.insert(name).second)
            err(c.name_locs[i], "interpolation label '" + name + "' appears twice");
          if (!functions_.interpolators.count(name))
            err(c.name_locs[i], "'" + name + "' is not a shared interpolator: an interpolation label names one " +
                                    "compiled before, or defined earlier in this source (or is perspective_linear, linear or default)");
        }
        if (!c.interpolators.empty() && !c.kinds.empty())
          err(c.name_locs[0], "the branch of interpolator '" + c.interpolators[0] + "' cannot share its body with '" +
                                  interpKindName(c.kinds[0]) + "': their interpolator_return take different values");
        ++interp_depth_;
        InterpKindSet save = interp_kinds_;
        interp_kinds_ = set;
        interp_named_ = c.interpolators.empty() ? "" : c.interpolators[0];
        scoped(c.body);
        interp_named_.clear();
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
          fixedAsFloat(s.value);
          const Type& t = s.value->type;
          if (t.base != BaseType::Void && !isShadingValue(t))
            err(s.value->loc, "an interpolator returns a float, point, vector, normal or color (its shading parameter's value), not " + typeName(t));
        }
        return_seen_in_interp_ = true;
        break;
      }
      if (interp_depth_ == 0) {
        err(s.loc, "interpolator_return is only allowed inside an interpolation { ... } construct");
        break;
      }
      if (!interp_named_.empty()) {  // the primitive's own value of a shared interpolator
        if (!s.value) {
          err(s.loc, "in the '" + interp_named_ + ":' branch, interpolator_return takes the interpolator's value: " +
                         "interpolator_return(value)");
          break;
        }
        expr(*s.value);
        fixedAsFloat(s.value);
        const Type& t = s.value->type;
        if (t.base != BaseType::Void && !isShadingValue(t))
          err(s.value->loc, "interpolator_return(value) in the '" + interp_named_ +
                                ":' branch returns the value of interpolator '" + interp_named_ +
                                "' (a float, point, vector, normal or color), not " + typeName(t));
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

void Analyzer::loop(Stmt& s) {
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

void Analyzer::declaration(Stmt& s) {
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

int Analyzer::lookupInInnermost(const std::string& name) const {
  auto f = scopes_.back().find(name);
  return f == scopes_.back().end() ? -1 : f->second;
}

void Analyzer::flowInto(int vi, const Expr& e, SourceLoc loc) {
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

void Analyzer::assignment(Stmt& s) {
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
        !(isNumericScalar(t) && isNumericScalar(s.target->type)) &&
        !(isFixed(s.target->type) && isNumericScalar(t)))  // q += 0.5: the float result converts into q
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

void Analyzer::checkAssignable(const Type& to, const Expr& from, const std::string& what) {
  if (from.type.base == BaseType::Void || to.base == BaseType::Void) return;
  if (to == from.type) return;
  if (to.dims.empty() && from.type.dims.empty()) {
    if (to.base == BaseType::Float && from.type.base == BaseType::Int) return;  // int -> float
    // Into a fixed type from a number or another format (rounded, saturated); out of one into
    // a float. Into an int only explicitly: int(x) truncates.
    if (to.base == BaseType::Fixed && (isNumericScalar(from.type) || isFixed(from.type))) return;
    if (to.base == BaseType::Float && isFixed(from.type)) return;
    if (isAggregate(to) && isAggregate(from.type) &&
        Type::componentsOf(to.base) == Type::componentsOf(from.type.base) &&
        to.base != BaseType::Point && from.type.base != BaseType::Point)
      return;  // vector/normal/color with equal component counts convert
  }
  err(from.loc, "cannot " + what + ": expected " + typeName(to) + ", found " + typeName(from.type));
}

std::string Analyzer::whyOf(const Expr& e) const {
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
  if (e.kind == ExprKind::Call && (e.name == "ztest" || e.name == "polygon_ztest"))
    return "it depends on " + e.name + "(), which reads the depth buffer";
  if (e.kind == ExprKind::Call &&
      (e.name == "field_hit" || e.name.rfind("field_gradient", 0) == 0 || e.name == "field_color"))
    return "it depends on " + e.name + "(), which is computed per pixel";
  for (const ExprPtr& a : e.args)
    if (a->varying) return whyOf(*a);
  return "it is varying";
}

std::string Analyzer::stripIt(const std::string& s) {
  return s.rfind("it ", 0) == 0 ? s.substr(3) : s;
}

}  // namespace pf::analysis
