// The context and the GL entry points of the spine: binding, errors as GL defines them, the
// depth buffer's format, and commands without a context.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <utility>
#include <vector>

namespace {

struct Ctx {
  PFcontext ctx;
  std::vector<unsigned char> pixels;
  Ctx(int w, int h, int depth_bits = 24) : ctx(pfCreateContext(GL_RGBA, depth_bits)), pixels(static_cast<size_t>(w) * h * 4) {
    EXPECT_NE(ctx, nullptr);
    EXPECT_EQ(pfMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, w, h), GL_TRUE);
  }
  ~Ctx() {
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
    pfDestroyContext(ctx);
  }
};

}  // namespace

TEST(Api, CreateRejectsBadFormatAndAttributes) {
  EXPECT_EQ(pfCreateContext(GL_RGB, 24), nullptr);
  EXPECT_EQ(pfCreateContext(GL_RGBA, -1), nullptr);
  const int bad[] = {0x12345, 1, 0};
  EXPECT_EQ(pfCreateContextAttribs(bad), nullptr);
  const int threads[] = {PF_FORMAT, GL_RGBA, PF_THREADS, 3, 0};
  PFcontext c = pfCreateContextAttribs(threads);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(pfGetThreadCount(c), 3);
  pfDestroyContext(c);
}

// pfGetColorBuffer, as OSMesaGetColorBuffer: the caller's buffer, after pending drawing ran;
// GL_FALSE and zeroed outputs for no context or one never bound.
TEST(Api, GetColorBufferHandsBackTheBoundBufferAfterDrawing) {
  GLint w = 1, h = 1, format = 1;
  void* p = &w;
  EXPECT_EQ(pfGetColorBuffer(nullptr, &w, &h, &format, &p), GL_FALSE);
  EXPECT_EQ(p, nullptr);
  EXPECT_EQ(w, 0);
  PFcontext unbound = pfCreateContext(GL_RGBA, 0);
  EXPECT_EQ(pfGetColorBuffer(unbound, nullptr, nullptr, nullptr, nullptr), GL_FALSE);
  pfDestroyContext(unbound);
  Ctx c(4, 3);
  pfglClearColor(1, 0, 0, 1);
  pfglClear(GL_COLOR_BUFFER_BIT);  // pending until something finishes it
  ASSERT_EQ(pfGetColorBuffer(c.ctx, &w, &h, &format, &p), GL_TRUE);
  EXPECT_EQ(p, c.pixels.data());
  EXPECT_EQ(w, 4);
  EXPECT_EQ(h, 3);
  EXPECT_EQ(format, GL_RGBA);
  EXPECT_EQ(c.pixels[0], 255);
}

TEST(Api, MakeCurrentValidatesArguments) {
  PFcontext c = pfCreateContext(GL_RGBA, 0);
  std::vector<unsigned char> buf(16);
  EXPECT_EQ(pfMakeCurrent(c, nullptr, GL_UNSIGNED_BYTE, 2, 2), GL_FALSE);
  EXPECT_EQ(pfMakeCurrent(c, buf.data(), GL_FLOAT, 2, 2), GL_FALSE);
  EXPECT_EQ(pfMakeCurrent(c, buf.data(), GL_UNSIGNED_BYTE, 0, 2), GL_FALSE);
  EXPECT_EQ(pfMakeCurrent(c, buf.data(), GL_UNSIGNED_BYTE, 8193, 1), GL_FALSE);
  EXPECT_EQ(pfMakeCurrent(c, buf.data(), GL_UNSIGNED_BYTE, 2, 2), GL_TRUE);
  EXPECT_EQ(pfGetCurrentContext(), c);
  // No depth buffer was asked for.
  GLint w, h, bpv;
  void* p;
  EXPECT_EQ(pfGetDepthBuffer(c, &w, &h, &bpv, &p), GL_FALSE);
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  EXPECT_EQ(pfGetCurrentContext(), nullptr);
  pfDestroyContext(c);
}

