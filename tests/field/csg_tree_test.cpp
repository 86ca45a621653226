// CSG trees of polynomial leaves (raster/field/csg_tree.h): which fields decompose, and the first
// hit they give along rays against the dense double-precision reference march of the field's own
// tape (field_reference.h) -- for HyperFun's R-functions, min/max/negation, the torus's
// polynomial-plus-root form, fields written in the language, and the shipped cup model.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <fstream>
#include <random>
#include <sstream>

#include "compiler/field/field_unit.h"
#include "compiler/field/hyperfun_reader.h"
#include "field/cast_comparison.h"
#include "field/field_reference.h"
#include "raster/field/csg_tree.h"
#include "raster/field/implicit_field.h"

namespace pf::field {
namespace {

FieldTape hyperfun(const std::string& body) {
  DiagnosticLog log;
  auto tape = readHyperFunModel("t.hf", "my_model(x[3], a[1]) {\n" + body + "\n}\n", log, {}, "my_model");
  EXPECT_TRUE(tape) << log.format();
  return tape ? *tape : FieldTape{};
}

FieldTape language(const std::string& source) {
  DiagnosticLog log;
  auto tape = compileFieldUnit("t.pfl", source, "", {}, log);
  EXPECT_TRUE(tape) << log.format();
  return tape ? *tape : FieldTape{};
}

FieldTape cupModel() {
  std::ifstream in(std::string(PF_SOURCE_DIR) + "/scenes/models/cup.hf");
  std::stringstream ss;
  ss << in.rdbuf();
  DiagnosticLog log;
  auto tape = readHyperFunModel("cup.hf", ss.str(), log, {}, "my_model");
  EXPECT_TRUE(tape) << log.format();
  return tape ? *tape : FieldTape{};
}

const char* const kTwoBallsMinusRod =
    "array c[3], d[3]; c = [0.4, 0, 0]; d = [-0.4, 0.1, 0];\n"
    "my_model = (hfSphere(x, c, 0.7) | hfSphere(x, d, 0.6)) \\ hfCylinderX(x, c, 0.2);";

TEST(CsgTree, RecognisesSignPreservingForms) {
  const auto balls = csgTreeOf(hyperfun(kTwoBallsMinusRod));
  ASSERT_TRUE(balls);
  EXPECT_EQ(balls->leaf_count, 3u);
  const auto torus = csgTreeOf(hyperfun("array c[3]; c = [0, 0, 0]; my_model = hfTorusZ(x, c, 0.6, 0.25);"));
  ASSERT_TRUE(torus);
  EXPECT_EQ(torus->leaf_count, 2u);  // A and k^2 B - A^2
  const auto cup = csgTreeOf(cupModel());
  ASSERT_TRUE(cup);
  EXPECT_EQ(cup->leaf_count, 7u);  // outer (shared), two slab planes, inner, the cavity floor, the torus's two
  // Blends and exponentials change the surface, not only the sign: no tree.
  EXPECT_FALSE(csgTreeOf(hyperfun("array c[3], d[3]; c = [0.4, 0, 0]; d = [-0.4, 0, 0];\n"
                                  "my_model = hfBlendUni(hfSphere(x, c, 0.5), hfSphere(x, d, 0.5), 0.3, 1, 1);")));
  EXPECT_FALSE(csgTreeOf(hyperfun("my_model = exp(-x[1]*x[1]) - 0.5 + 0 * x[2];")));
  // One polynomial is the plain analytic case, not a tree.
  EXPECT_FALSE(csgTreeOf(hyperfun("array c[3]; c = [0, 0, 0]; my_model = hfSphere(x, c, 1);")));
  // `auto` takes the analytic method for the cup, the interval method for a blend.
  EXPECT_EQ(resolveMethod(ImplicitField("cup", cupModel()), RootMethod::Auto), RootMethod::Analytic);
}

// Random rays through [-1.2, 1.2]^3: the tree's first hit against the reference march.
void expectHitsMatch(const FieldTape& tape, double tolerance = 1e-7) {
  const auto tree = csgTreeOf(tape);
  ASSERT_TRUE(tree);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0, mismatches = 0;
  for (int k = 0; k < 400; ++k) {
    const std::array<double, 3> o = {u(rng) * 0.5, u(rng) * 0.5, 2.0};
    const std::array<double, 3> target = {u(rng) * 0.8, u(rng) * 0.8, -1.5};
    const std::array<double, 3> d = {target[0] - o[0], target[1] - o[1], target[2] - o[2]};
    const double entry = 0.0, exit = 1.0;
    bool solved = false;
    const auto got = tree->firstHit(o, d, entry, exit, solved);
    ASSERT_TRUE(solved);
    const double want = testing::referenceHit(tape, o, d, entry, exit, 20000);
    if (std::isinf(want) != !got.has_value()) {
      ++mismatches;  // a feature thinner than the reference's step, or a grazing ray
      continue;
    }
    if (!got) continue;
    ++hits;
    EXPECT_NEAR(*got, want, tolerance) << "ray " << k;
  }
  EXPECT_LE(mismatches, 2);
  EXPECT_GT(hits, 60);
}

// sqrt(B) with a B that can be negative: the field is NaN (outside) there, which no min/max of
// polynomials says -- no tree, so `auto` and `analytic` do not draw a floor where B < 0.
TEST(CsgTree, RootsOfPossiblyNegativeValuesAreNotLeaves) {
  const FieldTape cap = language("field float cap(point p) { return sqrt(1.0 - p.x * p.x - p.y * p.y) - p.z; }");
  EXPECT_FALSE(csgTreeOf(cap));
  EXPECT_NE(resolveMethod(ImplicitField("cap", cap), RootMethod::Auto), RootMethod::Analytic);
}

// A NaN leaf (a folded 0/0) is ignored by AND / OR, as the field's min and max ignore it.
TEST(CsgTree, NaNLeavesAreIgnoredAsTheFieldIgnoresThem) {
  FieldTapeBuilder b;
  const uint32_t x = b.x(), z = b.z();
  const uint32_t disk = b.binary(FieldOp::Sub, b.constant(1.0f),
                                 b.binary(FieldOp::Add, b.unary(FieldOp::Square, x), b.unary(FieldOp::Square, z)));
  const uint32_t slab = b.binary(FieldOp::Sub, b.constant(0.5f), b.unary(FieldOp::Square, z));
  const uint32_t nan = b.constant(std::numeric_limits<float>::quiet_NaN());
  const FieldTape t = b.finish(b.binary(FieldOp::Max, b.binary(FieldOp::Min, nan, disk), slab));
  expectHitsMatch(t);
}

TEST(CsgTree, RFunctionTreesHitWhereTheReferenceDoes) { expectHitsMatch(hyperfun(kTwoBallsMinusRod)); }

TEST(CsgTree, MinMaxAndNegationHitWhereTheReferenceDoes) {
  expectHitsMatch(language(R"(
field float f(point p) {
    float ball = 0.8 - (p.x * p.x + p.y * p.y + p.z * p.z);
    float slab = min(0.3 - p.y, p.y + 0.5);
    float hole = 0.09 - p.x * p.x - p.y * p.y;
    return min(max(ball, -0.5 - p.z), -min(hole, slab)) * 2.0;
}
)"));
}

TEST(CsgTree, TheTorusRootFormHitsWhereTheReferenceDoes) {
  // Tilted so that rays from +z meet both its sides; the leaves square the form, so the boundary
  // moves by k^2's float rounding at most.
  expectHitsMatch(language(R"(
field float ring(point p) { return hfTorusX(hfRotate3DY(p, 0.5), point(0.0, 0.0, 0.0), 0.6, 0.25); }
)"), 1e-6);
}

TEST(CsgTree, TheCupCastsAnalyticallyAsTheReference) {
  const ImplicitField cup("cup", cupModel());
  const Vec3d lo{-3.5, -2.5, -2.5}, hi{3.5, 2.5, 2.5};
  const Comparison c = compare(cup, perspectiveRays(48, 48, 9.0, lo, hi), 48, 48, RootMethod::Analytic, 0.0f, 6000);
  std::printf("cup, analytic by CSG leaves: %d rays, %d coverage mismatches, max depth error %.3g\n", c.judged,
              c.coverage_mismatches, c.max_depth_error);
  EXPECT_EQ(c.counters.analytic_fallbacks, 0u);
  EXPECT_LE(c.coverage_mismatches, 2);
  EXPECT_LT(c.max_depth_error, 1e-5);
}

}  // namespace
}  // namespace pf::field
