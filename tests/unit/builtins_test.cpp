// Built-in functions: maths (componentwise over vectors and colours), vector operations and
// noise, each checked lane by lane against the same formula evaluated here in C++.
#include <gtest/gtest.h>

#include <cmath>

#include "compile_helpers.h"
#include "compiler/perlin_noise.h"

using namespace pf;
using namespace pf::test;

namespace {
float laneX(int i) { return static_cast<float>(i % 8) + 0.5f; }
float laneY(int i) { return static_cast<float>(i / 8) + 0.5f; }

// Compiles `Z = <expr>;` in a primitive and returns the depth written by each lane.
std::vector<float> evalPerLane(const std::string& decls, const std::string& expr) {
  auto c = compile("primitive p(inout varying float Z) {\n" + decls + "\n  Z = " + expr + ";\n}\n");
  EXPECT_TRUE(c.ok) << c.diagnostics;
  if (!c.ok) return std::vector<float>(64, 0.0f);
  return runBlock(*c.find("p"), {}, {}, 0, true, 1e9f).depth;
}

void expectPerLane(const std::string& decls, const std::string& expr, float (*ref)(float, float), float tol = 1e-6f) {
  std::vector<float> got = evalPerLane(decls, expr);
  for (int i = 0; i < 64; ++i) {
    float want = ref(laneX(i), laneY(i));
    EXPECT_NEAR(got[i], want, tol * std::max(1.0f, std::fabs(want))) << expr << " at lane " << i;
  }
}
}  // namespace

TEST(Builtins, ScalarMaths) {
  expectPerLane("", "sin(X) + cos(Y) * tan(X / 20.0)",
                [](float x, float y) { return std::sin(x) + std::cos(y) * std::tan(x / 20.0f); });
  expectPerLane("", "asin(X / 9.0) + acos(Y / 9.0) + atan(X - Y) + atan2(Y - 4.0, X - 4.0)",
                [](float x, float y) { return std::asin(x / 9.0f) + std::acos(y / 9.0f) + std::atan(x - y) + std::atan2(y - 4.0f, x - 4.0f); });
  expectPerLane("", "pow(X, 1.5) + exp(Y / 4.0) + log(X * Y)",
                [](float x, float y) { return std::pow(x, 1.5f) + std::exp(y / 4.0f) + std::log(x * y); });
  expectPerLane("", "fract(X * 0.3) + mod(Y, 2.5) + mod(-X, 3.0)",
                [](float x, float y) {
                  return (x * 0.3f - std::floor(x * 0.3f)) + (y - 2.5f * std::floor(y / 2.5f)) + (-x - 3.0f * std::floor(-x / 3.0f));
                });
  expectPerLane("", "step(4.0, X) * 10.0 + smoothstep(2.0, 6.0, Y) + mix(1.0, 5.0, X / 8.0) + clamp(Y - 3.0, 0.0, 2.0)",
                [](float x, float y) {
                  float t = std::fmin(std::fmax((y - 2.0f) / 4.0f, 0.0f), 1.0f);
                  return (x < 4.0f ? 0.0f : 10.0f) + t * t * (3.0f - 2.0f * t) + (1.0f + 4.0f * (x / 8.0f)) +
                         std::fmin(std::fmax(y - 3.0f, 0.0f), 2.0f);
                });
}

TEST(Builtins, ComponentwiseOverVectorsAndColours) {
  expectPerLane("  color c = mix(color(1.0, 0.0, 0.5), color(0.0, 1.0, 0.5, 0.0), X / 8.0);",
                "c.r * 1000.0 + c.g * 100.0 + c.b * 10.0 + c.a",
                [](float x, float) {
                  float t = x / 8.0f;
                  return (1.0f - t) * 1000.0f + t * 100.0f + 0.5f * 10.0f + (1.0f - t);
                });
  expectPerLane("  vector v = clamp(vector(X - 4.0, Y - 4.0, X * Y), -1.0, 2.0);",
                "v.x + v.y * 10.0 + v.z * 100.0",
                [](float x, float y) {
                  auto cl = [](float a) { return std::fmin(std::fmax(a, -1.0f), 2.0f); };
                  return cl(x - 4.0f) + cl(y - 4.0f) * 10.0f + cl(x * y) * 100.0f;
                });
}

