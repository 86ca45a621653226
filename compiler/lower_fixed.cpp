// Lowering of fixed<bits,frac> values (the Lowerer, lowerer.h; the rules are
// docs/language.md's "Fixed-point numbers", the arithmetic compiler/fixed_point.h's).
//
// A fixed value is a binding of two I32 values, the low and high words of its raw integer.
// Each operation is a pair of instructions, one per word of the result, both reading both
// operands' word pairs: the executors never need a 64-bit register, and every pass (folding,
// CSE, hoisting, dead-code removal) treats the words as the ordinary 32-bit values they are.
#include "compiler/fixed_point.h"
#include "compiler/lowerer.h"

namespace pf::lowering {
namespace {

FixedFormat formatOf(const Type& t) { return FixedFormat{t.fixed_bits, t.fixed_frac}; }

bool isIntScalar(const Type& t) { return t.dims.empty() && t.base == BaseType::Int; }

// Both operands fixed or int: the operation stays fixed-point and exact (else it is a float one).
bool exactOperands(const Binding& a, const Binding& b) {
  return (a.type.isFixed() || isIntScalar(a.type)) && (b.type.isFixed() || isIntScalar(b.type));
}

}  // namespace

int Lowerer::emitWord(Op op, ValueClass c, int a, int b, int cc, int d, int imm) {
  Value v;
  v.cls = c;
  v.varying = isVarying(a) || isVarying(b) || isVarying(cc) || isVarying(d);
  const int dst = newValue(v);
  IrNode n;
  n.inst = IrInst{op, dst, a, b, cc, d, imm, cur_loc_};
  blocks_.back()->push_back(std::move(n));
  return dst;
}

Binding Lowerer::fixedPair(Op op, const Type& result, int a, int b, int c, int d) {
  Binding out;
  out.type = result;
  for (int half = 0; half < 2; ++half)
    out.comps.push_back(emitWord(op, ValueClass::I32, a, b, c, d, fixedImm(formatOf(result), half)));
  return out;
}

Binding Lowerer::toFixed(const Binding& from, const Type& to) {
  if (from.comps.empty()) return Binding{to, {}};  // an error sema reported
  if (from.type == to) return from;
  if (from.type.isFixed())
    return fixedPair(Op::QConv, to, from.comps[0], from.comps[1], constI(from.type.fixed_frac));
  const int v = from.comps[0];
  if (cls(v) == ValueClass::I32) return fixedPair(Op::QFromI, to, v);
  return fixedPair(Op::QFromF, to, toFloat(v));
}

Binding Lowerer::asFloat(const Binding& v) {
  if (!v.type.isFixed() || v.comps.size() != 2) return v;
  // Only imm's frac matters to QToF (the half is unused).
  return scalar(Type::of(BaseType::Float),
                emitWord(Op::QToF, ValueClass::F32, v.comps[0], v.comps[1], -1, -1, fixedImm(formatOf(v.type), 0)));
}

int Lowerer::fixedToInt(const Binding& v) {
  return emitWord(Op::QToI, ValueClass::I32, v.comps[0], v.comps[1], -1, -1, fixedImm(formatOf(v.type), 0));
}

Binding Lowerer::fixedArith(const std::string& op, const Binding& a, const Binding& b, const Type& result,
                            SourceLoc loc) {
  if (!exactOperands(a, b) || !result.isFixed()) {
    // With a float (q + 0.5, or q += 0.5 into a fixed variable): computed in floats, then
    // converted into the result's type where that is fixed.
    Binding r = arith(op, asFloat(a), asFloat(b), result.isFixed() ? Type::of(BaseType::Float) : result, loc);
    return result.isFixed() ? toFixed(r, result) : r;
  }
  const Binding x = toFixed(a, result), y = toFixed(b, result);
  const Op o = op == "+" ? Op::QAdd : op == "-" ? Op::QSub : op == "*" ? Op::QMul : Op::QDiv;
  return fixedPair(o, result, x.comps[0], x.comps[1], y.comps[0], y.comps[1]);
}

int Lowerer::fixedCompare(const std::string& op, const Binding& a, const Binding& b) {
  if (!exactOperands(a, b)) {  // against a float: compared as floats
    int x = asFloat(a).comps[0], y = asFloat(b).comps[0];
    if (op == ">" || op == ">=") std::swap(x, y);
    const Op o = op == "<" || op == ">" ? Op::FLt : op == "<=" || op == ">=" ? Op::FLe : op == "==" ? Op::FEq : Op::FNe;
    return emit(o, ValueClass::Bool, false, toFloat(x), toFloat(y));
  }
  const Type& format = a.type.isFixed() ? a.type : b.type;
  Binding x = toFixed(a, format), y = toFixed(b, format);
  if (op == ">" || op == ">=") std::swap(x, y);
  const Op o = op == "<" || op == ">" ? Op::QLt : op == "<=" || op == ">=" ? Op::QLe : Op::QEq;
  const int r = emitWord(o, ValueClass::Bool, x.comps[0], x.comps[1], y.comps[0], y.comps[1], 0);
  return op == "!=" ? emit(Op::BNot, ValueClass::Bool, false, r) : r;
}

Binding Lowerer::fixedNegate(const Binding& a) { return fixedPair(Op::QNeg, a.type, a.comps[0], a.comps[1]); }

std::optional<Binding> Lowerer::fixedCall(const Expr& e, const std::vector<Binding>& args) {
  const std::string& f = e.name;
  if (f == "fixed") return args.size() == 1 ? toFixed(args[0], e.conversion) : Binding{e.type, {}};
  if (args.size() == 1 && args[0].type.isFixed() && (f == "float" || f == "int"))
    return f == "float" ? asFloat(args[0]) : scalar(e.type, fixedToInt(args[0]));
  if (!e.type.isFixed()) return std::nullopt;
  // abs / min / max / clamp of one format (ints converted): exact.
  std::vector<Binding> q;
  for (const Binding& a : args) q.push_back(toFixed(a, e.type));
  if (f == "abs") return fixedPair(Op::QAbs, e.type, q[0].comps[0], q[0].comps[1]);
  // The smaller / larger of two: a comparison and a select per word.
  const auto pick = [&](const Binding& x, const Binding& y, bool smaller) {
    const int y_wins = smaller ? emitWord(Op::QLt, ValueClass::Bool, y.comps[0], y.comps[1], x.comps[0], x.comps[1], 0)
                               : emitWord(Op::QLt, ValueClass::Bool, x.comps[0], x.comps[1], y.comps[0], y.comps[1], 0);
    Binding out;
    out.type = e.type;
    for (int k = 0; k < 2; ++k) out.comps.push_back(select(y_wins, y.comps[k], x.comps[k]));
    return out;
  };
  if (f == "min") return pick(q[0], q[1], true);
  if (f == "max") return pick(q[0], q[1], false);
  return pick(pick(q[0], q[1], false), q[2], true);  // clamp(x, lo, hi) = min(max(x, lo), hi)
}

}  // namespace pf::lowering
