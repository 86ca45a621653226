// Field units -> field tapes: the language's front end, lowering and passes, then a symbolic
// run of the IR (see field_unit.h for what a field may do with its point).
#include "compiler/field/field_unit.h"

#include <cmath>
#include <cstdlib>
#include <map>

#include "compiler/compiler.h"
#include "compiler/lower.h"
#include "compiler/passes.h"
#include "compiler/scalar_ops.h"

namespace pf::field {

namespace {

// A value during the symbolic run: known at compile time (its 32-bit pattern), or a value of
// the tape being built (point-dependent floats, and bools as 1 or 0; point-dependent ints have
// no tape value -- using one is the error).
struct Symbol {
  bool known = false;
  uint32_t bits = 0;
  uint32_t node = kNoNode;
  // A point-dependent value a tape cannot hold (floor of p, ...): the index of its error, raised
  // only where the value is used -- the unchosen arm of a ?: that the IR computed regardless is
  // no error.
  int poison = -1;
  static constexpr uint32_t kNoNode = 0xffffffffu;
};

// The user's name for an operation a tape cannot evaluate on a point-dependent value.
const char* sourceName(Op op) {
  switch (op) {
    case Op::FFloor: return "floor (and fract, mod)";
    case Op::FCeil: return "ceil";
    case Op::FNoise: return "noise";
    case Op::F2I: return "conversion to int";
    case Op::QAdd: case Op::QSub: case Op::QMul: case Op::QDiv: case Op::QNeg: case Op::QAbs:
    case Op::QLt: case Op::QLe: case Op::QEq: case Op::QFromF: case Op::QFromI: case Op::QToF:
    case Op::QToI: case Op::QConv:
      return "fixed-point arithmetic (fixed<bits,frac>)";
    default: return nullptr;
  }
}

// Raised after the first error: the run stops there.
struct Stop {};

class TapeTranslator {
 public:
  TapeTranslator(const IrFunction& f, const std::vector<float>& params, DiagnosticLog& log)
      : f_(f), params_(params), log_(log), env_(f.values.size()) {}

  std::optional<FieldTape> run(SourceLoc field_loc) {
    field_loc_ = field_loc;
    try {
      block(f_.body);
    } catch (const Stop&) {
      return std::nullopt;
    }
    if (result_ == Symbol::kNoNode) {  // lowering always ends a field with ShadeOut
      log_.error(field_loc, "field '" + f_.name + "' computes no value");
      return std::nullopt;
    }
    return builder_.finish(result_);
  }

 private:
  enum class Flow { Normal, Break, Continue };
  struct Outcome {
    Flow flow = Flow::Normal;
    int levels = 0;  // Break: loops still to leave
  };

  const IrFunction& f_;
  const std::vector<float>& params_;
  DiagnosticLog& log_;
  FieldTapeBuilder builder_;
  std::vector<Symbol> env_;  // by IR value id (merge values are overwritten as the run goes)
  uint32_t result_ = Symbol::kNoNode;
  long iterations_ = 0;
  SourceLoc field_loc_;
  std::vector<std::pair<SourceLoc, std::string>> poisons_;  // Symbol::poison -> its error

  [[noreturn]] void fail(SourceLoc loc, const std::string& message) {
    log_.error(loc, message);
    // An error inside an inlined function (the standard library's, say) names the field too.
    if (loc.file != field_loc_.file && field_loc_.file)
      log_.note(field_loc_, "in field '" + f_.name + "', through the functions it calls");
    throw Stop{};
  }
  [[noreturn]] void failPoisoned(const Symbol& s) { fail(poisons_[static_cast<size_t>(s.poison)].first, poisons_[static_cast<size_t>(s.poison)].second); }

  Symbol get(int v, SourceLoc loc) {
    if (v < 0) return {true, 0};
    const Value& val = f_.values[static_cast<size_t>(v)];
    switch (val.origin) {
      case Value::Origin::Const: return {true, val.bits};
      case Value::Origin::Param: return {true, fromF(params_[static_cast<size_t>(val.index)])};
      case Value::Origin::FieldPoint:
        return {false, 0, val.index == 0 ? builder_.x() : val.index == 1 ? builder_.y() : builder_.z()};
      case Value::Origin::Builtin:
        fail(loc, "this reads a pixel's built-in (X, Y, Z, P or N) through a function: a field is a function of its point alone");
      case Value::Origin::Temp: break;
    }
    return env_[static_cast<size_t>(v)];
  }