// A point plus or minus a vector (or normal) is the moved point; w stays the point's.
TEST(Builtins, PointsMoveByVectors) {
  expectPerLane("  point q = point(X, Y, 1.0, 2.0) + vector(1.0, Y, 3.0) - normal(0.5, 0.0, X);\n"
                "  point r = vector(X, 0.0, 0.0) + point(0.0, 1.0, 0.0);",
                "q.x + q.y * 10.0 + q.z * 100.0 + q.w * 1000.0 + r.x * 10000.0 + r.w * 100000.0",
                [](float x, float y) {
                  return (x + 0.5f) + (2 * y) * 10.0f + (4.0f - x) * 100.0f + 2000.0f + x * 10000.0f + 100000.0f;
                },
                1e-6f);
}

TEST(Builtins, VectorOperations) {
  expectPerLane("  vector a = vector(X, Y, 1.0); vector b = vector(2.0, -1.0, Y);",
                "dot(a, b) + length(cross(a, b)) + distance(point(X, Y, 0.0), point(0.0, 0.0, 0.0))",
                [](float x, float y) {
                  float cx = y * y - 1.0f * -1.0f, cy = 1.0f * 2.0f - x * y, cz = x * -1.0f - y * 2.0f;
                  return (2.0f * x - y + y) + std::sqrt(cx * cx + cy * cy + cz * cz) + std::sqrt(x * x + y * y);
                },
                1e-5f);
  expectPerLane("  vector n = normalize(vector(X, Y, 2.0)); vector r = reflect(vector(1.0, -1.0, 0.0), n);",
                "n.x * 100.0 + r.y",
                [](float x, float y) {
                  float l = std::sqrt(x * x + y * y + 4.0f), nx = x / l, ny = y / l;
                  float d = 2.0f * (nx * 1.0f + ny * -1.0f);
                  return nx * 100.0f + (-1.0f - d * ny);
                },
                1e-5f);
  // Refraction through a surface facing up: Snell's law; beyond the critical angle, 0.
  expectPerLane("  vector i = normalize(vector(X - 4.0, -1.0, 0.0)); vector t = refract(i, vector(0.0, 1.0, 0.0), 1.5);",
                "t.x * 10.0 + t.y",
                [](float x, float) {
                  float ix = x - 4.0f, iy = -1.0f, l = std::sqrt(ix * ix + 1.0f);
                  ix /= l;
                  iy /= l;
                  float ni = iy, k = 1.0f - 1.5f * 1.5f * (1.0f - ni * ni);
                  if (k < 0.0f) return 0.0f;
                  float m = 1.5f * ni + std::sqrt(k);
                  return (1.5f * ix) * 10.0f + (1.5f * iy - m);
                },
                1e-5f);
  expectPerLane("", "faceforward(vector(0.0, 0.0, 1.0), vector(X - 4.0, 0.0, -1.0), vector(1.0, 0.0, 0.0)).z",
                [](float x, float) { return (x - 4.0f) < 0.0f ? 1.0f : -1.0f; });
}

