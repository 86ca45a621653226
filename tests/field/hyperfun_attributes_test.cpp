// HyperFun's attributes (the s array and the hfA_* library, seed 000's procedural colour): each
// attribute tape, evaluated in double, equals HyperFun's formula written out here independently
// (from its C code, argument order included) at many points; the shape's tape is not changed
// by them; misuse is reported at file:line:col.
#include <gtest/gtest.h>

#include <cmath>

#include "field/hyperfun_attribute_helpers.h"

namespace pf::field {
namespace {

using namespace attribute_testing;

TEST(HyperFunAttributes, AssignedItemsAreTheModelsColour) {
  expectAttributes(model("s[1] = 0.5 + 0.5*sin(3*x[1]);\ns[2] = x[2]*x[3];\ns[3] = 0.25;"),
                   [](double x, double y, double z) { return std::vector<double>{0.5 + 0.5 * std::sin(3 * x), y * z, 0.25}; });
  // A list, a branch on the point (joined by select), and items left at HyperFun's 0.
  expectAttributes(model("s = [0.1, 0.2, 0.3];\nif x[1] > 0 then s[2] = 1; else s[3] = x[3]; endif;"),
                   [](double x, double, double z) {
                     return x > 0 ? std::vector<double>{0.1, 1, 0.3} : std::vector<double>{0.1, 0.2, z};
                   },
                   [](double x, double, double) { return std::fabs(x) < 1e-6; });
  expectAttributes("my_model(x[3], a[1], s[2]) {\n s[1] = x[1];\n my_model = 1;\n}\n",
                   [](double x, double, double) { return std::vector<double>{x, 0}; });
}

TEST(HyperFunAttributes, TheShapeIsUnchangedAndAModelWithoutSHasNone) {
  const Compiled with = compileOk(model("s[1] = x[1];\ns[2] = hfA_Step(x[2], 0);"));
  const Compiled without = compileOk("my_model(x[3], a[1]) {\n my_model = 4 - x[1]*x[1] - x[2]*x[2] - x[3]*x[3];\n}\n");
  EXPECT_EQ(with.shape.print(), without.shape.print());
  EXPECT_TRUE(without.attributes.empty());
  // Through compileFieldSource: only HyperFun has attributes.
  DiagnosticLog log;
  std::vector<FieldTape> attributes(2);
  ASSERT_TRUE(compileFieldSource(FieldFormat::Fidget, "m.vm", "x var-x\n", {}, 0.0, log, "", &attributes));
  EXPECT_TRUE(attributes.empty());
  ASSERT_TRUE(compileFieldSource(FieldFormat::HyperFun, "m.hf", model("s[3] = 2;"), {}, 0.0, log, "", &attributes));
  ASSERT_EQ(attributes.size(), 3u);
  EXPECT_EQ(testing::evaluateDouble(attributes[2], 0, 0, 0), 2.0);
}

TEST(HyperFunAttributes, SetColorAndSetAttributesWriteWhereFIsNotNegative) {
  // HyperFun's hfA_SetColor(f, s, r, g, b): s = (r, g, b) where f >= 0.
  expectAttributes(model("s = [0.1, 0.2, 0.3];\nd = hfA_SetColor(x[1] - 0.5, s, 1, x[2], 0);"),
                   [](double x, double y, double) {
                     return x - 0.5 >= 0 ? std::vector<double>{1, y, 0} : std::vector<double>{0.1, 0.2, 0.3};
                   },
                   [](double x, double, double) { return std::fabs(x - 0.5) < 1e-6; });
  // hfA_SetAttributes(f, s, s1): the first min(|s|, |s1|) items.
  expectAttributes(model("array c[2];\nc = [0.7, 0.8];\nd = hfA_SetAttributes(x[3], s, c);"),
                   [](double, double, double z) {
                     return z >= 0 ? std::vector<double>{0.7, 0.8, 0} : std::vector<double>{0, 0, 0};
                   },
                   [](double, double, double z) { return std::fabs(z) < 1e-6; });
}

TEST(HyperFunAttributes, LerpAndCerpInterpolateBetweenTwoArrays) {
  // hfA_Lerp(s, s1, s2, f, fmin, fmax): t = (f - fmin)/(fmax - fmin), s1 below 0, s2 above 1.
  // HyperFun registers hfA_Cerp with hfA_Lerp's code: the same values.
  for (const char* name : {"hfA_Lerp", "hfA_Cerp"}) {
    const std::string body = std::string("array c1[3], c2[3];\nc1 = [1, 0, 0];\nc2 = [0, 0.5, 1];\n") +
                             "s[3] = " + name + "(s, c1, c2, x[1], -1, 1.5);";
    expectAttributes(model(body), [](double x, double, double) {
      const double t = (x + 1) / 2.5;
      const double c1[3] = {1, 0, 0}, c2[3] = {0, 0.5, 1};
      std::vector<double> s(3);
      for (int i = 0; i < 3; ++i) s[i] = t < 0 ? c1[i] : t > 1 ? c2[i] : (1 - t) * c1[i] + t * c2[i];
      s[2] = t;  // the assignment after the call: what it returns, not clamped
      return s;
    });
  }
}

TEST(HyperFunAttributes, ScalarToolbox) {
  // hfA_Clamp(f, a, b), hfA_Step(f, a), hfA_SmoothStep(f, a, b), and hfA_Pulse(f, p, q), which
  // HyperFun's code makes 1 for q <= f <= p (its third argument is the lower bound).
  expectAttributes(model("s[1] = hfA_Clamp(x[1], -0.5, 1);\ns[2] = hfA_Step(x[2], 0.3) + hfA_Pulse(x[3], 1, -1);\n"
                         "s[3] = hfA_SmoothStep(x[1], -1, 2);"),
                   [](double x, double y, double z) {
                     const double clamp = x < -0.5 ? -0.5 : x > 1 ? 1 : x;
                     const double step = y < 0.3 ? 0 : 1;
                     const double pulse = z < -1 || z > 1 ? 0 : 1;
                     const double t = (x + 1) / 3;
                     const double smooth = x > 2 ? 1 : x < -1 ? 0 : t * t * (3 - 2 * t);
                     return std::vector<double>{clamp, step + pulse, smooth};
                   },
                   [](double, double y, double z) {
                     return std::fabs(y - 0.3) < 1e-6 || std::fabs(std::fabs(z) - 1) < 1e-6;
                   });
  // hfA_Wave(v, c1, c2, freq): (1 + sin(freq v))/2 onto [min, max] of c1, c2, either order.
  expectAttributes(model("s[1] = hfA_Wave(x[1], 0.2, 0.9, 4);\ns[2] = hfA_Wave(x[2], 0.9, 0.2, 4);\n"
                         "s[3] = hfA_Floor(2.7) + hfA_Modulo(-7, 3);"),
                   [](double x, double y, double) {
                     const double wx = (1 + std::sin(4 * x)) / 2, wy = (1 + std::sin(4 * y)) / 2;
                     return std::vector<double>{0.2 + wx * 0.7, 0.2 + wy * 0.7, 2 + 2};
                   });
}

TEST(HyperFunAttributes, UnionTakesEachSolidsColourAndCombinesWhereBothApply) {
  // hfA_Union(f1, f2, s, s1, s2, op) returns f1 | f2; where that is > -1e-6: s1 where only f1 >= 0,
  // s2 where only f2 >= 0, op's combination elsewhere.
  for (int op = 0; op <= 5; ++op) {
    SCOPED_TRACE(op);
    const std::string body = "array c1[3], c2[3];\nc1 = [1, 0, 0];\nc2 = [0.2, 0.6, 1];\n"
                             "u = hfA_Union(x[1], x[2], s, c1, c2, " + std::to_string(op) + ");\ns[3] = s[3] + u;";
    expectAttributes(model(body), [op](double f1, double f2, double) {
      const double c1[3] = {1, 0, 0}, c2[3] = {0.2, 0.6, 1};
      const double u = f1 + f2 + std::sqrt(f1 * f1 + f2 * f2);
      std::vector<double> s(3, 0.0);
      if (u > -1e-6)
        for (int i = 0; i < 3; ++i) {
          if (f1 >= 0 && f2 < 0) s[i] = c1[i];
          else if (f2 >= 0 && f1 < 0) s[i] = c2[i];
          else if (op == 0) s[i] = c1[i];
          else if (op == 1) s[i] = c2[i];
          else if (op == 2) s[i] = c1[i] + c2[i];
          else if (op == 3) s[i] = std::min(c1[i], c2[i]);
          else if (op == 4) s[i] = std::max(c1[i], c2[i]);
        }
      s[2] += u;
      return s;
    }, [](double x, double y, double) { return std::fabs(x) < 1e-6 || std::fabs(y) < 1e-6; });
  }
}

TEST(HyperFunAttributes, MisuseIsReportedWhereItIs) {
  expectHas(compileError(model("s[4] = 1;")), "m.hf:2:3: error: index 4 is out of range for 's' (1 to 3)");
  expectHas(compileError(model("d = hfA_SetColor(x[1], s, 1, 0);")),
            "m.hf:2:5: error: 'hfA_SetColor' takes 5 arguments (f, s, r, g, b), found 4");
  expectHas(compileError("my_model(x[3], a[1], s[2]) {\n d = hfA_SetColor(x[1], s, 1, 0, 0);\n my_model = 1;\n}\n"),
            "m.hf:2:25: error: 's' (argument 2 of 'hfA_SetColor') must be an array of at least 3 items; 's' has 2");
  expectHas(compileError(model("d = hfA_SetColor(x[1], 1, 1, 0, 0);")),
            "m.hf:2:24: error: argument 2 of 'hfA_SetColor' must be the name of an array");
  expectHas(compileError(model("array c[2];\nc = [1, 2];\nd = hfA_Lerp(s, c, s, x[1], 0, 1);")),
            "m.hf:4:17: error: 's1' (argument 2 of 'hfA_Lerp') must be an array of 3 items; 'c' has 2");
  expectHas(compileError(model("d = hfA_Union(x[1], x[2], s, s, s, x[3]);")),
            "m.hf:2:36: error: 'op' (argument 6 of 'hfA_Union') depends on the point x");
}

}  // namespace
}  // namespace pf::field
