// Pixel rectangles through the API where OSMesa cannot be the reference: images too large for
// primflow (GL_OUT_OF_MEMORY, nothing read, the context going on with what it had drawn), the
// formats a framebuffer without stencil or depth buffer lacks (GL_INVALID_OPERATION, as Mesa's
// glDrawPixels / glCopyPixels say: the conformance contexts always have both), and a bitmap's
// fragments exactly where GL 1.5 section 3.7 puts them. (Against OSMesa:
// tests/conformance/cases_pixel_rect.inc.)
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <vector>

#include "gl_context.h"

namespace {

using pf::test::windowOrtho;

GLenum error() { return pfglGetError(); }

TEST(PixelRectangles, TooLargeImagesAreOutOfMemoryAndTheContextGoesOn) {
  pf::test::GlContext c(16, 16);
  windowOrtho(16, 16);
  pfglClearColor(0, 0, 0, 1);
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglColor3f(0.0f, 1.0f, 0.0f);
  pfglRecti(0, 0, 4, 4);  // drawn before: kept
  const std::vector<unsigned char> small(64, 0xff);  // never read past: the size is refused first
  pfglRasterPos2i(8, 8);
  pfglDrawPixels(1 << 14, 1 << 13, GL_RGBA, GL_UNSIGNED_BYTE, small.data());
  EXPECT_EQ(error(), static_cast<GLenum>(GL_OUT_OF_MEMORY));
  pfglBitmap(1 << 15, 1 << 14, 0, 0, 1, 1, small.data());
  EXPECT_EQ(error(), static_cast<GLenum>(GL_OUT_OF_MEMORY));
  float position[4];
  pfglGetFloatv(GL_CURRENT_RASTER_POSITION, position);
  EXPECT_EQ(position[0], 8.0f);  // refused whole: not moved
  pfglNewList(1, GL_COMPILE);
  pfglDrawPixels(1 << 14, 1 << 13, GL_RGBA, GL_UNSIGNED_BYTE, small.data());
  pfglEndList();
  EXPECT_EQ(error(), static_cast<GLenum>(GL_OUT_OF_MEMORY));
  const unsigned char red[4] = {255, 0, 0, 255};
  pfglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  pfglDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
  pfglFinish();
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(c.at(8, 8)[0], 255);
  EXPECT_EQ(c.at(8, 8)[1], 0);
  EXPECT_EQ(c.at(1, 1)[1], 255);  // the rectangle drawn before
}

TEST(PixelRectangles, FormatsOfMissingBuffersAreInvalidOperation) {
  PFcontext ctx = pfCreateContext(GL_RGBA, 0);  // no depth, no stencil buffer
  std::vector<unsigned char> px(16 * 16 * 4);
  ASSERT_TRUE(pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, 16, 16));
  windowOrtho(16, 16);
  const unsigned char data[16] = {};
  pfglRasterPos2i(2, 2);
  pfglDrawPixels(2, 2, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, data);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_OPERATION));
  pfglDrawPixels(2, 2, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, data);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_OPERATION));
  pfglCopyPixels(0, 0, 2, 2, GL_STENCIL);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_OPERATION));
  pfglCopyPixels(0, 0, 2, 2, GL_DEPTH);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_OPERATION));
  pfglDrawPixels(2, 2, GL_STENCIL_INDEX, 0x1234, data);  // the format check comes first
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, data);
  pfglCopyPixels(0, 0, 2, 2, GL_COLOR);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
}

// A bitmap's set bits, and only they, at floor(raster position - origin), LSB first too.
TEST(PixelRectangles, BitmapFragmentsAtItsBits) {
  pf::test::GlContext c(32, 32);
  windowOrtho(32, 32);
  pfglClearColor(0, 0, 0, 1);
  pfglClear(GL_COLOR_BUFFER_BIT);
  const unsigned char bits[3 * 2] = {0xa5, 0x3c, 0x81, 0x0f, 0xf0, 0x55};  // 16 x 3, 2 bytes a row
  pfglPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  pfglColor3f(1.0f, 1.0f, 1.0f);
  pfglRasterPos2f(5.7f, 9.2f);
  pfglBitmap(16, 3, 0.5f, 1.0f, 0.0f, 0.0f, bits);  // lower left at (5, 8)
  pfglPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  pfglRasterPos2i(5, 20);
  pfglBitmap(16, 3, 0.0f, 0.0f, 0.0f, 0.0f, bits);
  pfglFinish();
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      bool set = false;
      for (int b = 0; b < 2; ++b) {
        const int ox = 5, oy = b == 0 ? 8 : 20;
        const int i = x - ox, j = y - oy;
        if (i < 0 || i >= 16 || j < 0 || j >= 3) continue;
        const unsigned char byte = bits[j * 2 + i / 8];
        set = set || ((byte >> (b == 0 ? 7 - i % 8 : i % 8)) & 1);
      }
      EXPECT_EQ(c.at(x, y)[0], set ? 255 : 0) << x << ", " << y;
    }
}

}  // namespace
