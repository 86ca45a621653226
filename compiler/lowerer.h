// Internal to lowering (not part of any public API; the entry points are in lower.h): the
// Lowerer class, which lowers one unit from the AST to the IR, and the records it works with.
// Its member functions are defined in lower.cpp (unit set-up, bindings, values),
// lower_statements.cpp (statements, branches, loops, inlined calls, assignment) and
// lower_expressions.cpp (expressions, arithmetic, built-in calls, calls of primitives).
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "compiler/lower.h"

namespace pf::lowering {

struct Binding {
  Type type;
  std::vector<int> comps;  // Value ids, one per scalar slot (per element for interpolator_data)
  bool writable = true;
  bool may_vary = false;   // sema's (conservative) verdict on the variable
  int sized_param = -1;    // a parameter-sized array (`T name[]`): its ParamInfo; no comps
};
constexpr int kSizedInterpData = -2;  // Binding::sized_param of `interpolator_data name[]`

// How deep lowering may recurse (statements and expressions, through inlined calls): the
// parser's limit (256) bounds one unit, this the units inlined into each other.
constexpr int kMaxLoweredNesting = 384;
// How deep calls of functions may nest once inlined (each costs lowering several frames).
constexpr size_t kMaxInlineDepth = 64;
// How many expressions one unit may lower, its inlined calls' included.
constexpr uint64_t kMaxLoweredExpressions = uint64_t{1} << 18;
// Varying else-if chains of this many links or more lower flat (Lowerer::ifChain): a few
// instructions more a link, and no limit on their length from the masks a program nests.
constexpr size_t kFlatElseIfLinks = 4;

// Thrown by Lowerer::refuse, after its error, to abandon the unit.
struct LoweringAbort {};

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
  const void* site = nullptr;         // the loop statement or the call it lowers (LoopMemo's key)
  std::function<int()> cond;          // emits the condition, returns its value (-1: always true)
  std::function<void()> body, step;
};

// The value class that holds one component of a base type (a fixed value's two words: ints).
inline ValueClass classOf(BaseType b) {
  return b == BaseType::Int || b == BaseType::Fixed ? ValueClass::I32
         : b == BaseType::Bool                      ? ValueClass::Bool
                                                    : ValueClass::F32;
}

class Lowerer {
 public:
  Lowerer(IrFunction& f, DiagnosticLog& log, const std::map<std::string, const Unit*>& functions,
          const PrimitiveTable& primitives)
      : f_(f), log_(log), functions_(functions), primitives_(primitives) {}

  bool run(const Unit& u);

  // A field unit (docs/language.md, "Fields"): its point p is three FieldPoint values (w = 1),
  // its other parameters are the parameter block's slots, and its body is inlined as a
  // function's. The field's value leaves through ShadeOut, which keeps it alive through the
  // passes. The pixel built-ins are bound as in a primitive, for the functions a field calls:
  // the field tape translation (compiler/field/field_unit.cpp) rejects any use of them.
  bool runField(const Unit& u);

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
  int named_index_ = -1;  // in a `name:` branch: its index in f_.named_interpolators
  int z_initial_ = -1;
  std::vector<int> n_initial_;
  SourceLoc cur_loc_;
  std::map<std::pair<int, uint32_t>, int> constants_;
  int zero_interp_ = -1;
  bool interpolator_ = false;  // lowering a shared interpolator: interpolator_return is its value

  // What lowering a loop found (lowerLoop): whether it is varying and which carried values are.
  // Kept per loop and call site, so that a loop lowered again -- inside an outer loop lowered
  // again, or an inlined function's -- starts from it instead of finding it anew: without it each
  // level of nested loops (an early `return` makes each inlined call one) doubles the work.
  struct LoopMemo {
    bool varying = false;
    std::vector<bool> forced;
  };
  std::map<std::vector<const void*>, LoopMemo> loop_memo_;
  std::vector<const void*> call_sites_;  // the calls being inlined, outermost first (as Expr*)
  std::vector<const Unit*> inlining_;    // and the functions they inline

  // Bounds on what inlining builds (docs/reliability.md): how deep lowering recurses, through
  // inlined calls too, and how many expressions it lowers in all (a function that calls another
  // twice, 24 deep, is 2^24 copies). Past either, lowering stops with an error naming the chain.
  int nesting_ = 0;
  uint64_t lowered_expressions_ = 0;
  struct NestingGuard {
    Lowerer& l;
    NestingGuard(Lowerer& lowerer, SourceLoc loc);
    ~NestingGuard() { --l.nesting_; }
  };
  [[noreturn]] void refuse(SourceLoc loc, const std::string& what);