  // The tape value of a float operand.
  uint32_t node(int v, SourceLoc loc) {
    const Symbol s = get(v, loc);
    if (s.poison >= 0) failPoisoned(s);
    if (s.known) return builder_.constant(asF(s.bits));
    if (s.node == Symbol::kNoNode) fail(loc, "a field's value cannot come from a point-dependent int or bool");
    return s.node;
  }

  bool knownValue(int v, SourceLoc loc) { return get(v, loc).known; }

  // A condition that must be decided at compile time.
  bool decide(int cond, SourceLoc loc, const char* what) {
    if (const Symbol s = get(cond, loc); s.poison >= 0) failPoisoned(s);
    if (!knownValue(cond, loc))
      fail(loc, std::string(what) + " depends on the field's point: a field's loops must run the same number of times "
                                    "at every point (an 'if' or ?: on the point is fine)");
    return get(cond, loc).bits != 0;
  }

  void set(int dst, Symbol s) { env_[static_cast<size_t>(dst)] = s; }
  void setNode(int dst, uint32_t n, SourceLoc loc) {
    if (builder_.size() > kMaxFieldTapeSize)
      fail(loc, "field '" + f_.name + "' unrolls to more than " + std::to_string(kMaxFieldTapeSize) + " tape operations");
    set(dst, {false, 0, n});
  }

  Outcome block(const IrBlock& b) {
    for (const IrNode& n : b) {
      Outcome o;
      if (n.kind == IrNode::Kind::If) {
        o = ifNode(n);
      } else if (n.kind == IrNode::Kind::Loop) {
        o = loop(n);
      } else {
        o = inst(n.inst);
      }
      if (o.flow != Flow::Normal) return o;
    }
    return {};
  }

  // --- Point-dependent control flow --------------------------------------------------------
  // An if decided at compile time runs one branch. One whose condition depends on the point runs
  // both, each on its own copy of the environment, and joins them with the tape's Select: every
  // value the branches leave different becomes cond ? then : else (a point-dependent int cannot
  // be chosen so: it becomes an error where it is used). This is the pixel executor's masked
  // execution done symbolically: `alive_` is the set of points still running here (a 1/0 tape
  // value), and a break, continue or return (a break out of the function's run-once loop) taken
  // at some points only records those points' values as an exit of its loop, merged back where
  // the loop ends (break) or its body ends (continue). A loop's count must still be known.
  static constexpr uint32_t kAll = Symbol::kNoNode;       // predicate: every point
  static constexpr uint32_t kNone = Symbol::kNoNode - 1;  // predicate: no point
  struct Exit {
    uint32_t points;            // where it was taken (a predicate)
    std::vector<Symbol> env;    // the values there
  };
  struct LoopFrame {
    uint32_t alive_at_entry;
    uint32_t alive;             // points not yet gone from this loop (break, or a break past it)
    std::vector<Exit> breaks;   // this loop's partial breaks, in the order they were taken
    std::vector<Exit> continues;  // partial continues of the current iteration
  };
  uint32_t alive_ = kAll;
  std::vector<LoopFrame> loops_;
  int exits_recorded_ = 0;

  uint32_t both(uint32_t a, uint32_t b) {
    if (a == kNone || b == kNone) return kNone;
    if (a == kAll) return b;
    if (b == kAll) return a;
    return builder_.binary(FieldOp::Min, a, b);
  }
  uint32_t either(uint32_t a, uint32_t b) {
    if (a == kAll || b == kAll) return kAll;
    if (a == kNone) return b;
    if (b == kNone) return a;
    return builder_.binary(FieldOp::Max, a, b);
  }
  uint32_t negate(uint32_t a) {
    if (a == kAll) return kNone;
    if (a == kNone) return kAll;
    return builder_.binary(FieldOp::Sub, builder_.constant(1.0f), a);
  }

