// IntervalEvaluator: one pass over the tape in interval arithmetic, noting min/max/select choices.
#include "raster/field/interval_evaluator.h"

#include "raster/field/sampled_bounds.h"

namespace pf::field {

// Operand `a` of min(a, b) is the result over the box when a <= b everywhere in it. An interval
// that may be NaN (the whole line) never decides: fieldMin would return the other operand.
static Choice minChoice(Interval a, Interval b) {
  if (a.isWhole() || b.isWhole()) return Choice::Both;
  if (a.hi <= b.lo) return Choice::Left;
  if (b.hi <= a.lo) return Choice::Right;
  return Choice::Both;
}

// Less / LessEq over a box: 1 or 0 where the comparison is decided, [0, 1] elsewhere (an
// interval that may be NaN decides nothing: a NaN compares false).
static Interval comparison(Interval a, Interval b, bool or_equal) {
  if (!a.isWhole() && !b.isWhole()) {
    if (or_equal ? a.hi <= b.lo : a.hi < b.lo) return Interval::point(1.0f);
    if (or_equal ? a.lo > b.hi : a.lo >= b.hi) return Interval::point(0.0f);
  }
  return {0.0f, 1.0f};
}

// Which operand a Select takes over the box: its condition's interval excludes 0, or is 0.
static Choice selectChoice(Interval cond) {
  if (cond.isWhole()) return Choice::Both;
  if (cond.lo > 0.0f || cond.hi < 0.0f) return Choice::Left;
  if (cond.lo == 0.0f && cond.hi == 0.0f) return Choice::Right;
  return Choice::Both;
}

Interval IntervalEvaluator::evaluate(Interval x, Interval y, Interval z, std::vector<Choice>* choices) {
  if (!tape_) return Interval::whole();
  const std::vector<FieldInstr>& code = tape_->instrs;
  if (choices) choices->assign(code.size(), Choice::Both);
  Interval* v = values_.data();
  for (size_t i = 0; i < code.size(); ++i) {
    const FieldInstr& in = code[i];
    switch (in.op) {
      case FieldOp::X: v[i] = x; break;
      case FieldOp::Y: v[i] = y; break;
      case FieldOp::Z: v[i] = z; break;
      case FieldOp::Const: v[i] = Interval::point(in.value); break;
      case FieldOp::Sample: v[i] = sampleInterval(*tape_->grids[static_cast<size_t>(in.value)], x, y, z); break;
      case FieldOp::Neg: v[i] = intervalNeg(v[in.a]); break;
      case FieldOp::Abs: v[i] = intervalAbs(v[in.a]); break;
      case FieldOp::Square: v[i] = intervalSquare(v[in.a]); break;
      case FieldOp::Sqrt: v[i] = intervalSqrt(v[in.a]); break;
      case FieldOp::Exp: v[i] = intervalExp(v[in.a]); break;
      case FieldOp::Log: v[i] = intervalLog(v[in.a]); break;
      case FieldOp::Sin: v[i] = intervalSin(v[in.a]); break;
      case FieldOp::Cos: v[i] = intervalCos(v[in.a]); break;
      case FieldOp::Atan: v[i] = intervalAtan(v[in.a]); break;
      case FieldOp::Floor: v[i] = intervalFloor(v[in.a]); break;
      case FieldOp::NoisePerm: case FieldOp::NoiseGradX: case FieldOp::NoiseGradY: case FieldOp::NoiseGradZ:
        v[i] = intervalNoiseTable(in.op, v[in.a]);
        break;
      case FieldOp::Add: v[i] = intervalAdd(v[in.a], v[in.b]); break;
      case FieldOp::Sub: v[i] = intervalSub(v[in.a], v[in.b]); break;
      case FieldOp::Mul: v[i] = intervalMul(v[in.a], v[in.b]); break;
      case FieldOp::Div: v[i] = intervalDiv(v[in.a], v[in.b]); break;
      case FieldOp::Min:
        v[i] = intervalMin(v[in.a], v[in.b]);
        if (choices) (*choices)[i] = minChoice(v[in.a], v[in.b]);
        break;
      case FieldOp::Max:
        v[i] = intervalMax(v[in.a], v[in.b]);
        // max(a, b) is a where b <= a everywhere: minChoice(b, a) says Left exactly then.
        if (choices) (*choices)[i] = minChoice(v[in.b], v[in.a]);
        break;
      case FieldOp::Less: v[i] = comparison(v[in.a], v[in.b], false); break;
      case FieldOp::LessEq: v[i] = comparison(v[in.a], v[in.b], true); break;
      case FieldOp::Select: {
        const Choice c = selectChoice(v[in.a]);
        if (choices) (*choices)[i] = c;
        v[i] = c == Choice::Left ? v[in.b] : c == Choice::Right ? v[in.c] : intervalHull(v[in.b], v[in.c]);
        break;
      }
    }
  }
  return code.empty() ? Interval::whole() : v[tape_->result];
}

}  // namespace pf::field