// The largest framebuffers, 8192 on a side (the limit: 8193 is refused above): a triangle
// across the whole of a 8192x16 and of a 16x8192 one reaches their last pixels, depth-tested.
TEST(Api, FramebuffersOf8192OnASideDrawToTheirFarEnd) {
  for (const auto& [w, h] : {std::pair{8192, 16}, std::pair{16, 8192}}) {
    std::vector<unsigned char> px(static_cast<size_t>(w) * h * 4, 0);
    PFcontext c = pfCreateContext(GL_RGBA, 24);
    ASSERT_EQ(pfMakeCurrent(c, px.data(), GL_UNSIGNED_BYTE, w, h), GL_TRUE) << w << "x" << h;
    pfglEnable(GL_DEPTH_TEST);
    pfglMatrixMode(GL_PROJECTION);
    pfglOrtho(0, w, 0, h, -1, 1);
    pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    pfglBegin(GL_TRIANGLES);
    pfglColor3f(0, 1, 0);
    pfglVertex3f(-1, -1, 0);
    pfglVertex3f(2.0f * w + 1, -1, 0);
    pfglVertex3f(-1, 2.0f * h + 1, 0);
    pfglEnd();
    pfglFinish();
    EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
    for (const auto& [x, y] : {std::pair{0, 0}, std::pair{w - 1, 0}, std::pair{0, h - 1}, std::pair{w - 1, h - 1}}) {
      const unsigned char* p = px.data() + (static_cast<size_t>(y) * w + x) * 4;
      EXPECT_EQ(p[1], 255) << w << "x" << h << " at " << x << ", " << y;
    }
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
    pfDestroyContext(c);
  }
}

TEST(Api, NoContextIsANoOp) {
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglBegin(GL_TRIANGLES);
  pfglVertex3f(0, 0, 0);
  pfglEnd();
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(pfglGetString(GL_VENDOR), nullptr);
  pfDestroyContext(nullptr);
}

