// TapeAlgebra (hyperfun_library.h): HyperFun's arithmetic on values that are known when the
// model compiles (folded in double, as HyperFun computes) or on the tape -- the operators, a^b and
// the R-functions the library functions are written with.
#include <cmath>

#include "compiler/field/hyperfun_library.h"

namespace pf::field::hyperfun {

Real TapeAlgebra::emit(FieldOp op, Real a) { return Real::onTape(b_.unary(op, materialize(a))); }
Real TapeAlgebra::emit(FieldOp op, Real a, Real b) {
  return Real::onTape(b_.binary(op, materialize(a), materialize(b)));
}

static bool isKnown(Real r, double v) { return r.is_known && r.value == v; }

Real TapeAlgebra::add(Real a, Real b) {
  if (a.is_known && b.is_known) return Real::known(a.value + b.value);
  if (isKnown(a, 0.0)) return b;
  if (isKnown(b, 0.0)) return a;
  return emit(FieldOp::Add, a, b);
}
Real TapeAlgebra::sub(Real a, Real b) {
  if (a.is_known && b.is_known) return Real::known(a.value - b.value);
  if (isKnown(b, 0.0)) return a;
  if (isKnown(a, 0.0)) return neg(b);
  return emit(FieldOp::Sub, a, b);
}
Real TapeAlgebra::mul(Real a, Real b) {
  if (a.is_known && b.is_known) return Real::known(a.value * b.value);
  if (isKnown(a, 1.0)) return b;
  if (isKnown(b, 1.0)) return a;
  if (isKnown(a, -1.0)) return neg(b);
  if (isKnown(b, -1.0)) return neg(a);
  return emit(FieldOp::Mul, a, b);
}
Real TapeAlgebra::div(Real a, Real b) {
  if (a.is_known && b.is_known) return Real::known(a.value / b.value);
  if (isKnown(b, 1.0)) return a;
  return emit(FieldOp::Div, a, b);
}
// min and max ignore a NaN operand, as the tape's (field_scalar.h).
Real TapeAlgebra::min(Real a, Real b) {
  if (a.is_known && b.is_known) return Real::known((a.value < b.value || b.value != b.value) ? a.value : b.value);
  return emit(FieldOp::Min, a, b);
}
Real TapeAlgebra::max(Real a, Real b) {
  if (a.is_known && b.is_known) return Real::known((a.value > b.value || b.value != b.value) ? a.value : b.value);
  return emit(FieldOp::Max, a, b);
}

// a^n for n >= 0 by squaring and multiplying (a^0 = 1, as HyperFun's empty product).
Real TapeAlgebra::integerPower(Real a, uint64_t n) {
  Real result = Real::known(1.0);
  while (n) {
    if (n & 1) result = mul(result, a);
    n >>= 1;
    if (n) a = square(a);
  }
  return result;
}

Real TapeAlgebra::pow(Real a, Real b) {
  if (b.is_known && b.value - std::floor(b.value) < kEps && std::fabs(b.value) < 4.0e9) {
    const double c = std::ceil(std::fabs(b.value));  // HyperFun's HF_round of |b|
    const auto n = static_cast<uint64_t>(c - std::fabs(b.value) > 0.5 ? c - 1.0 : c);
    const Real p = integerPower(a, n);
    return b.value < 0.0 ? div(Real::known(1.0), p) : p;
  }
  return exp(mul(b, log(a)));
}

Real TapeAlgebra::unite(Real a, Real b) { return add(add(a, b), sqrt(add(square(a), square(b)))); }
Real TapeAlgebra::intersect(Real a, Real b) { return sub(add(a, b), sqrt(add(square(a), square(b)))); }
// a & -b, written a - b - sqrt(a^2 + b^2): the same doubles, since (-b)^2 = b^2 and a + (-b) = a - b.
Real TapeAlgebra::subtract(Real a, Real b) { return sub(sub(a, b), sqrt(add(square(a), square(b)))); }

}  // namespace pf::field::hyperfun
