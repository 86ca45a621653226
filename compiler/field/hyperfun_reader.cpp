// HyperFun to FieldTape: runs a parsed model at compile time, symbolically (hyperfun_reader.h).
//
// Statements execute in order on an environment of Reals (hyperfun_library.h): numbers known
// now, or values on the tape. Whatever depends on the point x ends up as tape instructions.
// An `if` whose condition is known now runs one branch; one whose condition depends on x runs
// both, each on its own copy of the environment, and joins them with the tape's Select: every
// variable and array item the branches leave different becomes `cond ? then : else`. A `while`
// is unrolled, so its condition and every index must be known now. An object call compiles the
// callee afresh on copies of the caller's arrays (HyperFun passes x and a by value and copies s
// back), which inlines it; the builder shares what the copies have in common.
#include "compiler/field/hyperfun_reader.h"

#include <cmath>
#include <cstdio>
#include <map>

#include "compiler/field/hyperfun_lexer.h"
#include "compiler/field/hyperfun_library.h"
#include "compiler/field/hyperfun_parser.h"
#include "compiler/stack_guard.h"

namespace pf::field {
namespace hyperfun {
namespace {

constexpr int kMaxLoopIterations = 100000;
constexpr long kMaxStatements = 2000000;  // statements executed in all, loops and calls unrolled

struct ArrayValue {
  std::vector<Real> items;
  std::vector<char> assigned;
  ArrayValue() = default;
  ArrayValue(std::vector<Real> values) : items(std::move(values)), assigned(items.size(), 1) {}
  explicit ArrayValue(size_t size) : items(size), assigned(size, 0) {}
};

// One object being compiled: its arrays (x, a, s and the declared ones) and its variables.
struct Frame {
  size_t object;  // index in the program
  const ObjectDef& def;
  std::map<std::string, ArrayValue> arrays;
  std::map<std::string, Real> variables;
  // Variables assigned in one branch only of an `if` that depends on x: the if's position.
  std::map<std::string, std::pair<int, int>> one_branch;
};

// A condition's value: a Real that is 0 or 1 when `is_bool` (a comparison, and, or, not), or
// any real (HyperFun's truth: |v| >= EPS).
struct Truth {
  Real value;
  bool is_bool = false;
};

bool sameReal(const Real& a, const Real& b) {
  return a.is_known == b.is_known && (a.is_known ? (a.value == b.value || (a.value != a.value && b.value != b.value))
                                                 : a.id == b.id);
}

double hfRound(double v) {
  const double c = std::ceil(v);
  return c - v > 0.5 ? c - 1.0 : c;
}
bool truth(double v) { return std::fabs(v) >= kEps; }
std::string quoted(const std::string& s) { return "'" + s + "'"; }
std::string formatNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

class Compiler {
 public:
  Compiler(const SourceFile& file, const Program& program, DiagnosticLog& log, FieldTapeBuilder& builder)
      : file_(file), program_(program), log_(log), alg_(builder) {}

  TapeAlgebra& algebra() { return alg_; }

  // The value of object `index` for the given x, a and s items; s is updated (HyperFun copies
  // the callee's s back into the caller's).
  Real compileObject(size_t index, std::vector<Real> x, std::vector<Real> a, std::vector<Real>& s) {
    const ObjectDef& def = program_.objects[index];
    Frame frame{index, def, {}, {}, {}};
    frame.arrays["x"] = ArrayValue(std::move(x));
    frame.arrays["a"] = ArrayValue(std::move(a));
    frame.arrays["s"] = ArrayValue(s);
    for (const ArrayDecl& d : def.arrays) frame.arrays[d.name] = ArrayValue(static_cast<size_t>(d.size));
    run(frame, def.body);
    const Real result = real(frame, def.result);
    s = frame.arrays["s"].items;
    return result;
  }

 private:
  [[noreturn]] void fail(int line, int col, std::string message) {
    log_.error({&file_, line, col}, std::move(message));
    throw CompileAbort();
  }
  [[noreturn]] void fail(const Expr& at, std::string message) { fail(at.line, at.col, std::move(message)); }

