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
// the tape being built (point-dependent floats; point-dependent bools and ints have no tape
// value -- using one is the error).
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
    case Op::FSign: return "sign";
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
      fail(loc, std::string(what) + " depends on the field's point: a field's branches must be decided when it is "
                                    "compiled (write a point-dependent choice with min, max or abs)");
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
        o = block(decide(n.cond, n.inst.loc, "this 'if' condition") ? *n.then_block : *n.else_block);
      } else if (n.kind == IrNode::Kind::Loop) {
        o = loop(n);
      } else {
        o = inst(n.inst);
      }
      if (o.flow != Flow::Normal) return o;
    }
    return {};
  }

  Outcome loop(const IrNode& n) {
    for (;;) {
      Outcome c = block(*n.cond_block);
      if (c.flow != Flow::Normal) return c;
      if (n.cond >= 0 && !decide(n.cond, n.inst.loc, "this loop's condition")) return {};
      Outcome b = block(*n.body_block);
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
      case Op::Sel:
        set(in.dst, get(decide(in.a, loc, "this choice (?:)") ? in.b : in.c, loc));
        return {};
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
      // Point-dependent comparisons and logic: fine until something branches on them.
      case Op::FLt: case Op::FLe: case Op::FEq: case Op::FNe: case Op::BAnd: case Op::BOr: case Op::BNot:
        set(in.dst, {false, 0, Symbol::kNoNode});
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
