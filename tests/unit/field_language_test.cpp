// field_hit() and field_gradient() in the language: typing and uniformity errors, and a block
// run of each method on a sphere field against the analytic hit -- in both execution modes
// (runBlock checks the SIMD executor against the scalar reference interpreter lane by lane).
#include <gtest/gtest.h>

#include <cmath>

#include "compile_helpers.h"
#include "compiler/field/field_tape.h"

namespace pf::test {
namespace {

// f = 0.64 - x^2 - y^2 - z^2: a sphere of radius 0.8 (Lipschitz bound 2 |p| <= 2 sqrt 3).
field::FieldTable sphereTable() {
  field::FieldTapeBuilder b;
  uint32_t r2 = b.binary(field::FieldOp::Add, b.unary(field::FieldOp::Square, b.x()), b.unary(field::FieldOp::Square, b.y()));
  r2 = b.binary(field::FieldOp::Add, r2, b.unary(field::FieldOp::Square, b.z()));
  field::FieldTable table;
  table.push_back(std::make_unique<const field::ImplicitField>(
      "sphere", b.finish(b.binary(field::FieldOp::Sub, b.constant(0.64f), r2)), 3.5f));
  return table;
}

// The probe writes t as depth (runBlock's state maps the 8x8 block to [-1, 1]^2 with identity
// matrices: pixel rays run from z = -1 at t = 0 to z = 1 at t = 1).
constexpr const char* kProbe = R"(
primitive probe(float field[1]; float method[1]; float param[1]; varying float X, Y; inout varying float Z) {
    float t = field_hit(field[0], vector(-1.0), vector(1.0), method[0], param[0]);
    if (!(t <= 1)) return;
    Z = t;
}
primitive gradient_probe(float field[1]; float fd[1]; varying float X, Y; inout varying float Z) {
    vector p = vector((X - 4) / 4, (Y - 4) / 4, 0.25);
    vector g = fd[0] > 0 ? field_gradient_fd(field[0], p) : field_gradient(field[0], p);
    Z = g.x + 10 * g.y;
}
)";

TEST(FieldLanguage, FieldHitFindsTheSphereByEveryMethodInBothModes) {
  Compiled c = compile(kProbe);
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const field::FieldTable fields = sphereTable();
  for (float method : {0.0f, 1.0f, 2.0f, 3.0f, 4.0f}) {
    SCOPED_TRACE(method);
    BlockRun r = runBlock(*c.find("probe"), {1.0f, method, method == 3.0f ? 200.0f : 0.0f}, {}, 0, true, 1.0f,
                          InterpKind::PerspectiveLinear, 65536, -1, &fields);
    int hits = 0;
    for (int i = 0; i < 64; ++i) {
      const double x = ((i % 8) + 0.5) / 4 - 1, y = ((i / 8) + 0.5) / 4 - 1;
      const double h = 0.64 - x * x - y * y;
      if (h <= 1e-3) {  // outside the disk, or too close to its rim for a sure verdict
        if (h < -1e-3) {
          EXPECT_FALSE(r.drawn(i % 8, i / 8)) << "lane " << i;
        }
        continue;
      }
      ASSERT_TRUE(r.drawn(i % 8, i / 8)) << "lane " << i;
      const double t = (1.0 - std::sqrt(h)) / 2.0;  // z = -sqrt(h) on the ray z = 2t - 1
      EXPECT_NEAR(r.depth[i], t, 1e-5) << "lane " << i;
      ++hits;
    }
    EXPECT_GT(hits, 20);
    EXPECT_EQ(r.counters.unknown_field_lanes, 0u);
  }
}

TEST(FieldLanguage, GradientsDerivedAndByDifferences) {
  Compiled c = compile(kProbe);
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const field::FieldTable fields = sphereTable();
  for (float fd : {0.0f, 1.0f}) {
    BlockRun r = runBlock(*c.find("gradient_probe"), {1.0f, fd}, {}, 0, true, 1.0f, InterpKind::PerspectiveLinear,
                          65536, -1, &fields);
    for (int i = 0; i < 64; ++i) {
      const double x = ((i % 8) + 0.5 - 4) / 4, y = ((i / 8) + 0.5 - 4) / 4;
      EXPECT_NEAR(r.depth[i], -2 * x + 10 * (-2 * y), fd > 0 ? 1e-3 : 1e-5) << "lane " << i;
    }
  }
}

TEST(FieldLanguage, UnknownFieldsDrawNothingAndAreCounted) {
  Compiled c = compile(kProbe);
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const field::FieldTable fields = sphereTable();
  BlockRun r = runBlock(*c.find("probe"), {7.0f, 0.0f, 0.0f}, {}, 0, false, 1.0f, InterpKind::PerspectiveLinear, 65536,
                        -1, &fields);
  for (int i = 0; i < 64; ++i) EXPECT_FALSE(r.drawn(i % 8, i / 8));
  EXPECT_EQ(r.counters.unknown_field_lanes, 64u);
}

TEST(FieldLanguage, ArgumentsAreCheckedAndMustBeUniform) {
  auto diag = [](const std::string& body) {
    Compiled c = compile("primitive p(float f[1]; varying float X, Y; inout varying float Z) {\n" + body + "\n}\n");
    EXPECT_FALSE(c.ok);
    return c.diagnostics;
  };
  EXPECT_NE(diag("    float t = field_hit(f[0], vector(X), vector(1.0), 0, 0);").find(
                "field_hit()'s box minimum must be uniform"),
            std::string::npos);
  EXPECT_NE(diag("    float t = field_hit(X, vector(0.0), vector(1.0), 0, 0);").find("field_hit()'s field must be uniform"),
            std::string::npos);
  EXPECT_NE(diag("    float t = field_hit(f[0], 1.0, vector(1.0), 0, 0);").find(
                "field_hit()'s box minimum is a point or vector, not float"),
            std::string::npos);
  EXPECT_NE(diag("    float t = field_hit(f[0], vector(0.0), vector(1.0), 0);").find("field_hit() takes 5 arguments, not 4"),
            std::string::npos);
  EXPECT_NE(diag("    vector g = field_gradient(f[0], 2.0);").find("field_gradient() takes a point, vector or normal"),
            std::string::npos);
  Compiled in_interpolator = compile("interpolator i(float f) { interpolator_return(field_hit(f, vector(0.0), vector(1.0), 0, 0)); }\n");
  EXPECT_FALSE(in_interpolator.ok);
  EXPECT_NE(in_interpolator.diagnostics.find("field_hit() is only available in a primitive"), std::string::npos)
      << in_interpolator.diagnostics;
}

}  // namespace
}  // namespace pf::test
