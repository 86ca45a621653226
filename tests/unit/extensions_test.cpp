// The run-time primitive extensions: compile a user primitive, read the log, draw it with
// glBegin, and the iteration cap reported as GL_TOO_MANY_ITERATIONS_EXT.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <string>
#include <vector>

namespace {

struct Ctx {
  PFcontext ctx;
  std::vector<unsigned char> px;
  explicit Ctx(int cap = 0) : px(16 * 16 * 4) {
    const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_ITERATION_CAP, cap, 0};
    ctx = pfCreateContextAttribs(attribs);
    EXPECT_NE(ctx, nullptr);
    pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, 16, 16);
    pfglMatrixMode(GL_PROJECTION);
    pfglOrtho(0, 16, 0, 16, -1, 1);
  }
  ~Ctx() {
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
    pfDestroyContext(ctx);
  }
};

// A user primitive fed by glVertex: covers the pixels left of the first vertex's x, and (with
// `runaway`) loops forever on the right half.
const char* kHalf =
    "primitive half(point vertex[1]; inout varying float Z) {\n"
    "  float edge = screen(vertex[0]).x;\n"
    "  if (X > edge) return;\n"
    "  Z = 0.25;\n"
    "}\n"
    "primitive spin(point vertex[1]; inout varying float Z) {\n"
    "  float v = 0.0;\n"
    "  while (X > 8.0) v = v + 1.0;\n"
    "  Z = 0.5;\n"
    "}\n";

}  // namespace

TEST(Extensions, CompileRegisterAndDraw) {
  Ctx c;
  GLuint m = pfglCompilePrimitivesEXT(kHalf);
  ASSERT_NE(m, 0u);
  GLenum half = pfglGetPrimitiveEXT("half");
  EXPECT_GE(half, static_cast<GLenum>(GL_FIRST_PRIMITIVE_MODE_EXT));
  EXPECT_EQ(pfglGetPrimitiveEXT("triangles"), static_cast<GLenum>(GL_TRIANGLES));
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  pfglBegin(half);
  pfglVertex3f(5.0f, 0.0f, 0.0f);
  pfglEnd();
  GLint w, h, b;
  void* d;
  ASSERT_TRUE(pfGetDepthBuffer(c.ctx, &w, &h, &b, &d));
  const float* depth = static_cast<const float*>(d);
  for (int x = 0; x < 16; ++x) EXPECT_FLOAT_EQ(depth[3 * 16 + x], x + 0.5f <= 5.0f ? 0.25f : 1.0f) << x;
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(Extensions, CompileErrorsThroughTheLog) {
  Ctx c;
  EXPECT_EQ(pfglCompilePrimitivesEXT("primitive p() {\n  float a = nope;\n}\n"), 0u);
  char log[512];
  GLsizei len = 0;
  pfglGetCompileLogEXT(0, sizeof log, &len, log);
  std::string text(log, static_cast<size_t>(len));
  EXPECT_NE(text.find(":2:13: error: 'nope' is not declared"), std::string::npos) << text;
  // Truncation and bad ids.
  pfglGetCompileLogEXT(0, 5, &len, log);
  EXPECT_EQ(len, 4);
  EXPECT_EQ(log[4], '\0');
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  pfglGetCompileLogEXT(99, sizeof log, &len, log);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(pfglCompilePrimitivesEXT(nullptr), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(pfglGetPrimitiveEXT("no_such_primitive"), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
}

TEST(Extensions, RunawayPrimitiveIsStoppedAndReported) {
  Ctx c(500);
  ASSERT_NE(pfglCompilePrimitivesEXT(kHalf), 0u);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  pfglBegin(pfglGetPrimitiveEXT("spin"));
  pfglVertex3f(0.0f, 0.0f, 0.0f);
  pfglEnd();
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_TOO_MANY_ITERATIONS_EXT));
  GLint w, h, b;
  void* d;
  ASSERT_TRUE(pfGetDepthBuffer(c.ctx, &w, &h, &b, &d));
  const float* depth = static_cast<const float*>(d);
  for (int x = 0; x < 16; ++x) EXPECT_FLOAT_EQ(depth[x], x < 8 ? 0.5f : 1.0f) << "pixel " << x;
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));  // reported once
}

