// The polynomial form along a ray against direct double evaluation of the field on the ray.
#include <gtest/gtest.h>

#include <random>

#include "compiler/field/fidget_reader.h"
#include "field/field_reference.h"
#include "raster/field/ray_polynomial.h"

namespace pf::field {
namespace {

FieldTape model(const std::string& name) {
  DiagnosticLog log;
  return *readFidgetModel(name, testing::readModelText(name), log);
}

TEST(RayPolynomial, TanglecubeIsAQuarticAlongEveryRay) {
  const FieldTape t = model("fidget/tanglecube.vm");
  EXPECT_EQ(fieldPolynomialDegree(t), 4);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int k = 0; k < 50; ++k) {
    const std::array<double, 3> o = {u(rng), u(rng), u(rng)}, d = {u(rng), u(rng), u(rng)};
    const auto p = rayPolynomial(t, o, d);
    ASSERT_TRUE(p);
    EXPECT_EQ(p->degree, 4);
    for (double s = -3.0; s <= 3.0; s += 0.25) {
      // The tape's constants are floats: the reference evaluates the same tape in double.
      const double want = testing::evaluateDouble(t, o[0] + s * d[0], o[1] + s * d[1], o[2] + s * d[2]);
      EXPECT_NEAR(p->evaluate(s), want, 1e-9 * std::max(1.0, std::fabs(want)));
    }
  }
}

TEST(RayPolynomial, DegreeDropsAlongAxisRaysAndNonPolynomialsHaveNone) {
  // A sphere 1 - x^2 - y^2 - z^2 along the z axis: a quadratic in t; x and y are constants.
  FieldTapeBuilder b;
  uint32_t r2 = b.binary(FieldOp::Add, b.unary(FieldOp::Square, b.x()), b.unary(FieldOp::Square, b.y()));
  r2 = b.binary(FieldOp::Add, r2, b.unary(FieldOp::Square, b.z()));
  const FieldTape sphere = b.finish(b.binary(FieldOp::Sub, b.constant(1.0f), r2));
  EXPECT_EQ(fieldPolynomialDegree(sphere), 2);
  const auto p = rayPolynomial(sphere, {0.5, 0.25, 3.0}, {0.0, 0.0, -1.0});
  ASSERT_TRUE(p);
  EXPECT_EQ(p->degree, 2);
  EXPECT_DOUBLE_EQ(p->c[2], -1.0);
  EXPECT_DOUBLE_EQ(p->c[1], 6.0);
  EXPECT_DOUBLE_EQ(p->c[0], 1.0 - 0.25 - 0.0625 - 9.0);

  const FieldTape quarter = model("fidget/quarter.vm");  // max of non-constants
  EXPECT_EQ(fieldPolynomialDegree(quarter), -1);
  EXPECT_FALSE(rayPolynomial(quarter, {0, 0, 1}, {0.3, 0.2, -1}));
  // Degree 6 is past what the analytic method solves.
  FieldTapeBuilder c;
  const uint32_t x3 = c.binary(FieldOp::Mul, c.unary(FieldOp::Square, c.x()), c.x());
  const FieldTape sextic = c.finish(c.unary(FieldOp::Square, x3));
  EXPECT_EQ(fieldPolynomialDegree(sextic), 6);
  EXPECT_FALSE(rayPolynomial(sextic, {0, 0, 0}, {1, 0, 0}));
}

}  // namespace
}  // namespace pf::field
