// Named parameters and sequence points (paper section 3.1, figure 3): pfglRastParam*EXT sets a
// parameter's current value, pfglSequencePointEXT binds the current values, glVertex is "set
// vertex, then a sequence point". Coverage is checked against positions computed here in
// double precision; instances that do not fit their primitive are rejected whole.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <cmath>
#include <vector>

namespace {

constexpr int kW = 32, kH = 32;

struct Ctx {
  PFcontext ctx;
  std::vector<unsigned char> px;
  Ctx() : ctx(pfCreateContext(GL_RGBA, 24)), px(size_t(kW) * kH * 4) {
    EXPECT_NE(ctx, nullptr);
    pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, kW, kH);
    pfglMatrixMode(GL_PROJECTION);
    pfglOrtho(0, kW, 0, kH, -1, 1);  // window = object x, y
    pfglMatrixMode(GL_MODELVIEW);
    pfglClearColor(0, 0, 0, 0);
    pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  ~Ctx() {
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
    pfDestroyContext(ctx);
  }
  bool drawn(int x, int y) {
    pfglFinish();
    return px[(size_t(y) * kW + x) * 4 + 3] != 0;
  }
};

// A disk in window space: the paper's figure-3 shape of parameters (a point and a radius bound
// per sequence point, so one glBegin may hold many), drawn flat in a constant colour.
const char* kDisk =
    "primitive disk(point center[1]; float radius[1]; inout varying float Z) {\n"
    "  point c = screen(center[0]);\n"
    "  float cx = c.x / c.w;\n"
    "  float cy = c.y / c.w;\n"
    "  bound(cx - radius[0], cy - radius[0], cx + radius[0], cy + radius[0]);\n"
    "  if ((X - cx) * (X - cx) + (Y - cy) * (Y - cy) >= radius[0] * radius[0]) return;\n"
    "  Z = 0.5;\n"
    "}\n"
    // A per-primitive depth with a per-sequence-point vertex: a pixel-wide column at x.
    "primitive column(float depth; point vertex[1]; inout varying float Z) {\n"
    "  point v = screen(vertex[0]);\n"
    "  if (floor(X) != floor(v.x / v.w)) return;\n"
    "  Z = depth;\n"
    "}\n";

bool inDisk(double x, double y, double cx, double cy, double r) {
  return (x + 0.5 - cx) * (x + 0.5 - cx) + (y + 0.5 - cy) * (y + 0.5 - cy) < r * r;
}

}  // namespace

TEST(SequencePoints, ManyDisksInOneBeginEachBoundAtItsSequencePoint) {
  Ctx c;
  ASSERT_NE(pfglCompilePrimitivesEXT(kDisk), 0u);
  GLuint center = pfglGetParamNameEXT("center");
  GLuint radius = pfglGetParamNameEXT("radius");
  EXPECT_NE(center, 0u);
  EXPECT_EQ(pfglGetParamNameEXT("center"), center) << "one id per name";
  pfglColor3f(1, 1, 1);
  pfglTranslatef(2.0f, 0.0f, 0.0f);  // points are transformed when bound
  pfglBegin(pfglGetPrimitiveEXT("disk"));
  pfglRastParamfEXT(radius, 5.5f);
  pfglRastParam3fEXT(center, 6.25f, 8.0f, 0.0f);
  pfglSequencePointEXT();
  pfglRastParamfEXT(radius, 3.0f);  // the centre stays current; only the radius changes
  pfglSequencePointEXT();
  pfglRastParam4fEXT(center, 12.5f, 16.0f, 0.0f, 2.0f);  // homogeneous: the same point as above
  pfglRastParamfEXT(radius, 2.0f);
  pfglSequencePointEXT();
  const GLfloat far_center[2] = {20.5f, 22.0f};
  pfglRastParamfvEXT(center, 2, far_center);  // two values: z = 0, w = 1
  pfglSequencePointEXT();
  pfglEnd();
  ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  int covered = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      bool want = inDisk(x, y, 8.25, 8.0, 5.5) || inDisk(x, y, 8.25, 8.0, 3.0) || inDisk(x, y, 22.5, 22.0, 2.0);  // the radius set last is 2
      EXPECT_EQ(c.drawn(x, y), want) << "pixel (" << x << ", " << y << ")";
      covered += want;
    }
  EXPECT_GT(covered, 100);
}

