// The gradient form of a field: forward-mode automatic differentiation over the tape. Every value
// carries its partial derivatives in x, y and z; the surface normal is the normalized negative
// gradient (f >= 0 inside, so -grad f points out). Not finite differences: exact up to float
// rounding wherever the field is differentiable; at a kink (min, max, abs) it takes the side the
// float form takes.
#pragma once

#include <vector>

#include "compiler/field/field_tape.h"

namespace pf::field {

struct FieldGradient {
  float value = 0.0f;
  float dx = 0.0f, dy = 0.0f, dz = 0.0f;
};

class GradientEvaluator {
 public:
  explicit GradientEvaluator(const FieldTape& tape) : tape_(&tape), values_(tape.instrs.size()) {}
  FieldGradient evaluate(float x, float y, float z);

 private:
  const FieldTape* tape_;
  std::vector<FieldGradient> values_;
};

}  // namespace pf::field
