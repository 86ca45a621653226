// The interval form of a field: f over a box [x] x [y] x [z], enclosing every value the float
// form takes at a point of the box (interval.h says how). It also records, per min/max, which
// operand the intervals prove to be the result over the whole box -- the input of tape
// simplification (FieldTape simplify()), which is what makes a 7,866-op model fast: inside a
// small block most of a CSG tree is decided and drops out.
#pragma once

#include <vector>

#include "compiler/field/field_tape.h"
#include "raster/field/interval.h"

namespace pf::field {

class IntervalEvaluator {
 public:
  explicit IntervalEvaluator(const FieldTape& tape) : tape_(&tape), values_(tape.instrs.size()) {}
  // No field yet: evaluate() gives the whole line until reset() names one.
  IntervalEvaluator() = default;
  // Makes this the evaluator of `tape` (which must outlive its use), keeping the values'
  // storage: a scratch evaluator for many tapes allocates nothing once grown.
  void reset(const FieldTape& tape) {
    tape_ = &tape;
    if (values_.size() < tape.instrs.size()) values_.resize(tape.instrs.size());
  }

  // f over the box. With `choices`, fills it (one entry per instruction) with the proven operand
  // of each min/max (Both where neither dominates, and for every other instruction).
  Interval evaluate(Interval x, Interval y, Interval z, std::vector<Choice>* choices = nullptr);

 private:
  const FieldTape* tape_ = nullptr;
  std::vector<Interval> values_;
};

}  // namespace pf::field