TEST(SequencePoints, VertexIsSetVertexThenASequencePoint) {
  const float tri[3][3] = {{1.5f, 2.0f, 0.0f}, {29.0f, 5.5f, 0.0f}, {12.0f, 30.0f, 0.0f}};
  std::vector<unsigned char> with_vertex;
  {
    Ctx c;
    pfglBegin(GL_TRIANGLES);
    for (auto& v : tri) {
      pfglColor3f(v[0] / 32, v[1] / 32, 0.5f);
      pfglVertex3fv(v);
    }
    pfglEnd();
    pfglFinish();
    with_vertex = c.px;
  }
  Ctx c;
  GLuint vertex = pfglGetParamNameEXT("vertex");
  pfglBegin(GL_TRIANGLES);
  for (auto& v : tri) {
    pfglColor3f(v[0] / 32, v[1] / 32, 0.5f);
    pfglRastParam3fEXT(vertex, v[0], v[1], v[2]);
    pfglSequencePointEXT();
  }
  pfglEnd();
  pfglFinish();
  EXPECT_EQ(c.px, with_vertex);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(SequencePoints, PerPrimitiveValuesComeFromTheInstancesFirstSequencePoint) {
  Ctx c;
  ASSERT_NE(pfglCompilePrimitivesEXT(kDisk), 0u);
  GLuint depth = pfglGetParamNameEXT("depth");
  pfglEnable(GL_DEPTH_TEST);
  pfglDepthFunc(GL_ALWAYS);
  pfglBegin(pfglGetPrimitiveEXT("column"));
  pfglRastParamfEXT(depth, 0.25f);
  pfglVertex2f(3.5f, 0.0f);
  pfglRastParamfEXT(depth, 0.75f);
  pfglVertex2f(9.5f, 0.0f);
  pfglEnd();
  GLint w, h, b;
  void* d;
  ASSERT_TRUE(pfGetDepthBuffer(c.ctx, &w, &h, &b, &d));
  const float* z = static_cast<const float*>(d);
  EXPECT_EQ(z[3], 0.25f);
  EXPECT_EQ(z[9], 0.75f);
  EXPECT_EQ(z[5], 1.0f);
}

TEST(SequencePoints, InstancesThatDoNotFitAreRejectedWhole) {
  Ctx c;
  ASSERT_NE(pfglCompilePrimitivesEXT(kDisk), 0u);
  GLenum disk = pfglGetPrimitiveEXT("disk");
  GLuint center = pfglGetParamNameEXT("center");
  GLuint radius = pfglGetParamNameEXT("radius");
  // The radius was never set: nothing of this glBegin / glEnd is drawn.
  pfglBegin(disk);
  pfglRastParam3fEXT(center, 16, 16, 0);
  pfglSequencePointEXT();
  pfglEnd();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_FALSE(c.drawn(16, 16));
  // A radius of three values: mistyped. The first sequence point was fine; still nothing.
  pfglBegin(disk);
  pfglRastParamfEXT(radius, 4);
  pfglSequencePointEXT();
  pfglRastParam3fEXT(radius, 1, 2, 3);
  pfglSequencePointEXT();
  pfglEnd();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_FALSE(c.drawn(16, 16));
  // A primitive of the extension takes whole instances: "column" wants 1 per instance, so any
  // count fits; a user triangle of 3 with 4 sequence points does not.
  ASSERT_NE(pfglCompilePrimitivesEXT("primitive tri3(point vertex[3]; interpolator_data d[3]) { triangles(vertex, d); }"), 0u);
  pfglBegin(pfglGetPrimitiveEXT("tri3"));
  pfglVertex2f(0, 0);
  pfglVertex2f(30, 0);
  pfglVertex2f(0, 30);
  pfglVertex2f(30, 30);
  pfglEnd();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_FALSE(c.drawn(2, 2));
  // GL's own modes keep GL's rule: a trailing incomplete triangle is dropped silently.
  pfglBegin(GL_TRIANGLES);
  pfglVertex2f(0, 0);
  pfglVertex2f(30, 0);
  pfglVertex2f(0, 30);
  pfglVertex2f(30, 30);
  pfglEnd();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_TRUE(c.drawn(2, 2));
}

TEST(SequencePoints, Errors) {
  Ctx c;
  pfglSequencePointEXT();  // outside glBegin / glEnd
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  pfglRastParamfEXT(9999, 1.0f);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglRastParamfEXT(0, 1.0f);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(pfglGetParamNameEXT(nullptr), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(pfglGetParamNameEXT(""), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  GLuint p = pfglGetParamNameEXT("p");
  pfglRastParamfvEXT(p, 17, nullptr);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  const GLint two[2] = {1, 2};
  pfglRastParamivEXT(p, 0, two);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglRastParamivEXT(p, 2, two);
  pfglRastParamiEXT(p, 3);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

namespace {

// Writes one component of its vector or normal parameter as the depth of each pixel of the
// bottom row: columns 0-2 the vector's x, y, z, columns 3-5 the normal's (depth 0.5 + c / 8).
const char* kDirectionProbe =
    "primitive probe(vector v[1]; normal n[1]; inout varying float Z) {\n"
    "  bound(0, 0, 6, 1);\n"
    "  float c = v[0].x;\n"
    "  if (X > 1) c = v[0].y;\n"
    "  if (X > 2) c = v[0].z;\n"
    "  if (X > 3) c = n[0].x;\n"
    "  if (X > 4) c = n[0].y;\n"
    "  if (X > 5) c = n[0].z;\n"
    "  Z = 0.5 + c / 8;\n"
    "}\n";

struct Directions {
  double v[3], n[3];
};

// Draws the probe with v and n as given under the current modelview; what arrived.
Directions probeDirections(Ctx& c, const float v[3], const float n[3]) {
  const GLuint vn = pfglGetParamNameEXT("v"), nn = pfglGetParamNameEXT("n");
  pfglClear(GL_DEPTH_BUFFER_BIT);
  pfglBegin(pfglGetPrimitiveEXT("probe"));
  pfglRastParam3fEXT(vn, v[0], v[1], v[2]);
  pfglRastParam3fEXT(nn, n[0], n[1], n[2]);
  pfglSequencePointEXT();
  pfglEnd();
  pfglFinish();
  GLint w, h, bpv;
  void* p = nullptr;
  EXPECT_EQ(pfGetDepthBuffer(c.ctx, &w, &h, &bpv, &p), GL_TRUE);
  const float* d = static_cast<const float*>(p);
  Directions r{};
  for (int i = 0; i < 3; ++i) {
    r.v[i] = (d[i] - 0.5) * 8;
    r.n[i] = (d[3 + i] - 0.5) * 8;
  }
  return r;
}

}  // namespace

// Seed 003 section 2.1: a primitive declares which values are points, vectors and normals and
// the system transforms them -- vectors by the modelview's upper 3x3, normals by its inverse
// transpose (GL_NORMALIZE and GL_RESCALE_NORMAL as for glNormal), both to eye coordinates.
// Expected values are worked out here by hand from the matrices.
TEST(SequencePoints, VectorsAndNormalsAreTransformedToEyeCoordinates) {
  Ctx c;
  ASSERT_NE(pfglCompilePrimitivesEXT(kDirectionProbe), 0u);
  pfglEnable(GL_DEPTH_TEST);
  pfglDepthFunc(GL_ALWAYS);
  const double tol = 1e-6;
  auto expect = [&](const Directions& got, std::initializer_list<double> v, std::initializer_list<double> n,
                    const char* what) {
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(got.v[i], v.begin()[i], tol) << what << ": vector component " << i;
      EXPECT_NEAR(got.n[i], n.begin()[i], tol) << what << ": normal component " << i;
    }
  };
  const float x[3] = {1, 0, 0}, xy[3] = {1, 1, 0}, z[3] = {0, 0, 1};

  pfglLoadIdentity();
  expect(probeDirections(c, xy, xy), {1, 1, 0}, {1, 1, 0}, "identity");

  pfglLoadIdentity();
  pfglRotatef(90, 0, 0, 1);  // x goes to y
  expect(probeDirections(c, x, x), {0, 1, 0}, {0, 1, 0}, "rotated 90 degrees about z");

  pfglLoadIdentity();
  pfglTranslatef(3, -2, 1);  // translation moves points, never directions
  pfglScalef(2, 1, 1);       // a vector stretches with x; a normal shrinks (inverse transpose)
  expect(probeDirections(c, xy, xy), {2, 1, 0}, {0.5, 1, 0}, "translated and scaled by (2, 1, 1)");

  pfglEnable(GL_NORMALIZE);  // normals to unit length; vectors keep theirs
  const double s = 1 / std::sqrt(1.25);
  expect(probeDirections(c, xy, xy), {2, 1, 0}, {0.5 * s, s, 0}, "GL_NORMALIZE");
  pfglDisable(GL_NORMALIZE);

  pfglLoadIdentity();
  pfglScalef(4, 4, 4);
  expect(probeDirections(c, z, z), {0, 0, 4}, {0, 0, 0.25}, "uniform scale 4");
  pfglEnable(GL_RESCALE_NORMAL);  // divides by the inverse's third row's length, 1/4
  expect(probeDirections(c, z, z), {0, 0, 4}, {0, 0, 1}, "uniform scale 4, GL_RESCALE_NORMAL");
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}
