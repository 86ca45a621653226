// TapeAlgebra (hyperfun_library.h): HyperFun's arithmetic on values that are known when the
// model compiles (folded in double, as HyperFun computes) or on the tape -- the operators, a^b and
// the R-functions the library functions are written with.
#include <algorithm>
#include <cmath>

#include "compiler/field/hyperfun_library.h"
#include "compiler/field/perlin_tables.h"

namespace pf::field::hyperfun {

Real TapeAlgebra::emit(FieldOp op, Real a) { return Real::onTape(b_.unary(op, materialize(a))); }

Real TapeAlgebra::noiseTable(FieldOp op, Real a) {
  if (!a.is_known) return emit(op, a);
  if (a.value != a.value) return a;
  const int k = static_cast<int>(std::clamp(std::floor(a.value), 0.0, static_cast<double>(kPerlinTableSize - 1)));
  const PerlinTables& t = perlinTables();
  const int table = perlinTableOf(op);
  return Real::known(table == 0 ? t.perm[k] : t.grad[k][table - 1]);
}
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

Real TapeAlgebra::less(Real a, Real b) {
  if (a.is_known && b.is_known) return Real::known(a.value < b.value ? 1.0 : 0.0);
  return emit(FieldOp::Less, a, b);
}

Real TapeAlgebra::lessEq(Real a, Real b) {
  if (a.is_known && b.is_known) return Real::known(a.value <= b.value ? 1.0 : 0.0);
  return emit(FieldOp::LessEq, a, b);
}

Real TapeAlgebra::select(Real cond, Real if_true, Real if_false) {
  if (cond.is_known) return cond.value != 0.0 ? if_true : if_false;
  const bool same = if_true.is_known == if_false.is_known &&
                    (if_true.is_known ? if_true.value == if_false.value : if_true.id == if_false.id);
  if (same) return if_true;
  return Real::onTape(b_.select(cond.id, materialize(if_true), materialize(if_false)));
}

Real TapeAlgebra::unite(Real a, Real b) { return add(add(a, b), sqrt(add(square(a), square(b)))); }
Real TapeAlgebra::intersect(Real a, Real b) { return sub(add(a, b), sqrt(add(square(a), square(b)))); }
// a & -b, written a - b - sqrt(a^2 + b^2): the same doubles, since (-b)^2 = b^2 and a + (-b) = a - b.
Real TapeAlgebra::subtract(Real a, Real b) { return sub(sub(a, b), sqrt(add(square(a), square(b)))); }

// McCormack and Sherstyuk's closed form ("Creating and rendering convolution surfaces", 1998).
// With a the segment's unit direction, l its length, d = x - b, h = d . a (x's position along
// the segment) and p^2 = 1 + s^2 (|d|^2 - h^2) (1 plus s^2 times the squared distance to the
// segment's line), the antiderivative of 1/(p^2 + s^2 u^2)^2 is
// u / (2 p^2 (p^2 + s^2 u^2)) + atan(s u / p) / (2 s p^3); between u = -h and l - h that is
//   h / (2 p^2 (1 + s^2 |x - b|^2)) + (l - h) / (2 p^2 (1 + s^2 |x - e|^2))
//   + (atan(s h / p) + atan(s (l - h) / p)) / (2 s p^3).
// A segment of length 0 contributes 0 (the integral over nothing).
Real TapeAlgebra::cauchySegment(const Real x[3], const Real b[3], const Real e[3], Real s) {
  Real ll = Real::known(0.0);
  for (int k = 0; k < 3; ++k) ll = add(ll, square(sub(e[k], b[k])));
  if (ll.is_known && ll.value == 0.0) return Real::known(0.0);
  const Real l = sqrt(ll);
  Real h = Real::known(0.0), db = Real::known(0.0), de = Real::known(0.0);
  for (int k = 0; k < 3; ++k) {
    const Real d = sub(x[k], b[k]);
    h = add(h, mul(d, div(sub(e[k], b[k]), l)));
    db = add(db, square(d));
    de = add(de, square(sub(x[k], e[k])));
  }
  const Real s2 = square(s);
  const Real one = Real::known(1.0), two = Real::known(2.0);
  const Real p2 = add(one, mul(s2, sub(db, square(h))));
  const Real p = sqrt(p2);
  const Real lh = sub(l, h);
  const Real near_end = div(h, mul(mul(two, p2), add(one, mul(s2, db))));
  const Real far_end = div(lh, mul(mul(two, p2), add(one, mul(s2, de))));
  const Real angles = add(atan(div(mul(s, h), p)), atan(div(mul(s, lh), p)));
  return add(add(near_end, far_end), div(angles, mul(mul(two, s), mul(p, p2))));
}

}  // namespace pf::field::hyperfun
