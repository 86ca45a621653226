// FieldTape: building (sharing, folding), printing, dead-code removal and tape simplification.
#include "compiler/field/field_tape.h"

#include <sstream>

#include "compiler/field/field_scalar.h"

namespace pf::field {

std::string_view fieldOpName(FieldOp op) {
  switch (op) {
    case FieldOp::X: return "var-x";
    case FieldOp::Y: return "var-y";
    case FieldOp::Z: return "var-z";
    case FieldOp::Const: return "const";
    case FieldOp::Neg: return "neg";
    case FieldOp::Abs: return "abs";
    case FieldOp::Square: return "square";
    case FieldOp::Sqrt: return "sqrt";
    case FieldOp::Exp: return "exp";
    case FieldOp::Log: return "ln";
    case FieldOp::Sin: return "sin";
    case FieldOp::Cos: return "cos";
    case FieldOp::Atan: return "atan";
    case FieldOp::Floor: return "floor";
    case FieldOp::NoisePerm: return "hf-noise-perm";
    case FieldOp::NoiseGradX: return "hf-noise-grad-x";
    case FieldOp::NoiseGradY: return "hf-noise-grad-y";
    case FieldOp::NoiseGradZ: return "hf-noise-grad-z";
    case FieldOp::Add: return "add";
    case FieldOp::Sub: return "sub";
    case FieldOp::Mul: return "mul";
    case FieldOp::Div: return "div";
    case FieldOp::Min: return "min";
    case FieldOp::Max: return "max";
    case FieldOp::Less: return "less";
    case FieldOp::LessEq: return "less-eq";
    case FieldOp::Select: return "select";
    case FieldOp::Sample: return "sample";
  }
  return "?";
}

bool FieldTape::usesZ() const {
  for (const FieldInstr& in : instrs)
    if (in.op == FieldOp::Z || in.op == FieldOp::Sample) return true;  // (a grid varies along z)
  return false;
}

std::string FieldTape::print() const {
  std::ostringstream out;
  for (size_t i = 0; i < instrs.size(); ++i) {
    const FieldInstr& in = instrs[i];
    out << '_' << i << ' ' << fieldOpName(in.op);
    if (in.op == FieldOp::Const) out << ' ' << in.value;
    if (in.op == FieldOp::Sample) out << " grid " << in.value;
    if (fieldOpArity(in.op) >= 1) out << " _" << in.a;
    if (fieldOpArity(in.op) >= 2) out << " _" << in.b;
    if (fieldOpArity(in.op) == 3) out << " _" << in.c;
    out << '\n';
  }
  out << "result _" << result << '\n';
  return out.str();
}

size_t FieldTapeBuilder::InstrHash::operator()(const FieldInstr& in) const {
  uint32_t bits = 0;
  static_assert(sizeof(bits) == sizeof(in.value));
  __builtin_memcpy(&bits, &in.value, sizeof(bits));
  size_t h = static_cast<size_t>(in.op);
  h = h * 1000003u ^ in.a;
  h = h * 1000003u ^ in.b;
  h = h * 1000003u ^ in.c;
  h = h * 1000003u ^ bits;
  return h;
}

uint32_t FieldTapeBuilder::add(const FieldInstr& in) {
  auto [it, inserted] = known_.try_emplace(in, static_cast<uint32_t>(tape_.instrs.size()));
  if (inserted) tape_.instrs.push_back(in);
  return it->second;
}

uint32_t FieldTapeBuilder::x() { return add({FieldOp::X, 0, 0, 0.0f}); }
uint32_t FieldTapeBuilder::y() { return add({FieldOp::Y, 0, 0, 0.0f}); }
uint32_t FieldTapeBuilder::z() { return add({FieldOp::Z, 0, 0, 0.0f}); }

uint32_t FieldTapeBuilder::constant(float v) {
  // NaN constants compare unequal to themselves; they are still shared (the hash key holds bits,
  // equality is the instruction's ==), which only costs a duplicate.
  return add({FieldOp::Const, 0, 0, v});
}

uint32_t FieldTapeBuilder::sample(std::shared_ptr<const SampledGrid> grid) {
  for (size_t i = 0; i < tape_.grids.size(); ++i)
    if (tape_.grids[i] == grid) return add({FieldOp::Sample, 0, 0, static_cast<float>(i)});
  tape_.grids.push_back(std::move(grid));
  return add({FieldOp::Sample, 0, 0, static_cast<float>(tape_.grids.size() - 1)});
}

uint32_t FieldTapeBuilder::unary(FieldOp op, uint32_t a) {
  const FieldInstr& ia = tape_.instrs.at(a);
  if (ia.op == FieldOp::Const) return constant(applyFieldOp(op, ia.value, 0.0f));
  return add({op, a, 0, 0.0f});
}

uint32_t FieldTapeBuilder::binary(FieldOp op, uint32_t a, uint32_t b) {
  const FieldInstr& ia = tape_.instrs.at(a);
  const FieldInstr& ib = tape_.instrs.at(b);
  if (ia.op == FieldOp::Const && ib.op == FieldOp::Const) return constant(applyFieldOp(op, ia.value, ib.value));
  // Commutative operations take their operands in one order, so a+b and b+a are shared.
  if ((op == FieldOp::Add || op == FieldOp::Mul || op == FieldOp::Min || op == FieldOp::Max) && b < a)
    std::swap(a, b);
  if (a == b && (op == FieldOp::Min || op == FieldOp::Max)) return a;
  if (a == b && op == FieldOp::Mul) return unary(FieldOp::Square, a);
  return add({op, a, b, 0.0f});
}

uint32_t FieldTapeBuilder::select(uint32_t cond, uint32_t if_true, uint32_t if_false) {
  const FieldInstr& ic = tape_.instrs.at(cond);
  (void)tape_.instrs.at(if_true);  // operands must be earlier values, as for binary()
  (void)tape_.instrs.at(if_false);
  if (ic.op == FieldOp::Const) return ic.value != 0.0f ? if_true : if_false;
  if (if_true == if_false) return if_true;
  return add({FieldOp::Select, cond, if_true, 0.0f, if_false});
}

FieldTape FieldTapeBuilder::tapeOf(uint32_t result) const {
  FieldTape all = tape_;
  all.result = result;
  return removeDeadCode(all);
}

FieldTape FieldTapeBuilder::finish(uint32_t result) {
  tape_.result = result;
  FieldTape done = removeDeadCode(tape_);
  tape_ = {};
  known_.clear();
  return done;
}

// Marks what `result` needs, following only the chosen operand of a decided min/max/select, then
// copies the needed instructions in order with renumbered operands into `out`.
static void rebuild(const FieldTape& tape, const std::vector<Choice>* choices, FieldTape& out,
                    SimplifyScratch& scratch) {
  const size_t n = tape.instrs.size();
  auto chosen = [&](uint32_t i) -> Choice {
    if (!choices) return Choice::Both;
    const FieldOp op = tape.instrs[i].op;
    return (op == FieldOp::Min || op == FieldOp::Max || op == FieldOp::Select) ? (*choices)[i] : Choice::Both;
  };
  // forward[i]: the value that stands for value i once decided min/max/select are bypassed.
  std::vector<uint32_t>& forward = scratch.forward;
  forward.resize(n);
  for (uint32_t i = 0; i < n; ++i) {
    const FieldInstr& in = tape.instrs[i];
    const Choice c = chosen(i);
    const bool select = in.op == FieldOp::Select;
    forward[i] = c == Choice::Left    ? forward[select ? in.b : in.a]
                 : c == Choice::Right ? forward[select ? in.c : in.b]
                                      : i;
  }
  std::vector<char>& live = scratch.live;
  live.assign(n, 0);
  if (n) live[forward[tape.result]] = 1;
  for (size_t k = n; k-- > 0;) {
    if (!live[k]) continue;
    const FieldInstr& in = tape.instrs[k];
    const int arity = fieldOpArity(in.op);
    if (arity >= 1) live[forward[in.a]] = 1;
    if (arity >= 2) live[forward[in.b]] = 1;
    if (arity == 3) live[forward[in.c]] = 1;
  }
  out.instrs.clear();
  std::vector<uint32_t>& renumber = scratch.renumber;
  renumber.assign(n, 0);
  for (uint32_t i = 0; i < n; ++i) {
    if (!live[i]) continue;
    FieldInstr in = tape.instrs[i];
    const int arity = fieldOpArity(in.op);
    if (arity >= 1) in.a = renumber[forward[in.a]];
    if (arity >= 2) in.b = renumber[forward[in.b]];
    if (arity == 3) in.c = renumber[forward[in.c]];
    renumber[i] = static_cast<uint32_t>(out.instrs.size());
    out.instrs.push_back(in);
  }
  out.result = n ? renumber[forward[tape.result]] : 0;
  out.grids = tape.grids;
}

FieldTape removeDeadCode(const FieldTape& tape) {
  FieldTape out;
  SimplifyScratch scratch;
  rebuild(tape, nullptr, out, scratch);
  return out;
}

FieldTape simplify(const FieldTape& tape, const std::vector<Choice>& choices) {
  FieldTape out;
  SimplifyScratch scratch;
  rebuild(tape, &choices, out, scratch);
  return out;
}

void simplifyInto(const FieldTape& tape, const std::vector<Choice>& choices, FieldTape& out, SimplifyScratch& scratch) {
  rebuild(tape, &choices, out, scratch);
}

}  // namespace pf::field
