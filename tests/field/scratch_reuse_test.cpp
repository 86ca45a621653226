// The interval method's reused storage (ray_caster.cpp's Scratch): evaluators rebound with
// reset() give what fresh ones give, bit for bit, whatever they ran before; simplifyInto gives
// simplify()'s tape into an old tape's storage; TapePool hands out a tape only when no one else
// holds it.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "compiler/diagnostics.h"
#include "compiler/field/fidget_reader.h"
#include "field/field_reference.h"
#include "raster/field/float_evaluator.h"
#include "raster/field/interval_evaluator.h"
#include "raster/field/interval_slope_evaluator.h"
#include "raster/field/tape_pool.h"

namespace pf::field {
namespace {

std::vector<FieldTape> someTapes() {
  std::vector<FieldTape> tapes;
  for (const char* name : {"fidget/prospero.vm", "fidget/colonnade.vm", "fidget/tanglecube.vm"}) {
    DiagnosticLog log;
    tapes.push_back(*readFidgetModel(name, testing::readModelText(name), log));
  }
  FieldTapeBuilder b;
  tapes.push_back(b.finish(b.binary(FieldOp::Min, b.unary(FieldOp::Sin, b.x()), b.y())));
  return tapes;
}

// Boxes in [-1, 1]^3 of three sizes.
std::vector<std::array<Interval, 3>> someBoxes() {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<std::array<Interval, 3>> boxes;
  for (float size : {1.0f, 0.1f, 0.01f})
    for (int k = 0; k < 8; ++k) {
      const float x = u(rng), y = u(rng), z = u(rng);
      boxes.push_back({Interval{x, x + size}, Interval{y, y + size}, Interval{z, z + size}});
    }
  return boxes;
}

bool same(Interval a, Interval b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(ScratchReuse, EvaluatorsRebuiltByResetMatchFreshOnes) {
  const std::vector<FieldTape> tapes = someTapes();
  FloatEvaluator points;
  IntervalEvaluator intervals;
  IntervalSlopeEvaluator slopes;
  EXPECT_EQ(points.evaluate(0.5f, 0.5f, 0.5f), 0.0f);  // no field yet
  EXPECT_TRUE(intervals.evaluate({0, 1}, {0, 1}, {0, 1}).isWhole());
  EXPECT_TRUE(slopes.evaluate({0, 1}, {0, 1}, {0, 1}, {1, 1}, {0, 0}, {0, 0}).value.isWhole());
  float x[FloatEvaluator::kBatch], y[FloatEvaluator::kBatch], z[FloatEvaluator::kBatch];
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int i = 0; i < FloatEvaluator::kBatch; ++i) x[i] = u(rng), y[i] = u(rng), z[i] = u(rng);
  for (size_t order : {0, 3, 1, 2, 0, 2, 3, 1}) {  // large after small and small after large
    const FieldTape& t = tapes[order];
    FloatEvaluator fresh_points(t);
    IntervalEvaluator fresh_intervals(t);
    IntervalSlopeEvaluator fresh_slopes(t);
    points.reset(t);
    intervals.reset(t);
    slopes.reset(t);
    for (int n : {1, 7, 64}) {
      float want[FloatEvaluator::kBatch], got[FloatEvaluator::kBatch];
      fresh_points.evaluate(x, y, z, n, want);
      points.evaluate(x, y, z, n, got);
      ASSERT_EQ(std::memcmp(want, got, sizeof(float) * n), 0) << "tape " << order << ", n " << n;
    }
    for (const auto& b : someBoxes()) {
      std::vector<Choice> want_choices, got_choices;
      ASSERT_TRUE(same(fresh_intervals.evaluate(b[0], b[1], b[2], &want_choices),
                       intervals.evaluate(b[0], b[1], b[2], &got_choices)));
      ASSERT_EQ(want_choices, got_choices);
      const Interval d{0.5f, 0.6f};
      const IntervalSlope ws = fresh_slopes.evaluate(b[0], b[1], b[2], d, d, d);
      const IntervalSlope gs = slopes.evaluate(b[0], b[1], b[2], d, d, d);
      ASSERT_TRUE(same(ws.value, gs.value) && same(ws.rate, gs.rate)) << "tape " << order;
    }
  }
}

TEST(ScratchReuse, SimplifyIntoIsSimplify) {
  const std::vector<FieldTape> tapes = someTapes();
  FieldTape out;
  SimplifyScratch scratch;
  int decided = 0;
  for (size_t order : {0, 3, 1, 0, 2}) {
    const FieldTape& t = tapes[order];
    IntervalEvaluator ie(t);
    for (const auto& b : someBoxes()) {
      std::vector<Choice> choices;
      ie.evaluate(b[0], b[1], b[2], &choices);
      for (Choice c : choices) decided += c != Choice::Both;
      const FieldTape want = simplify(t, choices);
      simplifyInto(t, choices, out, scratch);
      ASSERT_EQ(want.instrs, out.instrs) << "tape " << order;
      ASSERT_EQ(want.result, out.result) << "tape " << order;
    }
  }
  EXPECT_GT(decided, 0);  // the boxes decided some min/max, so tapes were really cut
}

TEST(ScratchReuse, TapePoolRecyclesOnlyTapesNoOneHolds) {
  const std::vector<FieldTape> tapes = someTapes();
  const auto prospero = std::make_shared<const FieldTape>(tapes[0]);
  IntervalEvaluator ie(*prospero);
  std::vector<Choice> choices;
  const auto b = someBoxes().back();  // a small box: most of Prospero is decided
  ie.evaluate(b[0], b[1], b[2], &choices);
  TapePool pool;
  // Nothing decided: the tape itself, nothing made.
  const std::vector<Choice> none(prospero->size(), Choice::Both);
  EXPECT_EQ(pool.simplified(prospero, none), prospero);
  EXPECT_EQ(pool.size(), 0u);
  // Held tapes are never handed out again; released ones are.
  auto first = pool.simplified(prospero, choices);
  auto second = pool.simplified(prospero, choices);
  EXPECT_NE(first.get(), second.get());
  EXPECT_EQ(pool.size(), 2u);
  const FieldTape* second_address = second.get();
  second.reset();
  auto third = pool.simplified(prospero, choices);
  EXPECT_EQ(third.get(), second_address);
  EXPECT_EQ(pool.size(), 2u);
  const FieldTape want = simplify(*prospero, choices);
  EXPECT_EQ(first->instrs, want.instrs);
  EXPECT_EQ(third->instrs, want.instrs);
}

}  // namespace
}  // namespace pf::field
