// The Fidget .vm front end: the shipped models read and evaluate as Fidget's own meaning of the
// text (an independent double interpreter, with the sign flipped); bad files give precise errors.
#include <gtest/gtest.h>

#include <random>

#include "compiler/field/fidget_reader.h"
#include "field/field_reference.h"
#include "raster/field/float_evaluator.h"

namespace pf::field {
namespace {

FieldTape readOk(const std::string& relative) {
  DiagnosticLog log;
  auto tape = readFidgetModel(relative, testing::readModelText(relative), log);
  EXPECT_TRUE(tape) << log.format();
  return tape ? *tape : FieldTape{};
}

std::string readError(const std::string& text) {
  DiagnosticLog log;
  auto tape = readFidgetModel("bad.vm", text, log);
  EXPECT_FALSE(tape);
  return log.format();
}

TEST(FidgetReader, QuarterCircleIsInsideInTheLowerLeftOnly) {
  const FieldTape t = readOk("fidget/quarter.vm");
  FloatEvaluator f(t);
  EXPECT_GE(f.evaluate(-0.3f, -0.3f, 0.0f), 0.0f);  // inside: primflow's sign
  EXPECT_LT(f.evaluate(0.3f, -0.3f, 0.0f), 0.0f);
  EXPECT_LT(f.evaluate(-0.6f, -0.6f, 0.0f), 0.0f);  // past the circle r^2 = 0.5
  EXPECT_FALSE(t.usesZ());
}

// Every shipped model, at random points in [-1, 1]^3: float tape == -(Fidget's value) in double.
TEST(FidgetReader, ModelsEvaluateAsTheirTextSays) {
  for (const char* model : {"fidget/quarter.vm", "fidget/hi.vm", "fidget/tanglecube.vm", "fidget/bear.vm",
                            "fidget/colonnade.vm", "fidget/prospero.vm"}) {
    SCOPED_TRACE(model);
    const std::string text = testing::readModelText(model);
    const FieldTape t = readOk(model);
    FloatEvaluator f(t);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int checked = 0;
    for (int k = 0; k < 300; ++k) {
      const float x = u(rng), y = u(rng), z = u(rng);
      const double want = -testing::interpretVmDouble(text, x, y, z);
      const float got = f.evaluate(x, y, z);
      if (std::isnan(want)) continue;
      // Float against double through up to thousands of operations: a relative bound on the
      // result's magnitude, and the sign wherever the surface is not within that bound.
      EXPECT_NEAR(got, want, 1e-4 * std::max(1.0, std::fabs(want))) << x << ", " << y << ", " << z;
      if (std::fabs(want) > 1e-3) {
        EXPECT_EQ(got >= 0.0f, want >= 0.0) << x << ", " << y << ", " << z;
      }
      ++checked;
    }
    EXPECT_GT(checked, 250);
  }
}

TEST(FidgetReader, ProsperoKeepsItsSizeAndSharesNothingItShouldNot) {
  const FieldTape t = readOk("fidget/prospero.vm");
  // 7,866 operations in the file, plus the sign flip; sharing may only shrink it.
  EXPECT_LE(t.size(), 7867u);
  EXPECT_GT(t.size(), 7000u);
}

TEST(FidgetReader, ErrorsNameLineColumnAndShowACaret) {
  EXPECT_NE(readError("x var-x\ny atan2 x x\n").find("bad.vm:2:3: error: unsupported operation 'atan2'"),
            std::string::npos);
  EXPECT_NE(readError("x var-x\ny add x q\n").find("bad.vm:2:9: error: 'q' is not defined on an earlier line"),
            std::string::npos);
  EXPECT_NE(readError("x var-x\ny neg x x\n").find("bad.vm:2:9: error: 'neg' takes 1 argument, found 2"),
            std::string::npos);
  EXPECT_NE(readError("c const 1.5e99\n").find("bad.vm:1:9: error: '1.5e99' is not a finite number"),
            std::string::npos);
  EXPECT_NE(readError("c const 2x\n").find("'2x' is not a finite number"), std::string::npos);
  EXPECT_NE(readError("x var-x\nx var-y\n").find("bad.vm:2:1: error: 'x' is defined twice"), std::string::npos);
  EXPECT_NE(readError("# only a comment\n\n").find("bad.vm:1:1: error: the model has no operations"),
            std::string::npos);
  EXPECT_NE(readError("lonely\n").find("bad.vm:1:1: error: expected 'NAME OP ARGS...'"), std::string::npos);
  const std::string caret = readError("x var-x\ny bogus x\n");
  EXPECT_NE(caret.find("    y bogus x\n      ^"), std::string::npos) << caret;
}

}  // namespace
}  // namespace pf::field
