// A HyperFun model's procedural colour (its s array; seed 000, "Shading") through the API: the
// implicit primitive's colour bound to the `field_attributes` interpolator takes the attributes
// at each hit point -- checked per pixel against the formulas evaluated in double at the point
// the depth buffer gives, unlit and lit (GL_COLOR_MATERIAL, one directional light, against the
// sphere's analytic normal) -- and the same interpolator colours a GL quad by the field's
// attributes at its surface points (a solid texture). Images are byte-identical for any thread
// count and with native code or the interpreter.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "compiler/native/native_cache.h"
#include "field/perlin_reference.h"
#include "frame_capture.h"

namespace {

constexpr int kN = 64;
constexpr double kRadius = 0.9;

// A ball of radius 0.9 (hfSphere) coloured by three smooth functions of the point.
constexpr const char* kColouredBall =
    "my_model(x[3], a[1], s[3]) {\n"
    "  array c[3];\n"
    "  c = [0, 0, 0];\n"
    "  s[1] = 0.5 + 0.5*sin(4*x[1]);\n"
    "  s[2] = hfA_Wave(x[2], 0.1, 0.9, 5);\n"
    "  s[3] = hfA_SmoothStep(x[3] + x[1], -1.2, 1.2);\n"
    "  my_model = hfSphere(x, c, 0.9);\n"
    "}\n";

// The formulas of kColouredBall, in double.
void colourAt(double x, double y, double z, double out[3]) {
  out[0] = 0.5 + 0.5 * std::sin(4 * x);
  out[1] = 0.1 + (1 + std::sin(5 * y)) / 2 * 0.8;
  const double v = z + x, t = (v + 1.2) / 2.4;
  out[2] = v > 1.2 ? 1 : v < -1.2 ? 0 : t * t * (3 - 2 * t);
}
double clamp01(double v) { return std::min(1.0, std::max(0.0, v)); }

using Image = pf::test::CapturedFrame;

// What the tests draw: the ball (the implicit primitive over [-1, 1]^3, `method`), optionally
// lit, and optionally a GL quad in the plane z = -0.95 coloured by the same interpolator with
// `quad_field` as the field. Orthographic: x and y of the pixel centre, z = 1 - 2 depth.
Image draw(int threads, int native, bool lit, float method, bool quad, float quad_field = -1.0f,
           const char* model = kColouredBall) {
  pf::test::FrameCapture capture(kN, kN, threads, native);
  const GLuint field = pfglCompileFieldEXT(GL_FIELD_HYPERFUN_EXT, "ball.hf", model, 0.0f);
  EXPECT_NE(field, 0u);
  pf::test::viewUnitBoxFromAbove();
  if (lit) {  // (a directional light: the modelview's translation leaves it looking down -z)
    const GLfloat dir[4] = {0, 0, 1, 0}, white[4] = {1, 1, 1, 1}, none[4] = {0, 0, 0, 1};
    pfglEnable(GL_LIGHTING);
    pfglEnable(GL_LIGHT0);
    pfglLightfv(GL_LIGHT0, GL_POSITION, dir);
    pfglLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    pfglLightModelfv(GL_LIGHT_MODEL_AMBIENT, none);
    pfglEnable(GL_COLOR_MATERIAL);
  }
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  const GLuint colour = pfglGetParamNameEXT("color"), attributes = pfglGetInterpolatorEXT("field_attributes");
  EXPECT_NE(attributes, 0u);
  const GLenum implicit = pfglGetPrimitiveEXT("implicit");
  pfglMaterialInterpEXT(colour, implicit, attributes);
  const GLuint f = pfglGetParamNameEXT("field");
  pfglBegin(implicit);
  pfglRastParamfEXT(f, static_cast<float>(field));
  pfglRastParam3fEXT(pfglGetParamNameEXT("box_min"), -1, -1, -1);
  pfglRastParam3fEXT(pfglGetParamNameEXT("box_max"), 1, 1, 1);
  pfglRastParamfEXT(pfglGetParamNameEXT("method"), method);
  pfglRastParamfEXT(pfglGetParamNameEXT("steps"), 0);
  pfglSequencePointEXT();
  pfglEnd();
  if (quad) {
    pfglMaterialInterpEXT(colour, GL_QUADS, attributes);
    pfglRastParamfEXT(f, quad_field < 0 ? static_cast<float>(field) : quad_field);
    pfglNormal3f(0, 0, 1);
    pfglBegin(GL_QUADS);
    pfglVertex3f(-1, -1, -0.95f);
    pfglVertex3f(1, -1, -0.95f);
    pfglVertex3f(1, 1, -0.95f);
    pfglVertex3f(-1, 1, -0.95f);
    pfglEnd();
  }
  return capture.finish();
}

// Each drawn pixel's colour against the formulas at the point its depth gives (times the
// diffuse factor n.z of the sphere's normal there when lit), within 1.5/255. Returns the
// pixels checked. `formulas` (kColouredBall's by default) gives the colour at a point, or false
// where the test skips it (beside a step of the pattern).
using Formulas = bool (*)(double, double, double, double[3]);
bool colouredBall(double x, double y, double z, double out[3]) {
  colourAt(x, y, z, out);
  return true;
}
int expectColoursMatch(const Image& img, bool lit, bool ball_only, Formulas formulas = colouredBall) {
  int checked = 0;
  for (int py = 0; py < kN; ++py)
    for (int px = 0; px < kN; ++px) {
      const size_t i = static_cast<size_t>(py) * kN + px;
      if (!(img.depth[i] < 1.0f)) continue;
      const double x = (px + 0.5) / kN * 2 - 1, y = (py + 0.5) / kN * 2 - 1, z = 1 - 2.0 * img.depth[i];
      const bool on_ball = std::fabs(std::sqrt(x * x + y * y + z * z) - kRadius) < 1e-3;
      if (ball_only && !on_ball) continue;
      double c[3];
      if (!formulas(x, y, z, c)) continue;
      const double diffuse = lit ? std::max(0.0, z / kRadius) : 1.0;
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(img.rgba[i * 4 + static_cast<size_t>(k)] / 255.0, clamp01(c[k] * diffuse), 1.5 / 255)
            << "pixel " << px << ", " << py << " component " << k << (lit ? " (lit)" : "");
      ++checked;
    }
  return checked;
}

TEST(ImplicitAttributes, TheHitPointsColourIsTheModelsFormula) {
  for (float method : {0.0f, 2.0f, 3.0f}) {
    SCOPED_TRACE(method);
    const Image img = draw(2, 1, false, method, false);
    EXPECT_GT(expectColoursMatch(img, false, true), 1500);
  }
}

// A checkerboard of orange blocks and gaps whose colour is a hue ramp along x (HSV to RGB,
// hues from -90 to 270 so the wrap is crossed): the tape's floor at every hit point.
constexpr const char* kCheckeredBall =
    "my_model(x[3], a[1], s[3]) {\n"
    "  array c[3], bs[3], gp[3], cb[3], cg[3], hsv[3];\n"
    "  c = [0, 0, 0];\n  bs = [0.25, 0.25, 0.25];\n  gp = [0.125, 0.125, 0.125];\n  cb = [1, 0.5, 0];\n  cg = [0, 0, 0];\n"
    "  hsv[1] = 180*x[1] + 90;\n  hsv[2] = 0.8;\n  hsv[3] = 0.9;\n"
    "  d = hfA_HSVToRGB(hsv, cg);\n"
    "  d = hfA_CheckerBoard(x, bs, gp, s, cb, cg);\n"
    "  my_model = hfSphere(x, c, 0.9);\n"
    "}\n";

bool checkeredBall(double x, double y, double z, double out[3]) {
  const double p[3] = {x, y, z};
  bool inside = true;
  for (double v : p) {
    const double r = v - 0.375 * std::floor(v / 0.375);
    if (r < 5e-3 || std::fabs(r - 0.25) < 5e-3 || 0.375 - r < 5e-3) return false;  // beside a step
    inside = inside && r < 0.25;
  }
  if (inside) {
    out[0] = 1, out[1] = 0.5, out[2] = 0;
    return true;
  }
  double h = 180 * x + 90;
  while (h < 0) h += 360;
  while (h > 360) h -= 360;
  const double ramp[3] = {h < 120 ? (120 - h) / 60 : h < 240 ? 0 : (h - 240) / 60,
                          h < 120 ? h / 60 : h < 240 ? (240 - h) / 60 : 0,
                          h < 120 ? 0 : h < 240 ? (h - 120) / 60 : (360 - h) / 60};
  for (int k = 0; k < 3; ++k) out[k] = (1 - 0.8 + 0.8 * std::min(ramp[k], 1.0)) * 0.9;
  return true;
}

TEST(ImplicitAttributes, APatternWithFloorIsColouredPerPixel) {
  for (float method : {0.0f, 3.0f}) {
    SCOPED_TRACE(method);
    const Image img = draw(2, 1, false, method, false, -1.0f, kCheckeredBall);
    EXPECT_GT(expectColoursMatch(img, false, true, checkeredBall), 1000);
  }
}

// HyperFun's Perlin noise and turbulence (the tape's table look-ups) at every hit point.
constexpr const char* kNoisyBall =
    "my_model(x[3], a[1], s[3]) {\n"
    "  array c[3], y[3];\n"
    "  c = [0, 0, 0];\n  y[1] = 4*x[1];\n  y[2] = 4*x[2];\n  y[3] = 4*x[3];\n"
    "  s[1] = 0.5 + 0.5*hfA_NoiseP(y);\n"
    "  s[2] = 0.6*hfA_Turbulence(x, 8);\n"
    "  s[3] = 0.3;\n"
    "  my_model = hfSphere(x, c, 0.9);\n"
    "}\n";

bool noisyBall(double x, double y, double z, double out[3]) {
  const double p[3] = {x, y, z}, q[3] = {4 * x, 4 * y, 4 * z};
  out[0] = 0.5 + 0.5 * pf::field::testing::noise3(q);
  out[1] = 0.6 * pf::field::testing::turbulence(p, 8);
  out[2] = 0.3;
  return true;
}

TEST(ImplicitAttributes, PerlinNoiseIsColouredPerPixel) {
  const Image img = draw(2, 1, false, 0.0f, false, -1.0f, kNoisyBall);
  EXPECT_GT(expectColoursMatch(img, false, true, noisyBall), 1500);
}

TEST(ImplicitAttributes, LitThroughColorMaterial) {
  const Image img = draw(2, 1, true, 0.0f, false);
  EXPECT_GT(expectColoursMatch(img, true, true), 1500);
}

TEST(ImplicitAttributes, TheInterpolatorColoursOtherPrimitivesAsASolidTexture) {
  const Image img = draw(2, 1, false, 0.0f, true);
  int quad = 0;
  for (int py = 0; py < kN; ++py)
    for (int px = 0; px < kN; ++px) {
      const size_t i = static_cast<size_t>(py) * kN + px;
      const double x = (px + 0.5) / kN * 2 - 1, y = (py + 0.5) / kN * 2 - 1;
      if (x * x + y * y < 0.95 * 0.95) continue;  // the ball in front
      ASSERT_LT(img.depth[i], 1.0f);
      quad += 1;
    }
  EXPECT_GT(quad, 500);
  EXPECT_GT(expectColoursMatch(img, false, false), 3000);  // ball and quad alike
  // A field id naming no field: every component 1.
  const Image white = draw(2, 1, false, 0.0f, true, 99.0f);
  const size_t corner = 0;
  for (int k = 0; k < 3; ++k) EXPECT_EQ(white.rgba[corner * 4 + static_cast<size_t>(k)], 255);
}

TEST(ImplicitAttributes, ByteIdenticalForAnyThreadCountAndOnTheInterpreter) {
  const uint64_t saved = pf::NativeProgramCache::instance().threshold();
  pf::NativeProgramCache::instance().setThreshold(0);
  const Image base = draw(1, 0, true, 0.0f, true);
  for (int threads : {1, 3})
    for (int native : {0, 1}) {
      const Image other = draw(threads, native, true, 0.0f, true);
      EXPECT_TRUE(base.rgba == other.rgba) << threads << " threads, native " << native;
      EXPECT_TRUE(base.depth == other.depth) << threads << " threads, native " << native;
    }
  pf::NativeProgramCache::instance().setThreshold(saved);
}

}  // namespace