  // ---- bindings and values (lower.cpp) ----
  int newValue(const Value& v);

  void bindBuiltin(const std::string& name, uint32_t reg, bool writable, Type type = Type::of(BaseType::Float));

  int lookup(const std::string& name) const;

  int constant(ValueClass cls, uint32_t bits);
  int constF(float x) { return constant(ValueClass::F32, std::bit_cast<uint32_t>(x)); }
  int constI(int32_t x) { return constant(ValueClass::I32, static_cast<uint32_t>(x)); }
  int constB(bool x) { return constant(ValueClass::Bool, x ? 1u : 0u); }

  bool isVarying(int v) const { return v >= 0 && f_.values[v].varying; }
  ValueClass cls(int v) const { return f_.values[v].cls; }

  int emit(Op op, ValueClass c, bool varying, int a, int b = -1, int cc = -1, int imm = 0,
           SourceLoc loc = {});
  void emitEffect(Op op, int a, int b, int c, int d, int imm, SourceLoc loc);

  // Zero of the class of value v (interpolator_data: zero in every channel).
  int zeroLike(int v) { return cls(v) == ValueClass::Interp ? zeroInterp() : constant(cls(v), 0); }
  // Loaded once at entry (sequence point -1 reads zeros), so setup computes it for every use;
  // dead-code removal drops it where nothing uses it. (Emitted before any statement: a node
  // inserted later at the front would upset a loop's rollback, which truncates its block.)
  int zeroInterp() const { return zero_interp_; }

  // Element `index` of a parameter-sized array: loads from the instance's parameters, which sit
  // after the fixed part at F + count * offset + index * components (CompiledPrimitive::paramOffset).
  Binding loadSized(const Binding& array, int index, const Type& element);

  int paramValue(int slot, ValueClass c);

  int toFloat(int v);

  // Converts a lowered value to the declared type `to` (int -> float where needed).
  std::vector<int> convert(const Binding& from, const Type& to);

  // ---- statements: return true if the block always ends in `return` (lower_statements.cpp) ----
  bool statements(const std::vector<StmtPtr>& body);

  bool scoped(const std::vector<StmtPtr>& body);

  bool statement(const Stmt& s);
  bool statementAt(const Stmt& s);

  // The carried values of loop `index` (default: the innermost) take the current bindings.
  void carryCopies(SourceLoc loc, int index = -1);

  // Leaving `levels` loops under varying control makes each of them varying.
  void noteExit(int levels);

  // `return value;` in an inlined function: set the result and leave every loop up to the call.
  bool functionReturn(const Stmt& s);

  // Lowers a loop. Whether it is varying, and which carried values are, is first guessed from
  // sema; if lowering finds a varying value reaching a value guessed uniform, or a varying exit
  // from a loop guessed uniform, it lowers the loop again with that corrected (at most once per
  // carried value). That makes the classification exact per call site of inlined functions.
  void lowerLoop(const LoopSpec& spec);

  // The variables among `names` visible here, once each.
  std::vector<int> visibleBindings(const std::vector<std::string>& names) const;

  void loop(const Stmt& s);

  // A call of a user function, inlined: the body runs as a loop of one iteration whose result
  // is a carried value, so `return` anywhere (under varying control too) is a break.
  Binding callFunction(const Expr& e, const Unit& fn);

  // The body of function (or field) `fn` inlined with `args` as its parameters' values.
  Binding inlineFunction(const Unit& fn, const std::vector<Binding>& args, SourceLoc call_loc);

  bool namedBranches(const InterpolationCase& c);
  bool ifStatement(const Stmt& s);
  // A varying else-if chain of `links` (the first one's condition lowered as `first_cond`) as
  // ifs one mask deep each.
  bool ifChain(const std::vector<const Stmt*>& links, int first_cond);

  // An if node on `cond`: each part lowers its branch and says whether it always returns;
  // variables the branches leave different get merge copies.
  bool branch(int cond, SourceLoc loc, const std::function<bool()>& then_part, const std::function<bool()>& else_part);

  // Resolves an assignment target to its binding and the slots it may write: one candidate
  // range per element a run-time index can select, each with the condition (-1: always) under
  // which it is the one written. An index outside the array selects none: the write is lost.
  struct TargetSlots {
    int first;
    int cond;
  };
  bool target(const Expr& e, int& bind, std::vector<TargetSlots>& slots, int& count);

  // dst = cond ? a : b, for a value of any class.
  int select(int cond, int a, int b);

  void assign(const Stmt& s);

