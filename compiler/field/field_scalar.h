// The float meaning of each field operation: constant folding (FieldTapeBuilder) uses it, and the
// float evaluator's SIMD loops compute the same -- exactly for + - * / sqrt abs neg min max, within
// a few ULP for exp, log, sin, cos, atan (Highway's vector versions, raster/field/slot_loops_simd.cpp).
//
// min and max ignore a NaN operand (as C's fmin/fmax): a field that is NaN somewhere (sqrt of a
// negative, 0/0) then still has a defined union or intersection, and the interval evaluator,
// which treats "could be NaN" as "could be anything", stays sound for them.
#pragma once

#include <cmath>

#include "compiler/field/field_tape.h"
#include "compiler/field/perlin_tables.h"

namespace pf::field {

inline float fieldMin(float a, float b) { return (a < b || b != b) ? a : b; }
inline float fieldMax(float a, float b) { return (a > b || b != b) ? a : b; }

inline float applyFieldOp(FieldOp op, float a, float b) {
  switch (op) {
    case FieldOp::Neg: return -a;
    case FieldOp::Abs: return std::fabs(a);
    case FieldOp::Square: return a * a;
    case FieldOp::Sqrt: return std::sqrt(a);
    case FieldOp::Exp: return std::exp(a);
    case FieldOp::Log: return std::log(a);
    case FieldOp::Sin: return std::sin(a);
    case FieldOp::Cos: return std::cos(a);
    case FieldOp::Atan: return std::atan(a);
    case FieldOp::Floor: return std::floor(a);
    case FieldOp::NoisePerm: case FieldOp::NoiseGradX: case FieldOp::NoiseGradY: case FieldOp::NoiseGradZ:
      return perlinTableValue(op, a);
    case FieldOp::Add: return a + b;
    case FieldOp::Sub: return a - b;
    case FieldOp::Mul: return a * b;
    case FieldOp::Div: return a / b;
    case FieldOp::Min: return fieldMin(a, b);
    case FieldOp::Max: return fieldMax(a, b);
    case FieldOp::Less: return a < b ? 1.0f : 0.0f;
    case FieldOp::LessEq: return a <= b ? 1.0f : 0.0f;
    case FieldOp::Select:  // ternary: applySelect
    case FieldOp::X: case FieldOp::Y: case FieldOp::Z: case FieldOp::Const: case FieldOp::Sample: break;
  }
  return a;
}

inline float applySelect(float cond, float if_true, float if_false) { return cond != 0.0f ? if_true : if_false; }

}  // namespace pf::field
