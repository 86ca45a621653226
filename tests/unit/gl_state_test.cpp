// The GL state commands and queries: matrix stacks and their errors (checked against matrices
// computed here in double precision), glGet* for each piece of state, glReadPixels' formats and
// row alignment, colour masks, and the errors GL defines for misuse.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <cmath>
#include <cstring>
#include <vector>

namespace {

struct Ctx {
  PFcontext ctx;
  std::vector<unsigned char> px;
  Ctx(int w = 8, int h = 4, int depth_bits = 24) : ctx(pfCreateContext(GL_RGBA, depth_bits)), px(size_t(w) * h * 4) {
    EXPECT_NE(ctx, nullptr);
    pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, w, h);
  }
  ~Ctx() {
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
    pfDestroyContext(ctx);
  }
};

GLenum error() { return pfglGetError(); }

// Column-major 4x4 products and GL's formulas, in double.
struct M {
  double m[16];
  static M identity() {
    M r{};
    for (int i = 0; i < 4; ++i) r.m[i * 5] = 1;
    return r;
  }
  M operator*(const M& b) const {
    M r{};
    for (int c = 0; c < 4; ++c)
      for (int row = 0; row < 4; ++row)
        for (int k = 0; k < 4; ++k) r.m[c * 4 + row] += m[k * 4 + row] * b.m[c * 4 + k];
    return r;
  }
};

M translate(double x, double y, double z) {
  M r = M::identity();
  r.m[12] = x, r.m[13] = y, r.m[14] = z;
  return r;
}
M scale(double x, double y, double z) {
  M r = M::identity();
  r.m[0] = x, r.m[5] = y, r.m[10] = z;
  return r;
}
// GL 1.5 section 2.11.2: rotation by a degrees about the unit vector (x, y, z).
M rotate(double a, double x, double y, double z) {
  double l = std::sqrt(x * x + y * y + z * z);
  x /= l, y /= l, z /= l;
  double c = std::cos(a * M_PI / 180), s = std::sin(a * M_PI / 180);
  M r = M::identity();
  r.m[0] = x * x * (1 - c) + c, r.m[4] = x * y * (1 - c) - z * s, r.m[8] = x * z * (1 - c) + y * s;
  r.m[1] = y * x * (1 - c) + z * s, r.m[5] = y * y * (1 - c) + c, r.m[9] = y * z * (1 - c) - x * s;
  r.m[2] = x * z * (1 - c) - y * s, r.m[6] = y * z * (1 - c) + x * s, r.m[10] = z * z * (1 - c) + c;
  return r;
}
M frustum(double l, double r, double b, double t, double n, double f) {
  M m{};
  m.m[0] = 2 * n / (r - l), m.m[5] = 2 * n / (t - b);
  m.m[8] = (r + l) / (r - l), m.m[9] = (t + b) / (t - b), m.m[10] = -(f + n) / (f - n), m.m[11] = -1;
  m.m[14] = -2 * f * n / (f - n);
  return m;
}

void expectMatrix(GLenum which, const M& want, double tol) {
  GLdouble got[16];
  pfglGetDoublev(which, got);
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(got[i], want.m[i], tol) << "element " << i;
}

}  // namespace