  // ---- expressions (lower_expressions.cpp) ----
  Binding scalar(Type t, int v);

  Binding expr(const Expr& e);

  Binding exprAt(const Expr& e);

  Binding binary(const Expr& e);

  // + - * / % on scalars, aggregates (componentwise, scalars broadcast) and interpolator_data.
  Binding arith(const std::string& op, const Binding& a, const Binding& b, const Type& result, SourceLoc loc);

  int fadd(int a, int b) { return emit(Op::FAdd, ValueClass::F32, false, a, b); }
  int fsub(int a, int b) { return emit(Op::FSub, ValueClass::F32, false, a, b); }
  int fmul(int a, int b) { return emit(Op::FMul, ValueClass::F32, false, a, b); }
  Binding vec(const Type& t, std::vector<int> comps);
  // x*x' + y*y' + z*z' of two points, vectors or normals (a point's w is not part of it).
  int dot3(const Binding& a, const Binding& b);
  Binding sub3(const Binding& a, const Binding& b);

  // Componentwise maths over scalars and aggregates (a scalar argument applies to every
  // component). The result type was decided by sema.
  Binding componentwise(const Expr& e, const std::vector<Binding>& args, int arity);

  int state(StateValue s) { return emit(Op::LoadState, ValueClass::F32, false, -1, -1, -1, static_cast<int>(s)); }

  // Whether value v is the constant x.
  bool isConstF(int v, float x) const;
  // a * b for the transforms below, where b may be a literal: a literal 0 contributes nothing
  // (-1: no term), a literal 1 contributes a itself. So a direction (w = 0) or a unit vector
  // costs only the columns it uses: object(eye(unscreen(point(1, 0, 0, 0)))) is one column's
  // worth of work, all of it in setup.
  int transformTerm(int a, int b);
  int sumTerms(int sum, int term);

  // The state's column-major matrix `m` (its upper n x n; transposed if asked) times the n
  // components of v.
  Binding scalarMatrixTimes(const Type& type, StateValue m, const std::vector<int>& v, int n, bool transposed);
  int stateOn(StateValue s) { return emit(Op::FLt, ValueClass::Bool, false, constF(0.5f), state(s)); }

  // GL's front face for a window-space orientation (> 0: counter-clockwise):
  // (orientation > 0) == (glFrontFace is GL_CCW).
  int frontFacing(int orientation);

  // A call of another primitive (sema checked it is uniform): the arguments fill the outgoing
  // parameter block and sequence points, then Emit submits the callee's instance.
  Binding callPrimitive(const Expr& e, const CompiledPrimitive& callee);

  Binding call(const Expr& e);

  // ---- fixed<bits,frac> (lower_fixed.cpp; the arithmetic is compiler/fixed_point.h's) ----
  // One instruction on word pairs: a 4-operand emit.
  int emitWord(Op op, ValueClass c, int a, int b, int cc, int d, int imm);
  // Both words of a fixed result: op on the pairs (a, b) and (c, d).
  Binding fixedPair(Op op, const Type& result, int a, int b = -1, int c = -1, int d = -1);
  // A number or fixed value converted to fixed type `to` (rounded, saturated).
  Binding toFixed(const Binding& from, const Type& to);
  // A fixed value as a float binding (correctly rounded); any other binding unchanged.
  Binding asFloat(const Binding& v);
  int fixedToInt(const Binding& v);
  // + - * / where an operand is fixed: exact when both are fixed or int, else in floats.
  Binding fixedArith(const std::string& op, const Binding& a, const Binding& b, const Type& result, SourceLoc loc);
  // A comparison where an operand is fixed (a Bool value).
  int fixedCompare(const std::string& op, const Binding& a, const Binding& b);
  Binding fixedNegate(const Binding& a);
  // Conversions and abs / min / max / clamp whose result sema typed as fixed (or float(q), int(q)).
  std::optional<Binding> fixedCall(const Expr& e, const std::vector<Binding>& args);

  // ---- matrices (lower_matrices.cpp) ----
  int sumOfProducts(const std::vector<std::pair<int, int>>& terms);
  // m times a matrix, point, vector (upper 3x3) or normal (inverse transpose of the upper 3x3).
  Binding matrixTimes(const Binding& m, const Binding& v, const Type& result);
  std::array<int, 9> cofactors3(const Binding& m);  // of the upper 3x3, row-major
  int minor3(const Binding& m, const int rows[3], const int cols[3]);
  std::optional<Binding> matrixCall(const std::string& f, const Expr& e, const std::vector<Binding>& args);
};

}  // namespace pf::lowering