TEST(Extensions, RecompilingReplacesButKeepsPendingDrawing) {
  Ctx c;
  ASSERT_NE(pfglCompilePrimitivesEXT(kHalf), 0u);
  GLenum half = pfglGetPrimitiveEXT("half");
  pfglClear(GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  pfglBegin(half);
  pfglVertex3f(5.0f, 0.0f, 0.0f);
  pfglEnd();
  // Same name, new program, same mode; the instance above still draws with the old one.
  ASSERT_NE(pfglCompilePrimitivesEXT("primitive half(point vertex[1]; inout varying float Z) { Z = 0.125; }"), 0u);
  EXPECT_EQ(pfglGetPrimitiveEXT("half"), half);
  GLint w, h, b;
  void* d;
  ASSERT_TRUE(pfGetDepthBuffer(c.ctx, &w, &h, &b, &d));
  EXPECT_FLOAT_EQ(static_cast<const float*>(d)[0], 0.25f);
  EXPECT_FLOAT_EQ(static_cast<const float*>(d)[15], 1.0f);
}

// A user primitive with a parameter-sized vertex array that calls the built-in `triangles`
// draws, through glBegin, exactly what GL_TRIANGLES draws with the same triangles listed.
TEST(Extensions, UserPrimitiveCallingTrianglesDrawsLikeGlTriangles) {
  const char* kUserFan =
      "primitive user_fan(int vertex_count; point vertex[]; interpolator_data interp_data[]) {\n"
      "  for (int i = 2; i < vertex_count; i += 1) {\n"
      "    point v[3];\n"
      "    interpolator_data d[3];\n"
      "    v[0] = vertex[0];      d[0] = interp_data[0];\n"
      "    v[1] = vertex[i - 1];  d[1] = interp_data[i - 1];\n"
      "    v[2] = vertex[i];      d[2] = interp_data[i];\n"
      "    triangles(v, d);\n"
      "  }\n"
      "}\n";
  const float xy[6][2] = {{8, 8}, {15, 3}, {15.5f, 12}, {9, 15.75f}, {1, 14}, {0.5f, 2}};
  auto draw = [&](GLenum mode, bool listed) {
    pfglClear(GL_COLOR_BUFFER_BIT);
    pfglBegin(mode);
    for (int i = 2; i < (listed ? 6 : 3); ++i)
      for (int k : {0, i - 1, i}) {
        if (!listed && k != 0) continue;
        pfglColor3f(xy[k][0] / 16, xy[k][1] / 16, 0.5f);
        pfglVertex3f(xy[k][0], xy[k][1], 0);
      }
    if (!listed)
      for (int k = 1; k < 6; ++k) {
        pfglColor3f(xy[k][0] / 16, xy[k][1] / 16, 0.5f);
        pfglVertex3f(xy[k][0], xy[k][1], 0);
      }
    pfglEnd();
    pfglFinish();
  };
  Ctx c;
  ASSERT_NE(pfglCompilePrimitivesEXT(kUserFan), 0u);
  draw(GL_TRIANGLES, true);
  std::vector<unsigned char> want = c.px;
  draw(pfglGetPrimitiveEXT("user_fan"), false);
  int drawn = 0;
  for (size_t i = 0; i < want.size(); i += 4) drawn += want[i + 2] != 0;
  EXPECT_GT(drawn, 100);
  EXPECT_EQ(c.px, want);
  draw(GL_TRIANGLE_FAN, false);
  EXPECT_EQ(c.px, want) << "the built-in GL_TRIANGLE_FAN";
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// Calls inside setup loops multiply; past the budget of instances one submission may make, the
// rest are dropped and reported like a runaway loop -- promptly, not after 2^32 instances.
TEST(Extensions, ExplodingPrimitiveCallsAreCutAndReported) {
  Ctx c;
  ASSERT_NE(pfglCompilePrimitivesEXT(
                "primitive dot(point vertex[1]; inout varying float Z) { bound(-9.0, -9.0, -8.0, -8.0); Z = 0.5; }\n"
                "primitive many(point vertex[1]) { for (int i = 0; i < 60000; i += 1) dot(vertex); }\n"
                "primitive more(point vertex[1]) { for (int i = 0; i < 60000; i += 1) many(vertex); }\n"),
            0u);
  pfglBegin(pfglGetPrimitiveEXT("more"));
  pfglVertex2f(0.5f, 0.5f);
  pfglEnd();
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_TOO_MANY_ITERATIONS_EXT));
}

