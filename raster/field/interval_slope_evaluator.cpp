// IntervalSlopeEvaluator: one pass over the tape carrying (value, rate) interval pairs.
#include "raster/field/interval_slope_evaluator.h"

#include <cmath>

#include "raster/field/sampled_bounds.h"

namespace pf::field {
namespace {

// The smallest interval holding both, even where one is the whole line (then the whole line).
Interval hull(Interval a, Interval b) { return intervalHull(a, b); }

bool finite(Interval a) { return std::isfinite(a.lo) && std::isfinite(a.hi); }

// Which operand min(a, b) is over the box: Left where a <= b throughout, Right where b <= a.
Choice minSide(Interval a, Interval b) {
  if (!finite(a) || !finite(b)) return Choice::Both;
  if (a.hi <= b.lo) return Choice::Left;
  if (b.hi <= a.lo) return Choice::Right;
  return Choice::Both;
}

}  // namespace

IntervalSlope IntervalSlopeEvaluator::evaluate(Interval x, Interval y, Interval z, Interval dx, Interval dy,
                                               Interval dz) {
  if (!tape_ || tape_->instrs.empty()) return {Interval::whole(), Interval::whole()};
  const std::vector<FieldInstr>& code = tape_->instrs;
  Interval* v = values_.data();
  Interval* r = rates_.data();
  const Interval zero = Interval::point(0.0f), two = Interval::point(2.0f), one = Interval::point(1.0f);
  for (size_t i = 0; i < code.size(); ++i) {
    const FieldInstr& in = code[i];
    // (Operands an operation does not have are index 0, read and unused.)
    const Interval a = v[in.a], da = r[in.a], b = v[in.b], db = r[in.b];
    Interval value, rate;
    switch (in.op) {
      case FieldOp::X: value = x, rate = dx; break;
      case FieldOp::Y: value = y, rate = dy; break;
      case FieldOp::Z: value = z, rate = dz; break;
      case FieldOp::Const: value = Interval::point(in.value), rate = zero; break;
      case FieldOp::Sample: sampleSlope(*tape_->grids[static_cast<size_t>(in.value)], x, y, z, dx, dy, dz, value, rate); break;
      case FieldOp::Neg: value = intervalNeg(a), rate = intervalNeg(da); break;
      case FieldOp::Abs:
        value = intervalAbs(a);
        rate = a.lo >= 0.0f ? da : a.hi <= 0.0f ? intervalNeg(da) : hull(da, intervalNeg(da));
        break;
      case FieldOp::Square: value = intervalSquare(a), rate = intervalMul(intervalMul(two, a), da); break;
      case FieldOp::Sqrt:
        value = intervalSqrt(a);
        rate = intervalDiv(da, intervalMul(two, value));  // the whole line where sqrt(a) may be 0
        break;
      case FieldOp::Exp: value = intervalExp(a), rate = intervalMul(value, da); break;
      case FieldOp::Log: value = intervalLog(a), rate = intervalDiv(da, a); break;
      case FieldOp::Sin: value = intervalSin(a), rate = intervalMul(intervalCos(a), da); break;
      case FieldOp::Cos: value = intervalCos(a), rate = intervalNeg(intervalMul(intervalSin(a), da)); break;
      case FieldOp::Atan: value = intervalAtan(a), rate = intervalDiv(da, intervalAdd(one, intervalSquare(a))); break;
      case FieldOp::Floor:  // constant over the box (rate 0) unless it steps inside it
      case FieldOp::NoisePerm:  // (the table look-ups too: one entry over the box, or a step)
      case FieldOp::NoiseGradX:
      case FieldOp::NoiseGradY:
      case FieldOp::NoiseGradZ:
        value = in.op == FieldOp::Floor ? intervalFloor(a) : intervalNoiseTable(in.op, a);
        rate = finite(value) && value.lo == value.hi ? zero : Interval::whole();
        break;
      case FieldOp::Add: value = intervalAdd(a, b), rate = intervalAdd(da, db); break;
      case FieldOp::Sub: value = intervalSub(a, b), rate = intervalSub(da, db); break;
      case FieldOp::Mul: value = intervalMul(a, b), rate = intervalAdd(intervalMul(da, b), intervalMul(a, db)); break;
      case FieldOp::Div:
        value = intervalDiv(a, b);
        rate = intervalDiv(intervalSub(da, intervalMul(value, db)), b);  // (a' - (a/b) b') / b
        break;
      case FieldOp::Min:
      case FieldOp::Max: {
        value = in.op == FieldOp::Min ? intervalMin(a, b) : intervalMax(a, b);
        const Choice c = in.op == FieldOp::Min ? minSide(a, b) : minSide(b, a);
        rate = c == Choice::Left ? da : c == Choice::Right ? db : hull(da, db);
        break;
      }
      case FieldOp::Less:
      case FieldOp::LessEq: {
        const bool or_equal = in.op == FieldOp::LessEq;
        if (finite(a) && finite(b) && (or_equal ? a.hi <= b.lo : a.hi < b.lo)) value = one, rate = zero;
        else if (finite(a) && finite(b) && (or_equal ? a.lo > b.hi : a.lo >= b.hi)) value = zero, rate = zero;
        else value = {0.0f, 1.0f}, rate = Interval::whole();  // a step inside the box
        break;
      }
      case FieldOp::Select: {
        const Interval c = v[in.c], dc = r[in.c];
        if (finite(a) && (a.lo > 0.0f || a.hi < 0.0f)) value = b, rate = db;
        else if (a.lo == 0.0f && a.hi == 0.0f) value = c, rate = dc;
        else value = hull(b, c), rate = Interval::whole();  // may switch sides inside the box
        break;
      }
    }
    if (!finite(value)) rate = Interval::whole();
    v[i] = value;
    r[i] = rate;
  }
  return {v[tape_->result], r[tape_->result]};
}

}  // namespace pf::field
