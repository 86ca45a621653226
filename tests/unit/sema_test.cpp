// Semantic analysis: names, types, and the uniform/varying rules with their explanations.
#include <gtest/gtest.h>

#include "compile_helpers.h"

using namespace pf;
using pf::test::compile;

TEST(Sema, UndefinedNameAtItsColumn) {
  auto c = compile("primitive p()\n{\n    float a = bogus + 1.0;\n}\n");
  ASSERT_FALSE(c.ok);
  EXPECT_NE(c.diagnostics.find("test.pfl:3:15: error: 'bogus' is not declared"), std::string::npos) << c.diagnostics;
}

TEST(Sema, UniformReceivingVaryingExplainsTheChain) {
  auto c = compile(
      "primitive p(inout varying float Z)\n"
      "{\n"
      "    float e = X * 2.0;\n"
      "    float f = e + 1.0;\n"
      "    uniform float u = f;\n"
      "}\n");
  ASSERT_FALSE(c.ok);
  EXPECT_NE(c.diagnostics.find("test.pfl:5:23: error: 'u' is declared uniform, but the value it receives here is varying"),
            std::string::npos) << c.diagnostics;
  // The chain: f -> e -> X.
  EXPECT_NE(c.diagnostics.find("depends on 'f'"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("the built-in X"), std::string::npos) << c.diagnostics;
}

TEST(Sema, AssignmentUnderVaryingControlMakesVarying) {
  auto c = compile(
      "primitive p(inout varying float Z)\n"
      "{\n"
      "    uniform float u = 1.0;\n"
      "    if (Y > 3.0) u = 2.0;\n"
      "}\n");
  ASSERT_FALSE(c.ok);
  EXPECT_NE(c.diagnostics.find("varying (line 4)"), std::string::npos) << c.diagnostics;
}

TEST(Sema, BoundMustBeUniform) {
  auto c = compile("primitive p() { bound(X, 0, 1, 1); }");
  ASSERT_FALSE(c.ok);
  EXPECT_NE(c.diagnostics.find("bound() needs a uniform value"), std::string::npos) << c.diagnostics;
}

TEST(Sema, DepthBoundIsAUniformStatementOfAPrimitive) {
  auto ok = compile(
      "primitive p(float z0[1]; varying float X; inout varying float Z)\n"
      "{\n"
      "    depth_bound(z0[0], z0[0] + 0.5);\n"
      "    if (!ztest(z0[0])) return;\n"
      "    Z = z0[0];\n"
      "}\n");
  ASSERT_TRUE(ok.ok) << ok.diagnostics;
  auto c = compile(
      "primitive p(varying float X; inout varying float Z)\n"
      "{\n"
      "    depth_bound(X, 1.0);\n"                // varying
      "    float a = depth_bound(0.0, 1.0);\n"    // a value
      "    depth_bound(0.0);\n"                   // arity
      "    if (X > 2.0) depth_bound(0.0, 1.0);\n" // under varying control
      "}\n"
      "interpolator i() { depth_bound(0.0, 1.0); interpolator_return(color(1.0)); }\n");
  ASSERT_FALSE(c.ok);
  EXPECT_NE(c.diagnostics.find("3:5: error: depth_bound() sets the depth bound of the whole instance, so it must be uniform"),
            std::string::npos)
      << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("4:15: error: depth_bound() is a statement"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("5:5: error: depth_bound() takes 2 arguments, not 1"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("6:18: error: depth_bound() sets"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("depth_bound() is only available in a primitive"), std::string::npos) << c.diagnostics;
  // A primitive that never tests depth: the bound would describe nothing, and culling by it
  // would drop pixels.
  auto untested = compile(
      "primitive p(varying float X; inout varying float Z)\n"
      "{\n"
      "    depth_bound(0.9, 0.95);\n"
      "    Z = 0.9;\n"
      "}\n");
  ASSERT_FALSE(untested.ok);
  EXPECT_NE(untested.diagnostics.find("3:5: error: depth_bound() describes the depths this primitive tests with "
                                      "ztest(), but it never calls ztest()"),
            std::string::npos)
      << untested.diagnostics;
}

TEST(Sema, TypeErrors) {
  auto c = compile(
      "primitive p(point v[3]; interpolator_data d[3])\n"
      "{\n"
      "    float a = v[0];\n"           // point into float
      "    bool b = 1.0 + true;\n"      // float + bool
      "    float c = v[0].q;\n"         // no component q
      "    float e = v[3].x;\n"         // out of range
      "    float f = sqrt(1, 2);\n"     // arity
      "    interpolator_data g = d[0] * d[1];\n"  // interp * interp
      "}\n");
  ASSERT_FALSE(c.ok);
  EXPECT_NE(c.diagnostics.find("3:15: error: cannot initialise 'a': expected float, found point"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("4:18: error: operator '+' cannot combine float and bool"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("5:20: error: a point has no component 'q'"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("6:17: error: index 3 is out of range [0, 2]"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("7:15: error: sqrt() takes 1 argument, not 2"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("8:32: error: operator '*' cannot combine"), std::string::npos) << c.diagnostics;
}

TEST(Sema, ParametersAreReadOnlyAndBuiltinsChecked) {
  auto c = compile("primitive p(float r; varying float X; inout varying float Z) { r = 2.0; X = 1.0; }");
  ASSERT_FALSE(c.ok);
  EXPECT_NE(c.diagnostics.find("parameter 'r' is read-only"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("'X' is read-only"), std::string::npos) << c.diagnostics;
}

TEST(Sema, InterpolatorReturnPlacement) {
  auto c = compile(
      "primitive p(interpolator_data d[1]) {\n"
      "  interpolator_return(d[0]);\n"
      "  interpolation { default: interpolator_return(d[0]); linear: interpolator_return; }\n"
      "}\n");
  ASSERT_FALSE(c.ok);
  EXPECT_NE(c.diagnostics.find("2:3: error: interpolator_return is only allowed inside"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("in the 'default:' branch use 'interpolator_return;'"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("belongs in the 'default:' branch"), std::string::npos) << c.diagnostics;
}

TEST(Sema, ShippedPrimitivesCompile) {
  auto read = [](const char* f) {
    std::string path = std::string(PF_SOURCE_DIR) + "/primitives/" + f;
    FILE* fp = std::fopen(path.c_str(), "rb");
    EXPECT_NE(fp, nullptr) << path;
    std::string text;
    if (!fp) return text;
    char buf[4096];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, fp)) > 0) text.append(buf, n);
    std::fclose(fp);
    return text;
  };
  // triangles.pfl draws unfilled polygons with lines.pfl's and points.pfl's primitives, which a
  // context compiles before it (in file-name order): one source here.
  for (const char* f : {"triangles.pfl", "screen_triangle.pfl"}) {
    const std::string text = std::string(f) == "triangles.pfl" ? read("lines.pfl") + read("points.pfl") + read(f) : read(f);
    auto c = compile(text, f);
    EXPECT_TRUE(c.ok) << c.diagnostics;
  }
}