  // Value v where `points` hold: t, elsewhere e.
  Symbol choose(size_t v, uint32_t points, const Symbol& t, const Symbol& e, SourceLoc loc) {
    if (points == kAll) return t;
    if (points == kNone) return e;
    if (t.known == e.known && t.bits == e.bits && t.node == e.node && t.poison == e.poison) return e;
    // A value one side never set (a temporary of the other branch) is read only where that
    // branch ran: it keeps the side that has it.
    const auto unset = [](const Symbol& s) { return !s.known && s.node == Symbol::kNoNode && s.poison < 0; };
    if (unset(t)) return e;
    if (unset(e)) return t;
    if (t.poison >= 0) return t;
    if (e.poison >= 0) return e;
    const ValueClass cls = f_.values[v].cls;
    if (cls == ValueClass::F32 || cls == ValueClass::Bool) {
      const bool b = cls == ValueClass::Bool;
      return {false, 0, builder_.select(points, b ? boolOf(t) : floatOf(t), b ? boolOf(e) : floatOf(e))};
    }
    poisons_.push_back({loc, "an int chosen by a condition that depends on the field's point has no tape form: "
                             "a field's point-dependent choices are between floats"});
    return {false, 0, Symbol::kNoNode, static_cast<int>(poisons_.size()) - 1};
  }

  // env_ = the exits' values at their points (the first exit taken wins), env_ elsewhere.
  void mergeExits(const std::vector<Exit>& exits, SourceLoc loc) {
    for (size_t k = exits.size(); k-- > 0;)
      for (size_t v = 0; v < env_.size(); ++v) env_[v] = choose(v, exits[k].points, exits[k].env[v], env_[v], loc);
    if (builder_.size() > kMaxFieldTapeSize)
      fail(loc, "field '" + f_.name + "' unrolls to more than " + std::to_string(kMaxFieldTapeSize) + " tape operations");
  }

  // The points `points` take `flow` (a break or continue) with values `env`: they leave.
  void recordExit(const Outcome& flow, uint32_t points, std::vector<Symbol> env, SourceLoc loc) {
    const int levels = flow.flow == Flow::Break ? flow.levels : 1;
    if (levels < 1 || static_cast<size_t>(levels) > loops_.size()) fail(loc, "a break or continue outside a loop");
    const size_t target = loops_.size() - static_cast<size_t>(levels);
    if (flow.flow == Flow::Break) {
      loops_[target].breaks.push_back({points, std::move(env)});
      for (size_t i = target; i < loops_.size(); ++i) loops_[i].alive = both(loops_[i].alive, negate(points));
    } else {
      loops_.back().continues.push_back({points, std::move(env)});
    }
    alive_ = both(alive_, negate(points));
    ++exits_recorded_;
  }

