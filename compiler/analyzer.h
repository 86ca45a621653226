// Internal to semantic analysis (not part of any public API; the entry points are in sema.h):
// the Analyzer, which checks and types one unit, the program's FunctionTable the analyzers of
// all units share, and the type predicates both use. The Analyzer's member functions are
// defined in sema.cpp (units, parameters, variables), sema_statements.cpp (statements, loops,
// declarations, assignments, why a value is varying) and sema_expressions.cpp (expressions,
// operators, calls of functions, built-ins and primitives).
#pragma once

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "compiler/sema.h"

namespace pf::analysis {

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

inline bool isNumericScalar(const Type& t) {
  return t.dims.empty() && (t.base == BaseType::Float || t.base == BaseType::Int);
}
inline bool isFloatLike(const Type& t) { return isNumericScalar(t); }
inline bool isBool(const Type& t) { return t.dims.empty() && t.base == BaseType::Bool; }
inline bool isInterp(const Type& t) { return t.dims.empty() && t.base == BaseType::InterpData; }
inline bool isFixed(const Type& t) { return t.isFixed(); }
// Where a float is expected (a built-in's argument, a shading value, bound()), a fixed value
// takes part as its float: wraps e, if it is fixed, in an implicit float(e) conversion.
void fixedAsFloat(ExprPtr& e);
inline bool isAggregate(const Type& t) { return t.isAggregate() && t.base != BaseType::InterpData; }
// What a shading parameter can hold (an interpolator's value): a number, point, vector, normal
// or colour.
inline bool isShadingValue(const Type& t) {
  return t.dims.empty() && (isNumericScalar(t) || (isAggregate(t) && t.base != BaseType::Matrix));
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
  // Shared interpolators an interpolation label may name: compiled before, or defined earlier
  // in the program.
  std::set<std::string> interpolators;
};

class Analyzer {
 public:
  Analyzer(DiagnosticLog& log, FunctionTable& functions, bool reporting = true)
      : log_(log), functions_(functions), final_reporting_(reporting) {}

  // For a function: whether some `return` value was varying (with uniform parameters).
  bool returns_varying = false;

  void unit(Unit& u);

 private:
  // ---- units and their parameters (sema.cpp) ----
  // Function parameters are local variables initialised by the call (uniform here: the
  // function is checked as if every argument were uniform; each call site decides for itself).
  void functionParams(Unit& u);

  // A field: `field float name(point p, float a, ...)`. p is the point the field is evaluated
  // at, varying like a pixel's position; the other parameters are numbers fixed when the field
  // is compiled (pfglCompileFieldParamsEXT's values), so uniform.
  void fieldParams(Unit& u);

  void declareParam(const Param& p, bool writable);

  static bool alwaysReturns(const std::vector<StmtPtr>& body);

  void unitParams(Unit& u);
  void fixedPixelBuiltins(Unit& u);

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
  std::string interp_named_;  // in a `name:` branch: the shared interpolator it computes
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

  // ---- variables and scopes (sema.cpp) ----
  void err(SourceLoc loc, const std::string& msg);

  void declareBuiltin(const std::string& name, bool writable, Type type = Type::of(BaseType::Float));

  int declare(const Var& v);

  void resetScopesForPass();

  int lookup(const std::string& name) const;

  void markVarying(int vi, const std::string& why);

  // ---- statements (sema_statements.cpp) ----
  void statements(std::vector<StmtPtr>& body);

  void scoped(std::vector<StmtPtr>& body);

  void statement(Stmt& s);

  // for (init; cond; step) body / while (cond) body. A varying loop puts everything in it under
  // varying control (pixels iterate different numbers of times).
  void loop(Stmt& s);

  void declaration(Stmt& s);

  int lookupInInnermost(const std::string& name) const;

  // The value `e` flows into variable vi at `loc`: update inference, or report a uniform
  // variable receiving a varying value.
  void flowInto(int vi, const Expr& e, SourceLoc loc);

  void assignment(Stmt& s);

  void checkAssignable(const Type& to, const Expr& from, const std::string& what);

  std::string whyOf(const Expr& e) const;
  static std::string stripIt(const std::string& s);

  // ---- expressions (sema_expressions.cpp) ----
  void expr(Expr& e);

 public:
  static bool constantInt(const Expr& e, long& out);

 private:
  Type binaryType(const std::string& op, const Type& a, const Type& b, SourceLoc loc);

  // A call of another primitive: a statement that submits an instance of it, so everything
  // about it must be the same for every pixel (paper section 5: polygon -> screen_triangle).
  void primitiveCall(Expr& e, const PrimitiveSignature& callee);

  void call(Expr& e);

  // Calls involving fixed<bits,frac> values that stay fixed-point: conversions (fixed<b,f>(x),
  // float(q), int(q)) and abs / min / max / clamp of one format. Returns false to leave the
  // call to the built-ins (with its fixed arguments converted to float).
  bool fixedCall(Expr& e);
};

}  // namespace pf::analysis
