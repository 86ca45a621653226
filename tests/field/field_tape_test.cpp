// FieldTape: sharing and folding in the builder, dead-code removal, tape simplification.
#include <gtest/gtest.h>

#include "compiler/field/field_tape.h"
#include "field/field_reference.h"
#include "raster/field/float_evaluator.h"

namespace pf::field {
namespace {

TEST(FieldTape, BuilderSharesRepeatsAndCommutedOperands) {
  FieldTapeBuilder b;
  const uint32_t x = b.x(), y = b.y();
  EXPECT_EQ(b.x(), x);
  EXPECT_EQ(b.binary(FieldOp::Add, x, y), b.binary(FieldOp::Add, y, x));
  EXPECT_EQ(b.binary(FieldOp::Max, x, y), b.binary(FieldOp::Max, y, x));
  EXPECT_NE(b.binary(FieldOp::Sub, x, y), b.binary(FieldOp::Sub, y, x));  // not commutative
  EXPECT_EQ(b.binary(FieldOp::Min, x, x), x);
  const uint32_t sq = b.binary(FieldOp::Mul, x, x);
  EXPECT_EQ(b.unary(FieldOp::Square, x), sq);
}

TEST(FieldTape, BuilderFoldsConstantsAsTheFloatFormWould) {
  FieldTapeBuilder b;
  const uint32_t c = b.binary(FieldOp::Div, b.constant(1.0f), b.constant(3.0f));
  const uint32_t s = b.unary(FieldOp::Sin, c);
  const FieldTape t = b.finish(b.binary(FieldOp::Add, b.x(), s));
  ASSERT_EQ(t.size(), 3u);  // x, the folded constant, add
  const FieldInstr& add = t.instrs[t.result];
  const FieldInstr& folded = t.instrs[t.instrs[add.a].op == FieldOp::Const ? add.a : add.b];
  EXPECT_EQ(folded.op, FieldOp::Const);
  EXPECT_EQ(folded.value, std::sin(1.0f / 3.0f));
}

TEST(FieldTape, FinishRemovesDeadCode) {
  FieldTapeBuilder b;
  const uint32_t x = b.x();
  b.unary(FieldOp::Sqrt, b.y());  // never used
  const FieldTape t = b.finish(b.unary(FieldOp::Neg, x));
  EXPECT_EQ(t.size(), 2u);
  EXPECT_FALSE(t.usesZ());
  EXPECT_EQ(t.print(), "_0 var-x\n_1 neg _0\nresult _1\n");
}

// max(min(x, 1), y - 2): with min decided Left (x <= 1) the tape is max(x, y - 2); with the max
// decided Right too it is y - 2, with x gone.
TEST(FieldTape, SimplifyFollowsTheChosenOperandsAndKeepsValuesBitExact) {
  FieldTapeBuilder b;
  const uint32_t x = b.x(), one = b.constant(1.0f), y = b.y(), two = b.constant(2.0f);
  const uint32_t mn = b.binary(FieldOp::Min, x, one);
  const uint32_t sub = b.binary(FieldOp::Sub, y, two);
  const FieldTape t = b.finish(b.binary(FieldOp::Max, mn, sub));
  std::vector<Choice> choices(t.size(), Choice::Both);
  size_t min_at = 0, max_at = 0;
  for (size_t i = 0; i < t.size(); ++i) {
    if (t.instrs[i].op == FieldOp::Min) min_at = i;
    if (t.instrs[i].op == FieldOp::Max) max_at = i;
  }
  // Choices name the stored operand order (a, b): find which side is x and which is the min.
  const bool x_first = t.instrs[t.instrs[min_at].a].op == FieldOp::X;
  const bool min_first = t.instrs[max_at].a == min_at;
  choices[min_at] = x_first ? Choice::Left : Choice::Right;
  const FieldTape s1 = simplify(t, choices);
  EXPECT_EQ(s1.size(), t.size() - 2);  // the min and its constant
  choices[max_at] = min_first ? Choice::Right : Choice::Left;
  const FieldTape s2 = simplify(t, choices);
  EXPECT_EQ(s2.size(), 3u);  // y, 2, sub
  EXPECT_FALSE(s2.print().find("var-x") != std::string::npos);
  FloatEvaluator full(t), left(s1), right(s2);
  for (float x : {-3.0f, 0.25f, 0.999f}) {
    for (float y : {-1.0f, 0.5f, 2.75f}) {
      EXPECT_EQ(full.evaluate(x, y, 0.0f), left.evaluate(x, y, 0.0f));
      if (y - 2.0f >= x) {
        EXPECT_EQ(full.evaluate(x, y, 0.0f), right.evaluate(x, y, 0.0f));
      }
    }
  }
}

TEST(FloatEvaluator, ReusesSlotsAndMatchesTheDoubleEvaluation) {
  FieldTapeBuilder b;
  // Chain of 200 additions: only a couple of values are live at any time.
  uint32_t acc = b.x();
  for (int i = 0; i < 200; ++i) acc = b.binary(FieldOp::Add, acc, b.constant(static_cast<float>(i)));
  const FieldTape chain = b.finish(acc);
  FloatEvaluator eval(chain);
  EXPECT_LE(eval.slotCount(), 4);
  EXPECT_FLOAT_EQ(eval.evaluate(0.5f, 0.0f, 0.0f), static_cast<float>(testing::evaluateDouble(chain, 0.5, 0, 0)));
}

}  // namespace
}  // namespace pf::field
