// GradientEvaluator: dual numbers with three derivative components, one pass over the tape.
#include "raster/field/gradient_evaluator.h"

#include <cmath>

#include "compiler/field/field_scalar.h"

namespace pf::field {
namespace {

using G = FieldGradient;

// value v with derivative d * (the operand's derivative): the chain rule for unary ops.
G chain(float v, float d, const G& a) { return {v, d * a.dx, d * a.dy, d * a.dz}; }

}  // namespace

FieldGradient GradientEvaluator::evaluate(float x, float y, float z) {
  const std::vector<FieldInstr>& code = tape_->instrs;
  G* v = values_.data();
  for (size_t i = 0; i < code.size(); ++i) {
    const FieldInstr& in = code[i];
    const G& a = v[in.a];
    const G& b = v[in.b];
    switch (in.op) {
      case FieldOp::X: v[i] = {x, 1.0f, 0.0f, 0.0f}; break;
      case FieldOp::Y: v[i] = {y, 0.0f, 1.0f, 0.0f}; break;
      case FieldOp::Z: v[i] = {z, 0.0f, 0.0f, 1.0f}; break;
      case FieldOp::Const: v[i] = {in.value, 0.0f, 0.0f, 0.0f}; break;
      case FieldOp::Neg: v[i] = chain(-a.value, -1.0f, a); break;
      case FieldOp::Abs: v[i] = chain(std::fabs(a.value), a.value < 0.0f ? -1.0f : 1.0f, a); break;
      case FieldOp::Square: v[i] = chain(a.value * a.value, 2.0f * a.value, a); break;
      case FieldOp::Sqrt: {
        const float r = std::sqrt(a.value);
        v[i] = chain(r, 0.5f / r, a);
        break;
      }
      case FieldOp::Exp: {
        const float e = std::exp(a.value);
        v[i] = chain(e, e, a);
        break;
      }
      case FieldOp::Log: v[i] = chain(std::log(a.value), 1.0f / a.value, a); break;
      case FieldOp::Sin: v[i] = chain(std::sin(a.value), std::cos(a.value), a); break;
      case FieldOp::Cos: v[i] = chain(std::cos(a.value), -std::sin(a.value), a); break;
      case FieldOp::Add: v[i] = {a.value + b.value, a.dx + b.dx, a.dy + b.dy, a.dz + b.dz}; break;
      case FieldOp::Sub: v[i] = {a.value - b.value, a.dx - b.dx, a.dy - b.dy, a.dz - b.dz}; break;
      case FieldOp::Mul:
        v[i] = {a.value * b.value, a.dx * b.value + a.value * b.dx, a.dy * b.value + a.value * b.dy,
                a.dz * b.value + a.value * b.dz};
        break;
      case FieldOp::Div: {
        const float q = a.value / b.value;
        const float inv = 1.0f / b.value;
        v[i] = {q, (a.dx - q * b.dx) * inv, (a.dy - q * b.dy) * inv, (a.dz - q * b.dz) * inv};
        break;
      }
      case FieldOp::Min: v[i] = fieldMin(a.value, b.value) == a.value && !(a.value != a.value) ? a : b; break;
      case FieldOp::Max: v[i] = fieldMax(a.value, b.value) == a.value && !(a.value != a.value) ? a : b; break;
    }
  }
  return code.empty() ? G{} : v[tape_->result];
}

}  // namespace pf::field