TEST(GlState, MatrixOperationsComposeAsGlDefinesThem) {
  Ctx c;
  pfglMatrixMode(GL_MODELVIEW);
  pfglTranslatef(1, 2, 3);
  pfglRotatef(30, 1, 1, 0);
  pfglScaled(2, 0.5, 4);
  const GLfloat shear[16] = {1, 0.25f, 0, 0, 0, 1, 0, 0, 0.5f, 0, 1, 0, 0, 0, 0, 1};
  pfglMultMatrixf(shear);
  M s = M::identity();
  for (int i = 0; i < 16; ++i) s.m[i] = shear[i];
  expectMatrix(GL_MODELVIEW_MATRIX, translate(1, 2, 3) * rotate(30, 1, 1, 0) * scale(2, 0.5, 4) * s, 1e-6);
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-1, 2, -0.5, 1, 1, 100);
  expectMatrix(GL_PROJECTION_MATRIX, frustum(-1, 2, -0.5, 1, 1, 100), 1e-5);
  pfglLoadIdentity();
  const GLdouble load[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
  pfglLoadMatrixd(load);
  M l;
  for (int i = 0; i < 16; ++i) l.m[i] = load[i];
  expectMatrix(GL_PROJECTION_MATRIX, l, 0);
  pfglMatrixMode(GL_TEXTURE);
  pfglTranslated(0.5, 0, 0);
  expectMatrix(GL_TEXTURE_MATRIX, translate(0.5, 0, 0), 0);
  // A zero axis leaves the matrix as it was.
  pfglRotatef(45, 0, 0, 0);
  expectMatrix(GL_TEXTURE_MATRIX, translate(0.5, 0, 0), 0);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(GlState, StacksHaveTheirDepthsAndReportOverAndUnderflow) {
  Ctx c;
  struct {
    GLenum mode, depth, max;
    int expect_max;
  } stacks[] = {{GL_MODELVIEW, GL_MODELVIEW_STACK_DEPTH, GL_MAX_MODELVIEW_STACK_DEPTH, 32},
                {GL_PROJECTION, GL_PROJECTION_STACK_DEPTH, GL_MAX_PROJECTION_STACK_DEPTH, 4},
                {GL_TEXTURE, GL_TEXTURE_STACK_DEPTH, GL_MAX_TEXTURE_STACK_DEPTH, 4}};
  for (auto& s : stacks) {
    pfglMatrixMode(s.mode);
    GLint max = 0, depth = 0;
    pfglGetIntegerv(s.max, &max);
    EXPECT_EQ(max, s.expect_max);
    pfglPopMatrix();
    EXPECT_EQ(error(), static_cast<GLenum>(GL_STACK_UNDERFLOW));
    pfglTranslatef(1, 0, 0);
    for (int i = 1; i < max; ++i) pfglPushMatrix();
    pfglGetIntegerv(s.depth, &depth);
    EXPECT_EQ(depth, max);
    EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
    pfglPushMatrix();
    EXPECT_EQ(error(), static_cast<GLenum>(GL_STACK_OVERFLOW));
    pfglLoadIdentity();
    for (int i = 1; i < max; ++i) pfglPopMatrix();
    expectMatrix(s.mode == GL_MODELVIEW ? GL_MODELVIEW_MATRIX : s.mode == GL_PROJECTION ? GL_PROJECTION_MATRIX : GL_TEXTURE_MATRIX,
                 translate(1, 0, 0), 0);
    EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
  }
}

TEST(GlState, QueriesReturnTheStateInEachType) {
  Ctx c;
  pfglViewport(1, 2, 5, 3);
  pfglClearColor(0.25f, 0.5f, 0.75f, 1.0f);
  pfglDepthRange(0.25, 0.75);
  pfglDepthFunc(GL_GEQUAL);
  pfglEnable(GL_CULL_FACE);
  pfglCullFace(GL_FRONT);
  pfglFrontFace(GL_CW);
  pfglShadeModel(GL_FLAT);
  pfglColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  pfglColor4f(1.0f, 0.0f, 0.5f, 0.25f);
  pfglNormal3f(0.0f, 1.0f, 0.0f);
  pfglTexCoord2f(0.5f, 0.25f);
  GLint v[4];
  pfglGetIntegerv(GL_VIEWPORT, v);
  EXPECT_EQ(v[0], 1);
  EXPECT_EQ(v[3], 3);
  GLfloat f[4];
  pfglGetFloatv(GL_COLOR_CLEAR_VALUE, f);
  EXPECT_EQ(f[1], 0.5f);
  pfglGetIntegerv(GL_COLOR_CLEAR_VALUE, v);  // normalised: 1.0 -> 2^31 - 1, truncated as Mesa does
  EXPECT_EQ(v[3], 2147483647);
  EXPECT_EQ(v[0], 536870911);
  GLdouble d[4];
  pfglGetDoublev(GL_DEPTH_RANGE, d);
  EXPECT_EQ(d[0], 0.25);
  pfglGetIntegerv(GL_DEPTH_FUNC, v);
  EXPECT_EQ(v[0], GL_GEQUAL);
  GLboolean b[4];
  pfglGetBooleanv(GL_CULL_FACE, b);
  EXPECT_EQ(b[0], GL_TRUE);
  pfglGetBooleanv(GL_DEPTH_TEST, b);
  EXPECT_EQ(b[0], GL_FALSE);
  pfglGetIntegerv(GL_CULL_FACE_MODE, v);
  EXPECT_EQ(v[0], GL_FRONT);
  pfglGetIntegerv(GL_FRONT_FACE, v);
  EXPECT_EQ(v[0], GL_CW);
  pfglGetIntegerv(GL_SHADE_MODEL, v);
  EXPECT_EQ(v[0], GL_FLAT);
  pfglGetBooleanv(GL_COLOR_WRITEMASK, b);
  EXPECT_EQ(b[0], GL_TRUE);
  EXPECT_EQ(b[1], GL_FALSE);
  pfglGetFloatv(GL_CURRENT_COLOR, f);
  EXPECT_EQ(f[3], 0.25f);
  pfglGetFloatv(GL_CURRENT_NORMAL, f);
  EXPECT_EQ(f[1], 1.0f);
  pfglGetFloatv(GL_CURRENT_TEXTURE_COORDS, f);
  EXPECT_EQ(f[0], 0.5f);
  EXPECT_EQ(f[3], 1.0f);
  pfglGetIntegerv(GL_DEPTH_BITS, v);
  EXPECT_EQ(v[0], 24);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
  pfglGetIntegerv(GL_MAP1_GRID_SEGMENTS, v);  // not state primflow has: GL's initial value
  EXPECT_EQ(v[0], 1);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
  pfglGetIntegerv(0x1234, v);  // not a state variable
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglGetIntegerv(GL_VIEWPORT, nullptr);  // NULL: nothing written, no crash
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(GlState, ReadPixelsFormatsTypesAndAlignment) {
  Ctx c(3, 2);
  pfglClearColor(1.0f, 0.5f, 0.0f, 1.0f);
  pfglClearDepth(0.5);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  // RGB bytes, 3 wide: 9 bytes per row, padded to 12 by the default alignment of 4.
  std::vector<unsigned char> rgb(24, 7);
  pfglReadPixels(0, 0, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  EXPECT_EQ(rgb[0], 255);
  EXPECT_EQ(rgb[1], 128);
  EXPECT_EQ(rgb[9], 7) << "padding is left alone";
  EXPECT_EQ(rgb[12], 255) << "row 1 starts at byte 12";
  pfglPixelStorei(GL_PACK_ALIGNMENT, 1);
  std::fill(rgb.begin(), rgb.end(), 7);
  pfglReadPixels(0, 0, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  EXPECT_EQ(rgb[9], 255) << "alignment 1: row 1 starts at byte 9";
  std::vector<float> rgba(24);
  pfglReadPixels(0, 0, 3, 2, GL_RGBA, GL_FLOAT, rgba.data());
  EXPECT_FLOAT_EQ(rgba[1], 128 / 255.0f);
  float depth[6];
  pfglReadPixels(0, 0, 3, 2, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  EXPECT_EQ(depth[5], 0.5f);
  unsigned int depth32 = 0;
  pfglReadPixels(1, 1, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &depth32);
  EXPECT_EQ(depth32, 2147483648u);
  // Outside the framebuffer: left as it is.
  unsigned char outside[4] = {1, 2, 3, 4};
  pfglReadPixels(5, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, outside);
  EXPECT_EQ(outside[0], 1);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
  pfglReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, outside);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglReadPixels(0, 0, 1, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, outside);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglReadPixels(0, 0, 1, 1, GL_RGBA, GL_BYTE, outside);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglPixelStorei(GL_PACK_ALIGNMENT, 3);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglPixelStorei(0x1234, 1);  // not a pixel store mode
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);  // NULL: nothing, no crash
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(GlState, DepthReadWithoutDepthBufferIsInvalidOperation) {
  Ctx c(2, 2, 0);
  float d = 0;
  pfglReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &d);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_OPERATION));
}

TEST(GlState, BadEnumsAndCommandsInsideBeginEnd) {
  Ctx c;
  pfglMatrixMode(GL_COLOR);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglCullFace(GL_LEFT);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglFrontFace(GL_FRONT);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglShadeModel(GL_LINE);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglEnable(GL_LINE_SMOOTH);  // a capability primflow does not have
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglLoadMatrixf(nullptr);  // ignored
  pfglVertex3fv(nullptr);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
  pfglBegin(GL_TRIANGLES);
  pfglPushMatrix();
  pfglTranslatef(1, 0, 0);
  pfglCullFace(GL_BACK);
  pfglReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, c.px.data());
  pfglColor3ub(10, 20, 30);  // allowed
  pfglNormal3f(0, 0, 1);     // allowed
  pfglEnd();
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR)) << "the first error sticks, then clears";
  GLint depth;
  pfglGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &depth);
  EXPECT_EQ(depth, 1);
  expectMatrix(GL_MODELVIEW_MATRIX, M::identity(), 0);
  GLfloat col[4];
  pfglGetFloatv(GL_CURRENT_COLOR, col);
  EXPECT_FLOAT_EQ(col[1], 20 / 255.0f);
}

TEST(GlState, ColorMaskKeepsMaskedChannels) {
  Ctx c(2, 1);
  pfglClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
  pfglClearColor(1, 1, 1, 1);
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglFinish();
  EXPECT_EQ(c.px[0], 51);
  EXPECT_EQ(c.px[1], 255);
  EXPECT_EQ(c.px[2], 153);
  EXPECT_EQ(c.px[3], 255);
}
