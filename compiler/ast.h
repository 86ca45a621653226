// The abstract syntax tree of the primitive language, as the parser builds it and semantic
// analysis annotates it (Expr::type, Expr::varying).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "compiler/diagnostics.h"
#include "compiler/types.h"

namespace pf {

struct Expr;
struct Stmt;
using ExprPtr = std::unique_ptr<Expr>;
using StmtPtr = std::unique_ptr<Stmt>;

enum class ExprKind { IntLit, FloatLit, BoolLit, Name, Unary, Binary, Call, Index, Member, Ternary };

struct Expr {
  ExprKind kind;
  SourceLoc loc;
  std::string name;          // Name: the identifier; Call: the callee; Member: the field; Unary/Binary: operator
  double number = 0;         // literals
  bool boolean = false;
  std::vector<ExprPtr> args;  // operands / call arguments / [base, index] / [cond, a, b]
  // Nodes on the longest path from here down to a leaf: the parser bounds it, with the nesting
  // above, so that every later pass may recurse over the tree (`1 + 1 + ...` is one level a term).
  int height = 1;

  // Call of `fixed<bits,frac>(x)`, a conversion: the type converted to.
  Type conversion;

  // Filled in by semantic analysis.
  Type type;
  bool varying = false;
};

enum class StmtKind { Block, Decl, Assign, ExprStmt, If, Return, Bound, Interpolation, InterpReturn,
                      Loop, Break, Continue };

// One branch of an `interpolation { ... }` construct: its labels and its statements.
// One branch of `interpolation { ... }`: its labels -- kinds of interpolation (perspective_linear,
// linear, default), or names of shared interpolators the primitive computes itself -- and body.
struct InterpolationCase {
  std::vector<InterpKind> kinds;
  std::vector<std::string> interpolators;  // `spherical:`: channels bound to that interpolator
  std::vector<SourceLoc> kind_locs, name_locs;  // of each of the two
  std::vector<SourceLoc> label_locs;            // every label's, in source order
  std::vector<StmtPtr> body;
};

struct Stmt {
  StmtKind kind;
  SourceLoc loc;
  // Decl
  Qualifier qualifier = Qualifier::None;
  Type decl_type;
  std::string name;
  // Decl, filled in by semantic analysis: whether the variable may hold varying values.
  bool inferred_varying = false;
  // Decl initializer / Assign value / ExprStmt / If condition / InterpReturn value (may be null)
  ExprPtr value;
  // Assign: target (a Name, or Index/Member chain on a Name) and operator ("=", "+=", ...)
  ExprPtr target;
  std::string op;
  // Block / If then-branch
  std::vector<StmtPtr> body;
  // If else-branch (empty when absent)
  std::vector<StmtPtr> else_body;
  bool has_else = false;
  // Bound: four expressions
  std::vector<ExprPtr> bound_args;
  // Interpolation
  std::vector<InterpolationCase> cases;
  // Loop (`for` and `while`): init (a statement or null), `value` = condition (null: always
  // true), step (a statement or null), `body`. `for` scopes its init to the loop.
  StmtPtr init, step;

  // Filled in by semantic analysis: a loop whose iteration count can differ between pixels
  // (varying condition, or a break / continue under varying control).
  bool varying_loop = false;
};

struct Param {
  SourceLoc loc;
  Qualifier qualifier = Qualifier::None;
  Type type;
  std::string name;
};

// Field: `field float name(point p, float a, ...)`, an implicit surface's function of its point
// (compiled to a field tape, compiler/field/field_unit.h, not to programs).
enum class UnitKind { Primitive, Interpolator, Function, Field };

struct Unit {
  UnitKind kind;
  SourceLoc loc;
  std::string name;
  Type return_type;  // Function, Field
  std::vector<Param> params;
  std::vector<StmtPtr> body;
};

struct Program {
  std::vector<Unit> units;
};

}  // namespace pf