  ArrayValue* findArray(Frame& f, const std::string& name) {
    auto it = f.arrays.find(name);
    return it == f.arrays.end() ? nullptr : &it->second;
  }

  // --- Statements ----------------------------------------------------------------------------
  void run(Frame& f, const std::vector<Stmt>& body) {
    for (const Stmt& s : body) statement(f, s);
  }

  void statement(Frame& f, const Stmt& s) {
    if (++statements_ > kMaxStatements)
      fail(s.line, s.col, "the model needs more than " + std::to_string(kMaxStatements) +
                              " statements to compile (loops and object calls are unrolled)");
    if (alg_.tapeSize() > kMaxFieldTapeSize)
      fail(s.line, s.col, "the model unrolls to more than " + std::to_string(kMaxFieldTapeSize) +
                              " tape operations (loops and object calls are unrolled)");
    switch (s.kind) {
      case Stmt::Kind::Assign: {
        if (findArray(f, s.name))
          fail(s.line, s.col,
               quoted(s.name) + " is an array: assign an item ('" + s.name + "[1] = ...;') or a list ('" + s.name +
                   " = [1, 2, 3];')");
        f.variables[s.name] = real(f, s.value);
        f.one_branch.erase(s.name);
        return;
      }
      case Stmt::Kind::AssignElement: {
        ArrayValue& arr = arrayToAssign(f, s);
        const size_t k = index(f, s.index, s.name, arr);
        arr.items[k] = real(f, s.value);
        arr.assigned[k] = 1;
        return;
      }
      case Stmt::Kind::AssignArray: {
        ArrayValue& arr = arrayToAssign(f, s);
        if (s.items.size() != arr.items.size())
          fail(s.value_line, s.value_col, "array " + quoted(s.name) + " has " + std::to_string(arr.items.size()) +
                                              " items, but the list gives " + std::to_string(s.items.size()) +
                                              " (HyperFun wants exactly one number per item)");
        for (size_t k = 0; k < s.items.size(); ++k) {
          arr.items[k] = Real::known(s.items[k]);
          arr.assigned[k] = 1;
        }
        return;
      }
      case Stmt::Kind::If: {
        const Truth t = conditionTruth(f, s.value);
        if (t.value.is_known) {
          run(f, truth(t.value.value) ? s.body : s.else_body);
          return;
        }
        const Real cond = truthOf(t);
        Frame otherwise = f;
        run(f, s.body);
        run(otherwise, s.else_body);
        join(f, otherwise, cond, s);
        return;
      }
      case Stmt::Kind::While: {
        int iterations = 0;
        while (condition(f, s)) {
          if (++iterations > kMaxLoopIterations)
            fail(s.line, s.col, "loop does not end within " + std::to_string(kMaxLoopIterations) +
                                    " iterations (loops are unrolled when the model is compiled)");
          run(f, s.body);
        }
        return;
      }
    }
  }

  ArrayValue& arrayToAssign(Frame& f, const Stmt& s) {
    ArrayValue* arr = findArray(f, s.name);
    if (!arr)
      fail(s.line, s.col, quoted(s.name) + " is not an array (declare it first: 'array " + s.name + "[3];')");
    return *arr;
  }

  // --- Conditions ----------------------------------------------------------------------------
  // A while loop's condition: it must be known now (the loop is unrolled).
  bool condition(Frame& f, const Stmt& s) {
    const Truth t = conditionTruth(f, s.value);
    if (!t.value.is_known)
      fail(s.value_line, s.value_col,
           "condition depends on the point x: a 'while' that loops a different number of times at different points "
           "is not supported (loops are unrolled when the model is compiled; an 'if' on x is fine)");
    return truth(t.value.value);
  }

