// Ray polynomial form: truncated polynomial arithmetic over the tape.
#include "raster/field/ray_polynomial.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "compiler/field/perlin_tables.h"

namespace pf::field {
namespace {

using Poly = RayPolynomial;

// The helpers below write their result into `r` element by element: a value the next
// instruction reads is read the same way, element by element. (Building a Poly on the stack and
// copying it into the array made the copy's wide loads wait on the narrow stores just made -- a
// failed store forward per instruction, most of a ray's time on small tapes.)
void setConstant(Poly& r, double value) {
  r.c[0] = value;
  for (int k = 1; k <= 4; ++k) r.c[k] = 0.0;
  r.degree = 0;
}

void copyPoly(Poly& r, const Poly& a, double sign) {
  for (int k = 0; k <= 4; ++k) r.c[k] = sign * a.c[k];
  r.degree = a.degree;
}

void trim(Poly& p) {
  p.degree = 4;
  while (p.degree > 0 && p.c[p.degree] == 0.0) --p.degree;
}

// a * b into r (neither is r); false when the product's degree passes 4.
bool multiplyInto(const Poly& a, const Poly& b, Poly& r) {
  if (a.degree + b.degree > 4) return false;
  for (int k = 0; k <= 4; ++k) r.c[k] = 0.0;
  for (int i = 0; i <= a.degree; ++i)
    for (int j = 0; j <= b.degree; ++j) r.c[i + j] += a.c[i] * b.c[j];
  trim(r);
  return true;
}

}  // namespace

double RayPolynomial::evaluate(double t) const {
  double v = 0.0;
  for (int k = degree; k >= 0; --k) v = v * t + c[k];
  return v;
}

bool rayPolynomials(const FieldTape& tape, const std::array<double, 3>& origin, const std::array<double, 3>& direction,
                    std::vector<RayPolynomial>& v, std::vector<uint8_t>& valid, bool stop_at_invalid) {
  v.resize(tape.instrs.size());
  valid.assign(tape.instrs.size(), 1);
  for (size_t i = 0; i < tape.instrs.size(); ++i) {
    const FieldInstr& in = tape.instrs[i];
    const int arity = fieldOpArity(in.op);
    if ((arity >= 1 && !valid[in.a]) || (arity >= 2 && !valid[in.b]) || (arity == 3 && !valid[in.c])) {
      valid[i] = 0;
      continue;
    }
    // The result goes straight into v[i]; its operands are earlier values, never v[i] itself
    // (a leaf reads neither).
    const Poly& a = v[in.a];
    const Poly& b = v[in.b];
    Poly& r = v[i];
    bool ok = true;
    // Operations without a polynomial meaning apply only to constants.
    auto onConstant = [&](double value) {
      if (a.degree != 0 || (arity >= 2 && b.degree != 0)) return false;
      setConstant(r, value);
      return true;
    };
    switch (in.op) {
      case FieldOp::X: case FieldOp::Y: case FieldOp::Z: {
        const int axis = in.op == FieldOp::X ? 0 : in.op == FieldOp::Y ? 1 : 2;
        setConstant(r, origin[axis]);
        r.c[1] = direction[axis];
        trim(r);
        break;
      }
      case FieldOp::Const: setConstant(r, in.value); break;
      case FieldOp::Neg: copyPoly(r, a, -1.0); break;
      case FieldOp::Square: case FieldOp::Mul: ok = multiplyInto(a, in.op == FieldOp::Square ? a : b, r); break;
      case FieldOp::Add: case FieldOp::Sub:
        for (int k = 0; k <= 4; ++k) r.c[k] = in.op == FieldOp::Add ? a.c[k] + b.c[k] : a.c[k] - b.c[k];
        trim(r);
        break;
      case FieldOp::Div:
        ok = b.degree == 0 && b.c[0] != 0.0;
        if (ok) {
          for (int k = 0; k <= 4; ++k) r.c[k] = a.c[k] / b.c[0];
          trim(r);
        }
        break;
      case FieldOp::Abs: ok = onConstant(std::fabs(a.c[0])); break;
      case FieldOp::Sqrt: ok = onConstant(std::sqrt(a.c[0])); break;
      case FieldOp::Exp: ok = onConstant(std::exp(a.c[0])); break;
      case FieldOp::Log: ok = onConstant(std::log(a.c[0])); break;
      case FieldOp::Sin: ok = onConstant(std::sin(a.c[0])); break;
      case FieldOp::Cos: ok = onConstant(std::cos(a.c[0])); break;
      case FieldOp::Atan: ok = onConstant(std::atan(a.c[0])); break;
      case FieldOp::Floor: ok = onConstant(std::floor(a.c[0])); break;
      case FieldOp::NoisePerm: case FieldOp::NoiseGradX: case FieldOp::NoiseGradY: case FieldOp::NoiseGradZ:
        ok = onConstant(perlinTableValue(in.op, static_cast<float>(a.c[0])));
        break;
      case FieldOp::Min: ok = onConstant(std::min(a.c[0], b.c[0])); break;
      case FieldOp::Max: ok = onConstant(std::max(a.c[0], b.c[0])); break;
      case FieldOp::Less: ok = onConstant(a.c[0] < b.c[0] ? 1.0 : 0.0); break;
      case FieldOp::LessEq: ok = onConstant(a.c[0] <= b.c[0] ? 1.0 : 0.0); break;
      case FieldOp::Sample: ok = false; break;  // a grid is no polynomial
      case FieldOp::Select:  // a condition constant along the ray picks one polynomial
        ok = a.degree == 0;
        if (ok) copyPoly(r, a.c[0] != 0.0 ? b : v[in.c], 1.0);
        break;
    }
    if (!ok) {
      if (stop_at_invalid) return false;
      valid[i] = 0;
    }
  }
  return true;
}

std::optional<RayPolynomial> rayPolynomial(const FieldTape& tape, const std::array<double, 3>& origin,
                                           const std::array<double, 3>& direction) {
  if (tape.instrs.empty()) return std::nullopt;
  thread_local std::vector<Poly> v;  // reused per thread: a ray costs no allocation
  thread_local std::vector<uint8_t> valid;
  if (!rayPolynomials(tape, origin, direction, v, valid, true) || !valid[tape.result]) return std::nullopt;
  return v[tape.result];
}

std::vector<int> polynomialDegrees(const FieldTape& tape) {
  std::vector<int> degree(tape.instrs.size(), 0);  // -1: not a polynomial
  for (size_t i = 0; i < tape.instrs.size(); ++i) {
    const FieldInstr& in = tape.instrs[i];
    const int a = fieldOpArity(in.op) >= 1 ? degree[in.a] : 0;
    const int b = fieldOpArity(in.op) >= 2 ? degree[in.b] : 0;
    const int c = fieldOpArity(in.op) == 3 ? degree[in.c] : 0;
    int d = -1;
    if (a >= 0 && b >= 0 && c >= 0) {
      switch (in.op) {
        case FieldOp::X: case FieldOp::Y: case FieldOp::Z: d = 1; break;
        case FieldOp::Const: d = 0; break;
        case FieldOp::Sample: d = -1; break;
        case FieldOp::Neg: d = a; break;
        case FieldOp::Square: d = 2 * a; break;
        case FieldOp::Add: case FieldOp::Sub: d = std::max(a, b); break;
        case FieldOp::Mul: d = a + b; break;
        case FieldOp::Div: d = b == 0 ? a : -1; break;
        default: d = (a == 0 && b == 0 && c == 0) ? 0 : -1; break;  // constants only (folded by the builder)
      }
    }
    degree[i] = d;
  }
  return degree;
}

int fieldPolynomialDegree(const FieldTape& tape) {
  return tape.instrs.empty() ? -1 : polynomialDegrees(tape)[tape.result];
}

}  // namespace pf::field