namespace {

// A triangle strip of `n` vertices, all but the last three at one point (degenerate triangles),
// the last three a triangle over pixel (8, 7).
void degenerateStripThenATriangle(int n) {
  pfglBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < n - 3; ++i) pfglVertex2f(0.5f, 0.5f);
  pfglVertex2f(4, 4);
  pfglVertex2f(12, 4);
  pfglVertex2f(8, 12);
  pfglEnd();
}

}  // namespace

// The budget of calls scales with the iteration cap (32 calls an iteration): at a cap of 16,
// two levels of 15 calls each (240 instances) stay within its 512 and three (3,615) pass it, while
// no loop reaches the cap; a strip of more vertices than that is still drawn whole.
TEST(Extensions, TheCallBudgetIsThirtyTwoTimesTheIterationCap) {
  Ctx c(16);
  ASSERT_NE(pfglCompilePrimitivesEXT(
                "primitive dot(point vertex[1]; inout varying float Z) { bound(-9.0, -9.0, -8.0, -8.0); Z = 0.5; }\n"
                "primitive two(point vertex[1]) { for (int i = 0; i < 15; i += 1) dot(vertex); }\n"
                "primitive one(point vertex[1]) { for (int i = 0; i < 15; i += 1) two(vertex); }\n"
                "primitive zero(point vertex[1]) { for (int i = 0; i < 15; i += 1) one(vertex); }\n"),
            0u);
  for (const char* name : {"one", "zero"}) {
    SCOPED_TRACE(name);
    pfglBegin(pfglGetPrimitiveEXT(name));
    pfglVertex2f(0.5f, 0.5f);
    pfglEnd();
    pfglFinish();
    EXPECT_EQ(pfglGetError(), static_cast<GLenum>(std::string(name) == "one" ? GL_NO_ERROR : GL_TOO_MANY_ITERATIONS_EXT));
  }
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT);
  degenerateStripThenATriangle(32 * 16 + 103);
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_NE(c.px[(7 * 16 + 8) * 4 + 3], 0) << "the strip's last triangle is drawn";
}

// A loop over a parameter-sized array runs once per sequence point, whatever the cap: a strip
// longer than the iteration cap is drawn whole, without an error.
TEST(Extensions, LongStripsAreNoRunaway) {
  Ctx c(50);  // iteration cap 50
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < 200; ++i) pfglVertex2f(static_cast<float>(i) * 0.08f, i % 2 ? 16.0f : 0.0f);
  pfglEnd();
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_NE(c.px[(8 * 16 + 15) * 4 + 3], 0) << "the strip's far end (past 50 triangles) is drawn";
}

// Calls in proportion to the vertices are no runaway either: a strip, a fan and a polygon of
// more than 2^21 + 2 vertices (where calls of `triangles` once stopped, reported as a runaway
// loop) draw their last triangles. All but the last three vertices sit at one point.
TEST(Extensions, StripsFansAndPolygonsPast2To21VerticesAreDrawnWhole) {
  for (GLenum mode : {GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_POLYGON}) {
    SCOPED_TRACE(mode);
    Ctx c;
    pfglClearColor(0, 0, 0, 0);
    pfglClear(GL_COLOR_BUFFER_BIT);
    const int n = (1 << 21) + 100;
    if (mode == GL_TRIANGLE_STRIP) {
      degenerateStripThenATriangle(n);
    } else {  // the fan's centre and the polygon's first vertex are shared by every triangle
      pfglBegin(mode);
      pfglVertex2f(4, 4);
      for (int i = 1; i < n - 2; ++i) pfglVertex2f(4, 4);
      pfglVertex2f(12, 4);
      pfglVertex2f(8, 12);
      pfglEnd();
    }
    pfglFinish();
    EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
    EXPECT_NE(c.px[(7 * 16 + 8) * 4 + 3], 0) << "the last triangle is drawn";
  }
}