  // A condition's value as HyperFun computes it: comparisons give 1 or 0 (= and /= within
  // EPS), and/or/not read their operands' truth. Known operands fold now, in double; the rest
  // become the tape's Less/LessEq (0 or 1 per point) combined by min, max and 1 - v.
  Truth conditionTruth(Frame& f, const Expr& e) {
    if (stackNearlyExhausted()) tooDeepForTheStack(e);
    TapeAlgebra& m = alg_;
    if (e.kind == Expr::Kind::Unary && e.op == Op::Not) {
      const Truth a = conditionTruth(f, e.args[0]);
      if (a.value.is_known) return {Real::known(truth(a.value.value) ? 0.0 : 1.0), true};
      return {m.sub(Real::known(1.0), truthOf(a)), true};
    }
    if (e.kind == Expr::Kind::Binary && e.op >= Op::Less) {
      const Truth ta = conditionTruth(f, e.args[0]);
      const Truth tb = conditionTruth(f, e.args[1]);
      const Real a = ta.value, b = tb.value;
      if (a.is_known && b.is_known) {
        bool r = false;
        switch (e.op) {
          case Op::Less: r = a.value < b.value; break;
          case Op::LessEq: r = a.value <= b.value; break;
          case Op::Greater: r = a.value > b.value; break;
          case Op::GreaterEq: r = a.value >= b.value; break;
          case Op::Equal: r = std::fabs(a.value - b.value) < kEps; break;
          case Op::NotEqual: r = std::fabs(a.value - b.value) >= kEps; break;
          case Op::And: r = truth(a.value) && truth(b.value); break;
          case Op::Or: r = truth(a.value) || truth(b.value); break;
          default: break;
        }
        return {Real::known(r ? 1.0 : 0.0), true};
      }
      switch (e.op) {
        case Op::Less: return {compare(FieldOp::Less, a, b), true};
        case Op::LessEq: return {compare(FieldOp::LessEq, a, b), true};
        case Op::Greater: return {compare(FieldOp::Less, b, a), true};
        case Op::GreaterEq: return {compare(FieldOp::LessEq, b, a), true};
        case Op::Equal: return {compare(FieldOp::Less, m.abs(m.sub(a, b)), Real::known(kEps)), true};
        case Op::NotEqual: return {compare(FieldOp::LessEq, Real::known(kEps), m.abs(m.sub(a, b))), true};
        case Op::And: return {m.min(truthOf(ta), truthOf(tb)), true};
        case Op::Or: return {m.max(truthOf(ta), truthOf(tb)), true};
        default: failUnexpected(e, "unexpected operator in a condition");
      }
    }
    return {real(f, e), false};
  }

  // 1 where the condition holds, 0 elsewhere.
  Real truthOf(const Truth& t) {
    if (t.is_bool) return t.value;
    if (t.value.is_known) return Real::known(truth(t.value.value) ? 1.0 : 0.0);
    return compare(FieldOp::LessEq, Real::known(kEps), alg_.abs(t.value));
  }

  Real compare(FieldOp op, Real a, Real b) { return op == FieldOp::Less ? alg_.less(a, b) : alg_.lessEq(a, b); }

  Real select(Real cond, Real if_true, Real if_false) {
    if (sameReal(if_true, if_false)) return if_true;
    return alg_.select(cond, if_true, if_false);
  }

  // After an `if` on x: `f` holds what the then-branch left, `otherwise` what the else-branch
  // left; f becomes cond ? then : else, value by value. A variable only one branch assigned
  // (and that had no value before) has no value at the points of the other: reading it later
  // is an error naming the if.
  void join(Frame& f, Frame& otherwise, Real cond, const Stmt& s) {
    for (auto it = f.variables.begin(); it != f.variables.end();) {
      auto other = otherwise.variables.find(it->first);
      if (other == otherwise.variables.end()) {
        f.one_branch[it->first] = {s.line, s.col};
        it = f.variables.erase(it);
        continue;
      }
      it->second = select(cond, it->second, other->second);
      ++it;
    }
    for (const auto& [name, value] : otherwise.variables)
      if (!f.variables.count(name) && !f.one_branch.count(name)) f.one_branch[name] = {s.line, s.col};
    for (const auto& [name, at] : otherwise.one_branch)
      if (!f.variables.count(name)) f.one_branch.emplace(name, at);
    for (auto& [name, arr] : f.arrays) {
      const ArrayValue& other = otherwise.arrays.at(name);
      for (size_t k = 0; k < arr.items.size(); ++k) {
        if (arr.assigned[k] && other.assigned[k])
          arr.items[k] = select(cond, arr.items[k], other.items[k]);
        else
          arr.assigned[k] = 0;  // assigned by one branch only: as if never assigned
      }
    }
  }