  Outcome ifNode(const IrNode& n) {
    const SourceLoc loc = n.inst.loc;
    const Symbol c = get(n.cond, loc);
    if (c.poison >= 0) failPoisoned(c);
    if (c.known) return block(c.bits != 0 ? *n.then_block : *n.else_block);
    const uint32_t cond = boolNode(n.cond, loc);
    const uint32_t saved_alive = alive_, result_before = result_;
    const int exits_before = exits_recorded_;
    std::vector<Symbol> before = env_;
    alive_ = both(saved_alive, cond);
    const Outcome then_flow = block(*n.then_block);
    std::vector<Symbol> then_env = std::move(env_);
    const uint32_t then_alive = alive_, then_result = result_;
    env_ = std::move(before);
    result_ = result_before;
    alive_ = both(saved_alive, negate(cond));
    const Outcome else_flow = block(*n.else_block);
    const uint32_t else_alive = alive_;
    const bool then_leaves = then_flow.flow != Flow::Normal, else_leaves = else_flow.flow != Flow::Normal;
    if (then_result != result_) {
      if (then_leaves || else_leaves || then_result == Symbol::kNoNode || result_ == Symbol::kNoNode)
        fail(loc, "field '" + f_.name + "' computes its value in only one branch of this point-dependent 'if'");
      result_ = builder_.select(cond, then_result, result_);
    }
    if (then_leaves && else_leaves && then_flow.flow == else_flow.flow && then_flow.levels == else_flow.levels) {
      // Every point still running here leaves the same way: the enclosing block sees it whole --
      // less the points exits inside the branches took already.
      alive_ = exits_recorded_ != exits_before ? either(then_alive, else_alive) : saved_alive;
      for (size_t v = 0; v < env_.size(); ++v) env_[v] = choose(v, cond, then_env[v], env_[v], loc);
      return then_flow;
    }
    alive_ = saved_alive;
    if (then_leaves) recordExit(then_flow, then_alive, then_env, loc);
    if (else_leaves) recordExit(else_flow, else_alive, env_, loc);
    if (then_leaves) {
      alive_ = else_leaves ? kNone : else_alive;  // the else-branch's points go on, with its values
    } else if (else_leaves) {
      env_ = std::move(then_env);
      alive_ = then_alive;
    } else {
      for (size_t v = 0; v < env_.size(); ++v) env_[v] = choose(v, cond, then_env[v], env_[v], loc);
      // Exits taken inside either branch narrowed its points; otherwise every point goes on.
      alive_ = exits_recorded_ != exits_before ? either(then_alive, else_alive) : saved_alive;
    }
    if (builder_.size() > kMaxFieldTapeSize)
      fail(loc, "field '" + f_.name + "' unrolls to more than " + std::to_string(kMaxFieldTapeSize) + " tape operations");
    return {};
  }

  // The tape value of a float symbol (known: a constant) / of a bool symbol (1 or 0).
  uint32_t floatOf(const Symbol& s) { return s.known ? builder_.constant(asF(s.bits)) : s.node; }
  uint32_t boolOf(const Symbol& s) { return s.known ? builder_.constant(s.bits != 0 ? 1.0f : 0.0f) : s.node; }
  // A bool operand's tape value: 1 where it holds, 0 elsewhere.
  uint32_t boolNode(int v, SourceLoc loc) {
    const Symbol s = get(v, loc);
    if (s.poison >= 0) failPoisoned(s);
    if (!s.known && s.node == Symbol::kNoNode) fail(loc, "this condition has no tape form");
    return boolOf(s);
  }

  Outcome loop(const IrNode& n) {
    loops_.push_back({alive_, alive_, {}, {}});
    const Outcome o = loopIterations(n);
    // The points that broke out part-way take the values they had then.
    LoopFrame frame = std::move(loops_.back());
    loops_.pop_back();
    mergeExits(frame.breaks, n.inst.loc);
    // Points that left past this loop (a return from inside it) stay gone.
    alive_ = frame.alive_at_entry;
    if (!loops_.empty()) alive_ = both(alive_, loops_.back().alive);
    return o;
  }

  Outcome loopIterations(const IrNode& n) {
    for (;;) {
      Outcome c = block(*n.cond_block);
      if (c.flow != Flow::Normal) return c;
      if (n.cond >= 0 && !decide(n.cond, n.inst.loc, "this loop's condition")) return {};
      Outcome b = block(*n.body_block);
      // A break of every point still running, after some points continued or left this loop
      // part-way: a partial break -- the continuing points go on, and those that left keep
      // their exits (a break past this loop must not carry them along).
      const LoopFrame& frame = loops_.back();
      if (b.flow == Flow::Break && (!frame.continues.empty() || frame.alive != frame.alive_at_entry)) {
        const bool others_go_on = !frame.continues.empty();
        recordExit(b, alive_, env_, n.inst.loc);
        if (!others_go_on) return {};  // nobody is left in the loop: it ends here
        b = {};
      }
      // The points that continued part-way rejoin at the step, with their values.
      mergeExits(loops_.back().continues, n.inst.loc);
      loops_.back().continues.clear();
      alive_ = loops_.back().alive;
      if (b.flow == Flow::Break) return b.levels > 1 ? Outcome{Flow::Break, b.levels - 1} : Outcome{};
      Outcome s = block(*n.step_block);
      if (s.flow == Flow::Break) return s.levels > 1 ? Outcome{Flow::Break, s.levels - 1} : Outcome{};
      if (++iterations_ > kMaxFieldLoopIterations)
        fail(n.inst.loc, "field '" + f_.name + "' runs its loops more than " + std::to_string(kMaxFieldLoopIterations) +
                             " times while it is compiled: a field's loops must end after a fixed count");
    }
  }

