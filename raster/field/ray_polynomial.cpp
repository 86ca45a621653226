// Ray polynomial form: truncated polynomial arithmetic over the tape.
#include "raster/field/ray_polynomial.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pf::field {
namespace {

using Poly = RayPolynomial;

Poly constantPoly(double v) {
  Poly p;
  p.c[0] = v;
  return p;
}

void trim(Poly& p) {
  p.degree = 4;
  while (p.degree > 0 && p.c[p.degree] == 0.0) --p.degree;
}

std::optional<Poly> multiply(const Poly& a, const Poly& b) {
  if (a.degree + b.degree > 4) return std::nullopt;
  Poly r;
  for (int i = 0; i <= a.degree; ++i)
    for (int j = 0; j <= b.degree; ++j) r.c[i + j] += a.c[i] * b.c[j];
  trim(r);
  return r;
}

}  // namespace

double RayPolynomial::evaluate(double t) const {
  double v = 0.0;
  for (int k = degree; k >= 0; --k) v = v * t + c[k];
  return v;
}

std::optional<RayPolynomial> rayPolynomial(const FieldTape& tape, const std::array<double, 3>& origin,
                                           const std::array<double, 3>& direction) {
  std::vector<Poly> v(tape.instrs.size());
  for (size_t i = 0; i < tape.instrs.size(); ++i) {
    const FieldInstr& in = tape.instrs[i];
    const Poly& a = v[in.a];
    const Poly& b = v[in.b];
    Poly r;
    // Operations without a polynomial meaning apply only to constants.
    auto onConstant = [&](double value) -> bool {
      if (a.degree != 0 || (fieldOpArity(in.op) == 2 && b.degree != 0)) return false;
      r = constantPoly(value);
      return true;
    };
    switch (in.op) {
      case FieldOp::X: case FieldOp::Y: case FieldOp::Z: {
        const int axis = in.op == FieldOp::X ? 0 : in.op == FieldOp::Y ? 1 : 2;
        r.c[0] = origin[axis];
        r.c[1] = direction[axis];
        trim(r);
        break;
      }
      case FieldOp::Const: r = constantPoly(in.value); break;
      case FieldOp::Neg:
        r = a;
        for (double& c : r.c) c = -c;
        break;
      case FieldOp::Square: {
        auto m = multiply(a, a);
        if (!m) return std::nullopt;
        r = *m;
        break;
      }
      case FieldOp::Mul: {
        auto m = multiply(a, b);
        if (!m) return std::nullopt;
        r = *m;
        break;
      }
      case FieldOp::Add: case FieldOp::Sub:
        for (int k = 0; k <= 4; ++k) r.c[k] = in.op == FieldOp::Add ? a.c[k] + b.c[k] : a.c[k] - b.c[k];
        trim(r);
        break;
      case FieldOp::Div:
        if (b.degree != 0 || b.c[0] == 0.0) return std::nullopt;
        for (int k = 0; k <= 4; ++k) r.c[k] = a.c[k] / b.c[0];
        trim(r);
        break;
      case FieldOp::Abs: if (!onConstant(std::fabs(a.c[0]))) return std::nullopt; break;
      case FieldOp::Sqrt: if (!onConstant(std::sqrt(a.c[0]))) return std::nullopt; break;
      case FieldOp::Exp: if (!onConstant(std::exp(a.c[0]))) return std::nullopt; break;
      case FieldOp::Log: if (!onConstant(std::log(a.c[0]))) return std::nullopt; break;
      case FieldOp::Sin: if (!onConstant(std::sin(a.c[0]))) return std::nullopt; break;
      case FieldOp::Cos: if (!onConstant(std::cos(a.c[0]))) return std::nullopt; break;
      case FieldOp::Min: if (!onConstant(std::min(a.c[0], b.c[0]))) return std::nullopt; break;
      case FieldOp::Max: if (!onConstant(std::max(a.c[0], b.c[0]))) return std::nullopt; break;
    }
    v[i] = r;
  }
  if (tape.instrs.empty()) return std::nullopt;
  return v[tape.result];
}

int fieldPolynomialDegree(const FieldTape& tape) {
  std::vector<int> degree(tape.instrs.size(), 0);  // -1: not a polynomial
  for (size_t i = 0; i < tape.instrs.size(); ++i) {
    const FieldInstr& in = tape.instrs[i];
    const int a = fieldOpArity(in.op) >= 1 ? degree[in.a] : 0;
    const int b = fieldOpArity(in.op) == 2 ? degree[in.b] : 0;
    int d = -1;
    if (a >= 0 && b >= 0) {
      switch (in.op) {
        case FieldOp::X: case FieldOp::Y: case FieldOp::Z: d = 1; break;
        case FieldOp::Const: d = 0; break;
        case FieldOp::Neg: d = a; break;
        case FieldOp::Square: d = 2 * a; break;
        case FieldOp::Add: case FieldOp::Sub: d = std::max(a, b); break;
        case FieldOp::Mul: d = a + b; break;
        case FieldOp::Div: d = b == 0 ? a : -1; break;
        default: d = (a == 0 && b == 0) ? 0 : -1; break;  // constants only (folded by the builder)
      }
    }
    degree[i] = d;
  }
  return tape.instrs.empty() ? -1 : degree[tape.result];
}

}  // namespace pf::field