  // --- Expressions ---------------------------------------------------------------------------
  // The 0-based item that `index` selects in `arr` (HyperFun rounds; indexes start at 1).
  size_t index(Frame& f, const Expr& index, const std::string& name, const ArrayValue& arr) {
    const Real v = real(f, index);
    if (!v.is_known)
      fail(index, "the index of " + quoted(name) +
                      " depends on the point x: indexes must be known when the model is compiled");
    if (std::isnan(v.value)) fail(index, "the index of " + quoted(name) + " is not a number");
    const double k = hfRound(v.value);
    if (k < 1.0 || k > static_cast<double>(arr.items.size()))
      fail(index, "index " + formatNumber(k) + " is out of range for " + quoted(name) + " (1 to " +
                      std::to_string(arr.items.size()) + ")");
    return static_cast<size_t>(k) - 1;
  }

  // An expression's value. real() recurses once per level of nesting (up to the parser's 4000),
  // so its own frame holds nothing but the recursion: each case's work, and every message
  // built for an error, is in a function of its own (never inlined into it) -- under
  // AddressSanitizer a std::string temporary costs a padded stack slot per level.
  Real real(Frame& f, const Expr& e) {
    if (stackNearlyExhausted()) tooDeepForTheStack(e);
    switch (e.kind) {
      case Expr::Kind::Number:
        return Real::known(e.number);
      case Expr::Kind::Name:
        return variable(f, e);
      case Expr::Kind::Element:
        return element(f, e);
      case Expr::Kind::Unary:
        return unaryOperator(e, real(f, e.args[0]));
      case Expr::Kind::Binary: {
        if (e.op >= Op::Less) failConditionOnly(e);
        const Real a = real(f, e.args[0]);
        return binaryOperator(e, a, real(f, e.args[1]));
      }
      case Expr::Kind::Call:
        return call(f, e);
    }
    failUnexpected(e, "unexpected expression");
  }

  // (A thread with a small stack: the parser's limit assumes 1 MB.)
  [[noreturn, gnu::noinline]] void tooDeepForTheStack(const Expr& e) {
    fail(e, "nested too deep for this thread's stack (split it with variables)");
  }

  [[gnu::noinline]] Real element(Frame& f, const Expr& e) {
    ArrayValue* arr = findArray(f, e.name);
    if (!arr)
      fail(e, quoted(e.name) + (f.variables.count(e.name) ? " is a variable, not an array" : " is not an array"));
    const size_t k = index(f, e.args[0], e.name, *arr);
    if (!arr->assigned[k])
      fail(e, quoted(e.name + "[" + std::to_string(k + 1) + "]") + " is used before it is assigned");
    return arr->items[k];
  }

  [[gnu::noinline]] Real unaryOperator(const Expr& e, Real a) {
    if (e.op == Op::Plus) return a;
    if (e.op == Op::Negate || e.op == Op::Complement) return alg_.neg(a);
    failConditionOnly(e);
  }

  [[gnu::noinline]] Real binaryOperator(const Expr& e, Real a, Real b) {
    TapeAlgebra& m = alg_;
    switch (e.op) {
      case Op::Add: return m.add(a, b);
      case Op::Sub: return m.sub(a, b);
      case Op::Mul: return m.mul(a, b);
      case Op::Div: return m.div(a, b);
      case Op::Pow: return m.pow(a, b);
      case Op::Union: return m.unite(a, b);
      case Op::Intersection: case Op::Product: return m.intersect(a, b);
      case Op::Subtraction: return m.subtract(a, b);
      default: break;
    }
    fail(e, "unexpected operator " + opSpelling(e.op));
  }

  [[noreturn, gnu::noinline]] void failConditionOnly(const Expr& e) {
    fail(e, opSpelling(e.op) + " is allowed only in the condition of 'if' or 'while'");
  }
  [[noreturn, gnu::noinline]] void failUnexpected(const Expr& e, const char* message) { fail(e, message); }