  // x^n for an integer n, by squaring.
  uint32_t integerPower(uint32_t x, long long n) {
    if (n == 0) return builder_.constant(1.0f);
    const bool reciprocal = n < 0;
    unsigned long long m = static_cast<unsigned long long>(n < 0 ? -n : n);
    uint32_t result = Symbol::kNoNode, square = x;
    while (m) {
      if (m & 1) result = result == Symbol::kNoNode ? square : builder_.binary(FieldOp::Mul, result, square);
      m >>= 1;
      if (m) square = builder_.unary(FieldOp::Square, square);
    }
    return reciprocal ? builder_.binary(FieldOp::Div, builder_.constant(1.0f), result) : result;
  }

  Outcome inst(const IrInst& in) {
    const SourceLoc loc = in.loc;
    switch (in.op) {
      case Op::Break: return {Flow::Break, in.imm > 1 ? in.imm : 1};
      case Op::Continue: return {Flow::Continue, 1};
      case Op::ShadeOut: result_ = node(in.a, loc); return {};
      case Op::XLoadVertexAt: return {};  // lowering's zero interpolator_data: unused by fields
      case Op::Mov: set(in.dst, get(in.a, loc)); return {};
      case Op::Sel: {
        const Symbol c = get(in.a, loc);
        if (c.poison >= 0) failPoisoned(c);
        if (c.known) {
          set(in.dst, get(c.bits != 0 ? in.b : in.c, loc));
          return {};
        }
        // A point-dependent choice: between floats or bools, on the tape.
        const ValueClass cls = f_.values[static_cast<size_t>(in.dst)].cls;
        if (cls != ValueClass::F32 && cls != ValueClass::Bool)
          fail(loc, "this choice (?:) depends on the field's point and picks an int: a field's point-dependent "
                    "choices are between floats");
        const Symbol t = get(in.b, loc), e = get(in.c, loc);
        if (t.poison >= 0) failPoisoned(t);
        if (e.poison >= 0) failPoisoned(e);
        const uint32_t cond = boolNode(in.a, loc);
        setNode(in.dst, builder_.select(cond, cls == ValueClass::Bool ? boolOf(t) : floatOf(t),
                                        cls == ValueClass::Bool ? boolOf(e) : floatOf(e)), loc);
        return {};
      }
      default: break;
    }
    const bool pure = static_cast<int>(in.op) < static_cast<int>(Op::Mov) && in.op != Op::CrossSign;
    if (!pure)
      fail(loc, std::string("'") + opName(in.op) + "' is not available in a field: a field is a pure function of its point");
    // An operand that is already an error makes this value one too (raised where it is used).
    for (int v : {in.a, in.b, in.c, in.d})
      if (const Symbol s = get(v, loc); s.poison >= 0) {
        set(in.dst, s);
        return {};
      }
    const bool known = knownValue(in.a, loc) && knownValue(in.b, loc) && knownValue(in.c, loc) && knownValue(in.d, loc);
    if (known) {
      const auto bits = [&](int v) { return get(v, loc).bits; };
      set(in.dst, {true, evalScalar(in.op, bits(in.a), bits(in.b), bits(in.c), bits(in.d), static_cast<uint32_t>(in.imm))});
      return {};
    }
    const auto unary = [&](FieldOp op) { setNode(in.dst, builder_.unary(op, node(in.a, loc)), loc); };
    const auto binary = [&](FieldOp op) { setNode(in.dst, builder_.binary(op, node(in.a, loc), node(in.b, loc)), loc); };
    switch (in.op) {
      case Op::FAdd: binary(FieldOp::Add); return {};
      case Op::FSub: binary(FieldOp::Sub); return {};
      case Op::FMul: binary(FieldOp::Mul); return {};
      case Op::FDiv: binary(FieldOp::Div); return {};
      case Op::FMin: binary(FieldOp::Min); return {};
      case Op::FMax: binary(FieldOp::Max); return {};
      case Op::FNeg: unary(FieldOp::Neg); return {};
      case Op::FAbs: unary(FieldOp::Abs); return {};
      case Op::FSqrt: unary(FieldOp::Sqrt); return {};
      case Op::FExp: unary(FieldOp::Exp); return {};
      case Op::FLog: unary(FieldOp::Log); return {};
      case Op::FSin: unary(FieldOp::Sin); return {};
      case Op::FCos: unary(FieldOp::Cos); return {};
      case Op::FAtan: unary(FieldOp::Atan); return {};
      case Op::FAsin: case Op::FAcos: {
        // asin v = atan(v / sqrt(1 - v^2)); acos v = pi/2 - asin v (as the HyperFun reader does).
        const uint32_t v = node(in.a, loc);
        const uint32_t root = builder_.unary(FieldOp::Sqrt, builder_.binary(FieldOp::Sub, builder_.constant(1.0f),
                                                                             builder_.unary(FieldOp::Square, v)));
        const uint32_t asin = builder_.unary(FieldOp::Atan, builder_.binary(FieldOp::Div, v, root));
        setNode(in.dst, in.op == Op::FAsin ? asin : builder_.binary(FieldOp::Sub, builder_.constant(1.5707963705062866f), asin), loc);
        return {};
      }
      case Op::FAtan2: {
        // atan2(y, x) = 2 atan(y / (sqrt(x^2 + y^2) + x)): C's value except on the negative x
        // axis itself (0/0 there: NaN, a set of no area).
        const uint32_t y = node(in.a, loc), x = node(in.b, loc);
        const uint32_t r = builder_.unary(FieldOp::Sqrt, builder_.binary(FieldOp::Add, builder_.unary(FieldOp::Square, x),
                                                                          builder_.unary(FieldOp::Square, y)));
        const uint32_t half = builder_.unary(FieldOp::Atan, builder_.binary(FieldOp::Div, y, builder_.binary(FieldOp::Add, r, x)));
        setNode(in.dst, builder_.binary(FieldOp::Mul, builder_.constant(2.0f), half), loc);
        return {};
      }
      case Op::FSign: {  // 1, -1 or 0 (and 0 for NaN, as the pixel programs' sign)
        const uint32_t v = node(in.a, loc), zero = builder_.constant(0.0f);
        const uint32_t negative = builder_.select(builder_.binary(FieldOp::Less, v, zero), builder_.constant(-1.0f), zero);
        setNode(in.dst, builder_.select(builder_.binary(FieldOp::Less, zero, v), builder_.constant(1.0f), negative), loc);
        return {};
      }
      case Op::FTan: {
        const uint32_t x = node(in.a, loc);
        setNode(in.dst, builder_.binary(FieldOp::Div, builder_.unary(FieldOp::Sin, x), builder_.unary(FieldOp::Cos, x)), loc);
        return {};
      }
      case Op::FPow: {
        // A constant integer exponent: products (a negative base is fine, as in C's pow);
        // otherwise exp(y log x), which is pow wherever x > 0 (NaN for x < 0, as pow's
        // non-integer powers of negative numbers).
        if (knownValue(in.b, loc)) {
          const float y = asF(get(in.b, loc).bits);
          if (y == std::floor(y) && std::fabs(y) < 4.0e9f) {  // as the HyperFun reader's ^
            setNode(in.dst, integerPower(node(in.a, loc), static_cast<long long>(y)), loc);
            return {};
          }
        }
        const uint32_t log_x = builder_.unary(FieldOp::Log, node(in.a, loc));
        setNode(in.dst, builder_.unary(FieldOp::Exp, builder_.binary(FieldOp::Mul, node(in.b, loc), log_x)), loc);
        return {};
      }
      // Point-dependent comparisons and logic: 1 where they hold, 0 elsewhere (C's meaning: a
      // comparison with NaN is false, except !=).
      case Op::FLt: binary(FieldOp::Less); return {};
      case Op::FLe: binary(FieldOp::LessEq); return {};
      case Op::FEq: case Op::FNe: {
        const uint32_t a = node(in.a, loc), b = node(in.b, loc);
        const uint32_t eq = builder_.binary(FieldOp::Min, builder_.binary(FieldOp::LessEq, a, b),
                                            builder_.binary(FieldOp::LessEq, b, a));
        setNode(in.dst, in.op == Op::FEq ? eq : builder_.binary(FieldOp::Sub, builder_.constant(1.0f), eq), loc);
        return {};
      }
      case Op::BAnd: case Op::BOr:
        setNode(in.dst, builder_.binary(in.op == Op::BAnd ? FieldOp::Min : FieldOp::Max, boolNode(in.a, loc),
                                        boolNode(in.b, loc)), loc);
        return {};
      case Op::BNot:
        setNode(in.dst, builder_.binary(FieldOp::Sub, builder_.constant(1.0f), boolNode(in.a, loc)), loc);
        return {};
      default: break;
    }
    const char* name = sourceName(in.op);
    poisons_.push_back({loc, std::string("'") + (name ? name : opName(in.op)) +
                                 "' of a value that depends on the field's point has no tape form: a field's "
                                 "point-dependent part uses + - * / min max abs sqrt exp log sin cos atan pow"});
    set(in.dst, {false, 0, Symbol::kNoNode, static_cast<int>(poisons_.size()) - 1});
    return {};
  }
};

// The user's field units, by name.
std::map<std::string, const Unit*> fieldsOf(const Program& program, const std::string& filename) {
  std::map<std::string, const Unit*> out;
  for (const Unit& u : program.units)
    if (u.kind == UnitKind::Field && u.loc.file && u.loc.file->name == filename) out[u.name] = &u;
  return out;
}

}  // namespace

std::optional<FieldTape> compileFieldUnit(const std::string& filename, const std::string& text,
                                          const std::string& name, const std::vector<float>& params,
                                          DiagnosticLog& log) {
  Program program;
  if (!analyzeSource(filename, text, log, program, {})) return std::nullopt;
  const std::map<std::string, const Unit*> fields = fieldsOf(program, filename);
  const SourceFile* file = nullptr;
  for (const Unit& u : program.units)
    if (u.loc.file && u.loc.file->name == filename) file = u.loc.file;
  const SourceLoc start{file ? file : &log.addSource(filename, text), 1, 1};
  std::string names;
  for (const auto& [n, u] : fields) names += (names.empty() ? "'" : ", '") + n + "'";
  const Unit* field = nullptr;
  if (name.empty()) {
    if (fields.size() != 1) {
      log.error(start, fields.empty() ? std::string("the source defines no field (a unit 'field float name(point p) { ... }')")
                                      : "the source defines several fields (" + names + "): name the one to compile");
      return std::nullopt;
    }
    field = fields.begin()->second;
  } else {
    auto it = fields.find(name);
    if (it == fields.end() && fields.size() == 1) it = fields.begin();  // a source of one field
    if (it == fields.end()) {
      log.error(start, "the source defines no field named '" + name + "'" +
                           (names.empty() ? std::string() : " (its fields: " + names + ")"));
      return std::nullopt;
    }
    field = it->second;
  }
  if (field->params.size() - 1 != params.size()) {
    log.error(field->loc, "field '" + field->name + "' takes " + std::to_string(field->params.size() - 1) +
                              " parameter value" + (field->params.size() == 2 ? "" : "s") + " after its point; " +
                              std::to_string(params.size()) + " given");
    return std::nullopt;
  }
  std::map<std::string, const Unit*> functions;
  for (const Unit& u : program.units)
    if (u.kind == UnitKind::Function || u.kind == UnitKind::Field) functions[u.name] = &u;
  IrFunction ir;
  if (!lowerField(*field, functions, ir, log)) return std::nullopt;
  optimize(ir);
  return TapeTranslator(ir, params, log).run(field->loc);
}

}  // namespace pf::field