TEST(Api, ErrorsFollowGL) {
  Ctx c(16, 16);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  pfglBegin(0x7777);  // not a primitive
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglEnd();  // no glBegin
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  pfglViewport(0, 0, -1, 4);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglOrtho(0, 0, 0, 1, 0, 1);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglFrustum(-1, 1, -1, 1, 0, 10);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglMatrixMode(GL_COLOR);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglClear(0x80000000u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglDepthFunc(GL_NEVER - 1);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglDepthFunc(GL_ALWAYS + 1);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_EQ(pfglGetString(0x1234), nullptr);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_ENUM));

  // Inside glBegin/glEnd: state commands and glGetError itself are invalid operations; the
  // first error sticks until glGetError reads it.
  pfglBegin(GL_TRIANGLES);
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglLoadIdentity();
  pfglBegin(GL_TRIANGLES);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));  // not allowed here: returns 0
  pfglEnd();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(Api, StringsAndEnables) {
  Ctx c(4, 4);
  EXPECT_STREQ(reinterpret_cast<const char*>(pfglGetString(GL_VENDOR)), "primflow");
  EXPECT_EQ(pfglIsEnabled(GL_DEPTH_TEST), GL_FALSE);
  pfglEnable(GL_DEPTH_TEST);
  EXPECT_EQ(pfglIsEnabled(GL_DEPTH_TEST), GL_TRUE);
  pfglDisable(GL_DEPTH_TEST);
  EXPECT_EQ(pfglIsEnabled(GL_DEPTH_TEST), GL_FALSE);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(Api, ClearAndDepthBufferFormat) {
  Ctx c(5, 3);
  pfglClearColor(0.2f, 0.4f, 0.6f, 1.0f);
  pfglClearDepth(0.25);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglFinish();
  for (int i = 0; i < 15; ++i) {
    EXPECT_EQ(c.pixels[i * 4 + 0], 51);   // 0.2 * 255 rounded
    EXPECT_EQ(c.pixels[i * 4 + 1], 102);
    EXPECT_EQ(c.pixels[i * 4 + 2], 153);
    EXPECT_EQ(c.pixels[i * 4 + 3], 255);
  }
  GLint w, h, bpv;
  void* p;
  ASSERT_EQ(pfGetDepthBuffer(c.ctx, &w, &h, &bpv, &p), GL_TRUE);
  EXPECT_EQ(w, 5);
  EXPECT_EQ(h, 3);
  EXPECT_EQ(bpv, 4);
  const float* d = static_cast<const float*>(p);
  for (int i = 0; i < 15; ++i) EXPECT_FLOAT_EQ(d[i], 0.25f);
}

TEST(Api, DepthTestAndDepthBufferRowOrder) {
  // A triangle at z = 0 (window depth 0.5) over the bottom half only: row 0 is the bottom.
  Ctx c(8, 8);
  pfglMatrixMode(GL_PROJECTION);
  pfglLoadIdentity();
  pfglOrtho(0, 8, 0, 8, -1, 1);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  pfglColor3f(1, 0, 0);
  pfglBegin(GL_TRIANGLES);
  pfglVertex3f(0, 0, 0);
  pfglVertex3f(16, 0, 0);
  pfglVertex3f(0, 4, 0);
  pfglEnd();
  GLint w, h, bpv;
  void* p;
  ASSERT_EQ(pfGetDepthBuffer(c.ctx, &w, &h, &bpv, &p), GL_TRUE);
  const float* d = static_cast<const float*>(p);
  EXPECT_FLOAT_EQ(d[0], 0.5f);           // bottom-left pixel covered
  EXPECT_FLOAT_EQ(d[7 * 8 + 0], 1.0f);   // top-left pixel not
  EXPECT_EQ(c.pixels[0], 255);
  EXPECT_EQ(c.pixels[(7 * 8) * 4], 0);
}

TEST(Api, IncompleteTriangleIsDropped) {
  Ctx c(8, 8);
  pfglMatrixMode(GL_PROJECTION);
  pfglOrtho(0, 8, 0, 8, -1, 1);
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglBegin(GL_TRIANGLES);
  pfglVertex3f(0, 0, 0);
  pfglVertex3f(8, 0, 0);
  pfglEnd();
  pfglFinish();
  for (size_t i = 0; i < c.pixels.size(); i += 4) EXPECT_EQ(c.pixels[i], 0);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// The stencil buffer exists only when the context asks for it (PF_STENCIL_BITS): GL_STENCIL_BITS
// says 8 or 0, and reading GL_STENCIL_INDEX without one is GL_INVALID_OPERATION (as OSMesa);
// with one, a clear under a write mask reads back as (old & ~mask) | (value & mask).
TEST(Api, StencilBufferOnlyWhenAskedFor) {
  std::vector<unsigned char> px(8 * 8 * 4);
  for (int bits : {0, 8}) {
    const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_STENCIL_BITS, bits, 0};
    PFcontext ctx = pfCreateContextAttribs(attribs);
    ASSERT_NE(ctx, nullptr);
    ASSERT_TRUE(pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, 8, 8));
    GLint stencil_bits = -1;
    pfglGetIntegerv(GL_STENCIL_BITS, &stencil_bits);
    EXPECT_EQ(stencil_bits, bits);
    pfglClearStencil(0x5a);
    pfglClear(GL_STENCIL_BUFFER_BIT);
    pfglStencilMask(0x0f);
    pfglClearStencil(0xa3);
    pfglClear(GL_STENCIL_BUFFER_BIT);
    GLubyte value = 7;
    pfglReadPixels(3, 4, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &value);
    if (bits == 0) {
      EXPECT_EQ(pfglGetError(), GLenum(GL_INVALID_OPERATION));
      EXPECT_EQ(value, 7);
    } else {
      EXPECT_EQ(pfglGetError(), GLenum(GL_NO_ERROR));
      EXPECT_EQ(value, 0x53);
    }
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
    pfDestroyContext(ctx);
  }
  const int negative[] = {PF_STENCIL_BITS, -1, 0};
  EXPECT_EQ(pfCreateContextAttribs(negative), nullptr);
}