  [[gnu::noinline]] Real variable(Frame& f, const Expr& e) {
    auto it = f.variables.find(e.name);
    if (it != f.variables.end()) return it->second;
    if (auto one = f.one_branch.find(e.name); one != f.one_branch.end())
      fail(e, quoted(e.name) + " is assigned in only one branch of the 'if' at line " + std::to_string(one->second.first) +
                  ", whose condition depends on the point x: assign it in both branches, or before the 'if'");
    if (findArray(f, e.name))
      fail(e, quoted(e.name) + " is an array: use one of its items ('" + e.name + "[1]'), or pass it to a function");
    if (objectIndex(e.name)) fail(e, quoted(e.name) + " is an object: call it ('" + e.name + "(x, a)')");
    if (f.def.assigned.count(e.name)) fail(e, quoted(e.name) + " is used before it is assigned");
    fail(e, quoted(e.name) + " is not defined (no variable, array or object has this name)");
  }

  std::optional<size_t> objectIndex(const std::string& name) const {
    for (size_t i = 0; i < program_.objects.size(); ++i)
      if (program_.objects[i].name == name) return i;
    return std::nullopt;
  }

  Real call(Frame& f, const Expr& e) {
    if (const LibraryFunction* fn = findLibraryFunction(e.name)) return libraryCall(f, e, *fn);
    const std::optional<size_t> callee = objectIndex(e.name);
    if (!callee) fail(e, "unknown function " + quoted(e.name));
    if (*callee == f.object) fail(e, "object " + quoted(e.name) + " cannot call itself");
    if (*callee > f.object)
      fail(e, "object " + quoted(e.name) + " is defined after " + quoted(f.def.name) +
                  ": an object can only call the objects defined before it");
    return objectCall(f, e, *callee);
  }

  // An array argument: the name of an array, of `size` items unless size is 0, all assigned.
  ArrayValue& arrayArgument(Frame& f, const Expr& arg, const std::string& what, size_t size = 0,
                            const std::string& wanted = {}) {
    ArrayValue* arr = arg.kind == Expr::Kind::Name ? findArray(f, arg.name) : nullptr;
    if (!arr) fail(arg, what + " must be the name of an array (x, a, s or a declared array)");
    if (size && arr->items.size() != size)
      fail(arg, what + " takes " + wanted + ", but " + quoted(arg.name) + " has " + std::to_string(arr->items.size()) +
                    " items");
    for (size_t k = 0; k < arr->assigned.size(); ++k)
      if (!arr->assigned[k])
        fail(arg, quoted(arg.name + "[" + std::to_string(k + 1) + "]") +
                      " is not assigned (HyperFun passes only arrays whose items are all assigned)");
    return *arr;
  }

  Real libraryCall(Frame& f, const Expr& e, const LibraryFunction& fn) {
    const std::string fname(fn.name);
    if (!fn.build) {
      std::string message(fn.unsupported);
      for (size_t at = message.find('$'); at != std::string::npos; at = message.find('$'))
        message.replace(at, 1, fname);
      fail(e, message);
    }
    if (e.args.size() != fn.kinds.size())
      fail(e, quoted(fname) + " takes " + std::to_string(fn.kinds.size()) + " argument" +
                  (fn.kinds.size() == 1 ? "" : "s") + " (" + std::string(fn.params) + "), found " +
                  std::to_string(e.args.size()));
    LibraryCall c{alg_, fn, {}, {}, {}};
    c.reals.resize(e.args.size());
    c.arrays.resize(e.args.size(), nullptr);
    c.array_names.resize(e.args.size());
    for (size_t i = 0; i < e.args.size(); ++i) {
      if (fn.kinds[i] == 'R') {
        c.reals[i] = real(f, e.args[i]);
      } else {
        ArrayValue& arr = arrayArgument(f, e.args[i], "argument " + std::to_string(i + 1) + " of " + quoted(fname));
        c.arrays[i] = &arr.items;
        c.array_names[i] = e.args[i].name;
      }
    }
    try {
      return fn.build(c);
    } catch (const LibraryError& err) {
      fail(err.argument >= 0 ? e.args[static_cast<size_t>(err.argument)] : e, err.message);
    }
  }

