// HyperFun's functions as tape builders: the built-in maths (sqrt ... frac), the hf* library
// (primitives, blends, space mappings) and the R-function set operators.
//
// A model compiles symbolically: every real is either known when the model is compiled (a
// double: literals, a[] parameters and what follows from them) or a value on the FieldTape
// (anything that depends on the point x). Real keeps the two apart; TapeAlgebra combines Reals,
// folding known ones in double -- as HyperFun computes -- and emitting tape instructions for the
// rest. A library function takes its real arguments as Reals and its array arguments as vectors
// of Reals whose sizes are known; a space mapping overwrites the items of the array it is given
// (the aliasing HyperFun has: a mapping applied to x changes every later use of x).
// The formulas are those of shared/hyperfun.md a.5-a.6; docs/hyperfun.md says what is rejected.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/field/field_tape.h"

namespace pf::field::hyperfun {

inline constexpr double kEps = 1e-6;  // HyperFun's EPS: comparisons, integer exponents, truth

// A real while a model compiles: known (a double) or the id of a value on the tape.
struct Real {
  bool is_known = true;
  double value = 0.0;  // when known
  uint32_t id = 0;     // when on the tape

  static Real known(double v) { return {true, v, 0}; }
  static Real onTape(uint32_t id) { return {false, 0.0, id}; }
};

// Arithmetic on Reals: known operands fold in double, the others become tape instructions.
class TapeAlgebra {
 public:
  explicit TapeAlgebra(FieldTapeBuilder& builder) : b_(builder) {}

  Real x() { return Real::onTape(b_.x()); }
  Real y() { return Real::onTape(b_.y()); }
  Real z() { return Real::onTape(b_.z()); }
  uint32_t materialize(Real r) { return r.is_known ? b_.constant(static_cast<float>(r.value)) : r.id; }
  size_t tapeSize() const { return b_.size(); }

  Real add(Real a, Real b);
  Real sub(Real a, Real b);
  Real mul(Real a, Real b);
  Real div(Real a, Real b);
  Real min(Real a, Real b);
  Real max(Real a, Real b);
  Real neg(Real a) { return a.is_known ? Real::known(-a.value) : emit(FieldOp::Neg, a); }
  Real abs(Real a) { return a.is_known ? Real::known(std::fabs(a.value)) : emit(FieldOp::Abs, a); }
  Real square(Real a) { return a.is_known ? Real::known(a.value * a.value) : emit(FieldOp::Square, a); }
  Real sqrt(Real a) { return a.is_known ? Real::known(std::sqrt(a.value)) : emit(FieldOp::Sqrt, a); }
  Real exp(Real a) { return a.is_known ? Real::known(std::exp(a.value)) : emit(FieldOp::Exp, a); }
  Real log(Real a) { return a.is_known ? Real::known(std::log(a.value)) : emit(FieldOp::Log, a); }
  Real sin(Real a) { return a.is_known ? Real::known(std::sin(a.value)) : emit(FieldOp::Sin, a); }
  Real cos(Real a) { return a.is_known ? Real::known(std::cos(a.value)) : emit(FieldOp::Cos, a); }
  Real atan(Real a) { return a.is_known ? Real::known(std::atan(a.value)) : emit(FieldOp::Atan, a); }
  Real floor(Real a) { return a.is_known ? Real::known(std::floor(a.value)) : emit(FieldOp::Floor, a); }
  // Entry floor(a) of one of HyperFun's Perlin tables (op: FieldOp::NoisePerm ... NoiseGradZ); a
  // known index reads the tables as HyperFun holds them (ints, double gradients).
  Real noiseTable(FieldOp op, Real a);
  // C's (int) cast of a (towards zero), as a double: -floor(-a) below 0, floor(a) elsewhere.
  Real trunc(Real a) { return a.is_known ? Real::known(std::trunc(a.value)) : select(less(a, Real::known(0.0)), neg(floor(neg(a))), floor(a)); }

  // HyperFun's a^b: an exponent within 1e-6 above an integer n multiplies (a negative base is
  // fine; a negative n takes the reciprocal); any other exponent is exp(b*log(a)).
  Real pow(Real a, Real b);
  Real integerPower(Real a, uint64_t n);  // a^n by squaring (a^0 = 1)
  // The R-functions of HyperFun's set operators with alpha = 0.
  Real unite(Real a, Real b);      // a | b = a + b + sqrt(a^2 + b^2)
  Real intersect(Real a, Real b);  // a & b = a + b - sqrt(a^2 + b^2), and a @ b
  Real subtract(Real a, Real b);   // a \ b = a & -b
  // Point-dependent choices: 1 where a < b (a <= b) holds, 0 elsewhere (false with NaN, as C);
  // cond != 0 ? if_true : if_false, only the chosen side's value (FieldOp::Select).
  Real less(Real a, Real b);
  Real lessEq(Real a, Real b);
  Real select(Real cond, Real if_true, Real if_false);
  // The Cauchy kernel 1/(1 + s^2 r^2)^2 integrated along the segment from b to e (r: the distance
  // from x to the segment's point), in closed form: hfConvLine's and hfConvCurve's term.
  Real cauchySegment(const Real x[3], const Real b[3], const Real e[3], Real s);

 private:
  Real emit(FieldOp op, Real a);
  Real emit(FieldOp op, Real a, Real b);
  FieldTapeBuilder& b_;
};

// A library function's complaint about its arguments: `argument` is the 0-based argument it is
// about, or -1 for the call as a whole. Thrown by LibraryFunction::build.
struct LibraryError {
  int argument = -1;
  std::string message;
};

struct LibraryFunction;

// One call's arguments, evaluated. For argument i, reals[i] holds a real argument and arrays[i]
// points at the items of an array argument (nullptr for reals); array_names[i] names it.
struct LibraryCall {
  TapeAlgebra& alg;
  const LibraryFunction& function;
  std::vector<Real> reals;
  std::vector<std::vector<Real>*> arrays;
  std::vector<std::string> array_names;
};

struct LibraryFunction {
  std::string_view name;         // "hfSphere"; looked up case-insensitively
  std::string_view params;       // "x, center, R": the parameter names, for messages
  std::string_view kinds;        // one letter per argument: 'R' a real, 'A' the name of an array
  Real (*build)(LibraryCall&);   // the value (throws LibraryError); nullptr when unsupported
  std::string_view unsupported;  // when build is nullptr: the error at the call, '$' standing for `name`
};

// The function named `lowercase_name`, or nullptr. Every name HyperFun reserves for a function
// is there, including the ones primflow does not support yet (build == nullptr).
const LibraryFunction* findLibraryFunction(std::string_view lowercase_name);
inline bool isLibraryName(std::string_view lowercase_name) { return findLibraryFunction(lowercase_name) != nullptr; }

}  // namespace pf::field::hyperfun