TEST(Builtins, NoiseIsImprovedPerlinNoise) {
  // The language's noise is the reference implementation's, lane by lane...
  expectPerLane("", "snoise(point(X * 0.37, Y * 0.41, 1.7)) * 100.0 + noise(X * 0.9)",
                [](float x, float y) {
                  return perlinNoise(x * 0.37f, y * 0.41f, 1.7f) * 100.0f + (perlinNoise(x * 0.9f, 0.0f, 0.0f) * 0.5f + 0.5f);
                });
  // ...and that is improved Perlin noise: zero at lattice points, bounded, smooth, and not constant.
  float lo = 1e9f, hi = -1e9f;
  for (int i = 0; i < 20000; ++i) {
    float x = 0.013f * i, y = 0.029f * i - 7.0f, z = 0.0071f * i + 3.0f;
    float v = perlinNoise(x, y, z);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    EXPECT_LE(std::fabs(v - perlinNoise(x + 1e-3f, y, z)), 0.01f) << "continuity at " << x;
  }
  EXPECT_LT(lo, -0.4f);
  EXPECT_GT(hi, 0.4f);
  EXPECT_LE(hi, 1.05f);
  EXPECT_GE(lo, -1.05f);
  for (int i = -5; i <= 5; ++i) EXPECT_FLOAT_EQ(perlinNoise(i, 2.0f * i, -3.0f * i), 0.0f);
  EXPECT_FLOAT_EQ(perlinNoise(NAN, 0.0f, 0.0f), 0.0f);
}

TEST(Builtins, Errors) {
  auto c = compile(
      "primitive p(inout varying float Z) {\n"
      "  float a = mix(vector(1.0), color(1.0), 0.5).x;\n"
      "  float b = dot(color(1.0), vector(1.0));\n"
      "  float d = sin(1.0, 2.0);\n"
      "  float e = refract(vector(1.0), vector(1.0), vector(1.0)).x;\n"
      "}\n");
  ASSERT_FALSE(c.ok);
  EXPECT_NE(c.diagnostics.find("2:30: error: mix() takes floats, or vectors with floats, not color"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("3:17: error: dot() takes a point, vector or normal here, not color"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("4:13: error: sin() takes 1 argument, not 2"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("refract()'s third argument is the ratio of refractive indices"), std::string::npos) << c.diagnostics;
}

TEST(Builtins, CrossSignIsExactWhereFloatArithmeticIsNot) {
  // a*d - b*c with a = d = 1 + 2^-23, b = 1, c = 1 + 2^-22: exactly 2^-46 > 0, but in float
  // both products round to 1 + 2^-22 and the difference is 0. Uniform (setup) and per pixel.
  const std::string a = "1.00000011920928955078125", c = "1.0000002384185791015625";
  std::vector<float> got = evalPerLane("  float k = X - X;",
                                       "cross_sign(" + a + ", 1.0, " + c + ", " + a + ") * 10.0 + "
                                       "cross_sign(" + a + " + k, 1.0, " + c + ", " + a + ") + "
                                       "(" + a + " * " + a + " - 1.0 * " + c + ") * 100.0");
  for (int i = 0; i < 64; ++i) EXPECT_FLOAT_EQ(got[i], 11.0f) << "lane " << i;  // float difference: 0
}

TEST(Builtins, StandardLibraryFbmAndTurbulence) {
  // Written in the language (compiler/stdlib.pfl); checked against the same sums in C++.
  std::vector<float> got = evalPerLane("  point q = point(X * 0.21, Y * 0.17, 0.5);",
                                       "fbm(q, 4) * 100.0 + turbulence(q, 3)");
  for (int i = 0; i < 64; ++i) {
    float qx = laneX(i) * 0.21f, qy = laneY(i) * 0.17f, qz = 0.5f;
    float f = 0.0f, t = 0.0f, amp = 0.5f, freq = 1.0f;
    for (int k = 0; k < 4; ++k) {
      f += amp * perlinNoise(qx * freq, qy * freq, qz * freq);
      if (k < 3) t += amp * std::fabs(perlinNoise(qx * freq, qy * freq, qz * freq));
      freq *= 2.0f;
      amp *= 0.5f;
    }
    EXPECT_NEAR(got[i], f * 2.0f * 100.0f + t, 1e-4f) << "lane " << i;
  }
  auto c = compile("float fbm(point p, int n) { return 0.0; }\nprimitive p() { }\n");
  ASSERT_FALSE(c.ok);
  EXPECT_NE(c.diagnostics.find("test.pfl:1:1: error: 'fbm' is a function of the standard library"), std::string::npos)
      << c.diagnostics;
}