  Real objectCall(Frame& f, const Expr& e, size_t callee_index) {
    const ObjectDef& callee = program_.objects[callee_index];
    if (e.args.size() != 2 && e.args.size() != 3)
      fail(e, "object " + quoted(callee.name) + " takes 2 or 3 arrays (x, a[, s]), found " +
                  std::to_string(e.args.size()) + " arguments");
    const int sizes[3] = {callee.x_size, callee.a_size, callee.s_size};
    const char* names[3] = {"x", "a", "s"};
    std::vector<Real> items[3];
    for (size_t i = 0; i < e.args.size(); ++i) {
      const std::string wanted = std::string(names[i]) + "[" + std::to_string(sizes[i]) + "]";
      const size_t size = static_cast<size_t>(sizes[i]);
      items[i] = arrayArgument(f, e.args[i], "object " + quoted(callee.name), size, wanted).items;
    }
    if (e.args.size() == 2) {
      if (callee.s_size != 1)
        fail(e, "object " + quoted(callee.name) + " has s[" + std::to_string(callee.s_size) +
                    "]: pass an array of that size as a third argument");
      items[2].assign(1, Real::known(0.0));
    }
    const Real value = compileObject(callee_index, items[0], items[1], items[2]);
    if (e.args.size() == 3) findArray(f, e.args[2].name)->items = items[2];
    return value;
  }

  const SourceFile& file_;
  const Program& program_;
  DiagnosticLog& log_;
  TapeAlgebra alg_;
  long statements_ = 0;
};

std::string lowercase(std::string s) {
  for (char& c : s)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return s;
}

}  // namespace
}  // namespace hyperfun

std::optional<FieldTape> readHyperFunModel(const std::string& name, std::string text, DiagnosticLog& log,
                                           const std::vector<double>& params, const std::string& object,
                                           double time, std::vector<FieldTape>* attributes) {
  using namespace hyperfun;
  const SourceFile& file = log.addSource(name, std::move(text));
  const int errors_before = log.errorCount();
  const std::vector<Token> tokens = scanHyperFun(file, log);
  if (log.errorCount() > errors_before) return std::nullopt;
  const std::optional<Program> program = parseHyperFun(file, tokens, log);
  if (!program) return std::nullopt;

  // The object drawn: `object` if the file has it, else the first (as hfp -o).
  size_t drawn = 0;
  const std::string wanted = lowercase(object);
  for (size_t i = 0; i < program->objects.size(); ++i)
    if (program->objects[i].name == wanted) drawn = i;
  const ObjectDef& def = program->objects[drawn];
  if (params.size() > static_cast<size_t>(def.a_size)) {
    log.error({&file, def.a_line, def.a_col}, std::to_string(params.size()) + " parameters given, but " +
                                                  quoted(def.name) + " has a[" + std::to_string(def.a_size) + "]");
    return std::nullopt;
  }

  FieldTapeBuilder builder;
  Compiler compiler(file, *program, log, builder);
  TapeAlgebra& m = compiler.algebra();
  // x[1..3] are the point, x[4] the time; further coordinates are fixed at 0.
  std::vector<Real> x;
  for (int k = 0; k < def.x_size; ++k)
    x.push_back(k == 0 ? m.x() : k == 1 ? m.y() : k == 2 ? m.z() : Real::known(k == 3 ? time : 0.0));
  std::vector<Real> a(static_cast<size_t>(def.a_size), Real::known(0.0));
  for (size_t k = 0; k < params.size(); ++k) a[k] = Real::known(params[k]);
  std::vector<Real> s(static_cast<size_t>(def.s_size), Real::known(0.0));
  try {
    const Real value = compiler.compileObject(drawn, std::move(x), std::move(a), s);
    if (attributes) {
      attributes->clear();
      if (def.declares_s)
        for (const Real& item : s) attributes->push_back(builder.tapeOf(m.materialize(item)));
    }
    return builder.finish(m.materialize(value));
  } catch (const CompileAbort&) {
    return std::nullopt;
  }
}

}  // namespace pf::field
