// The accumulation buffer through the API, where the conformance cases (against OSMesa:
// tests/conformance/cases_accum.inc, whose contexts all have one) cannot go: a context without
// one, the PF_ACCUM_BITS attribute, the buffer following the drawable's size, and the average of
// accumulated images against the exact mean.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace {

// A context of w x h with (or without) an accumulation buffer, current; the caller destroys it.
PFcontext accumContext(std::vector<unsigned char>& px, int w, int h, int accum_bits) {
  px.assign(static_cast<size_t>(w) * h * 4, 0);
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_ACCUM_BITS, accum_bits, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  if (ctx && !pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, w, h)) {
    pfDestroyContext(ctx);
    return nullptr;
  }
  return ctx;
}

void release(PFcontext ctx) {
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
}

GLint integer(GLenum pname) {
  GLint v = -1;
  pfglGetIntegerv(pname, &v);
  return v;
}

// As OSMesa (and GL): without an accumulation buffer glAccum is GL_INVALID_OPERATION -- after
// the op's own GL_INVALID_ENUM --, clearing it is no error, and its sizes read 0.
TEST(Accumulation, WithoutABufferGlAccumIsInvalidOperation) {
  std::vector<unsigned char> px;
  PFcontext ctx = accumContext(px, 16, 16, 0);
  ASSERT_NE(ctx, nullptr);
  EXPECT_EQ(integer(GL_ACCUM_RED_BITS), 0);
  EXPECT_EQ(integer(GL_ACCUM_ALPHA_BITS), 0);
  pfglAccum(GL_LOAD, 1.0f);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  pfglAccum(GL_RETURN + 100, 1.0f);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglClearAccum(0.5f, 0.5f, 0.5f, 0.5f);
  pfglClear(GL_ACCUM_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  release(ctx);
}

// Any positive PF_ACCUM_BITS gives Mesa's 16 bits a channel; a negative one is no context.
TEST(Accumulation, AttributeGivesSixteenBitsAChannel) {
  std::vector<unsigned char> px;
  EXPECT_EQ(accumContext(px, 8, 8, -1), nullptr);
  for (int bits : {1, 16, 64}) {
    PFcontext ctx = accumContext(px, 8, 8, bits);
    ASSERT_NE(ctx, nullptr);
    for (GLenum p : {GL_ACCUM_RED_BITS, GL_ACCUM_GREEN_BITS, GL_ACCUM_BLUE_BITS, GL_ACCUM_ALPHA_BITS})
      EXPECT_EQ(integer(p), 16) << bits;
    release(ctx);
  }
}

// Seven flat images accumulated at 1/7 and returned: each channel is the exact mean of the seven
// bytes within one step (each pass truncates to 1/32767; the return rounds once).
TEST(Accumulation, AveragedImagesGiveTheMean) {
  std::vector<unsigned char> px;
  PFcontext ctx = accumContext(px, 32, 8, 16);
  ASSERT_NE(ctx, nullptr);
  const int kPasses = 7;
  double sum[32][4] = {};
  pfglClear(GL_ACCUM_BUFFER_BIT);
  pfglEnable(GL_SCISSOR_TEST);
  for (int pass = 0; pass < kPasses; ++pass) {
    for (int x = 0; x < 32; ++x) {  // a colour per column and pass
      uint8_t c[4];
      for (int k = 0; k < 4; ++k) c[k] = static_cast<uint8_t>((x * 37 + pass * 101 + k * 53) * 7 % 256);
      pfglScissor(x, 0, 1, 8);
      pfglClearColor(c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, c[3] / 255.0f);
      pfglClear(GL_COLOR_BUFFER_BIT);
      for (int k = 0; k < 4; ++k) sum[x][k] += c[k];
    }
    pfglScissor(0, 0, 32, 8);
    pfglAccum(GL_ACCUM, 1.0f / kPasses);
  }
  pfglDisable(GL_SCISSOR_TEST);
  pfglAccum(GL_RETURN, 1.0f);
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 32; ++x)
      for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(px[(static_cast<size_t>(y) * 32 + x) * 4 + k], sum[x][k] / kPasses, 1.0) << x << "," << y << " " << k;
  release(ctx);
}

// The buffer follows the drawable: bound again at another size it covers the whole new
// framebuffer (cleared to 0), and the old contents are gone.
TEST(Accumulation, BufferFollowsTheDrawable) {
  std::vector<unsigned char> px;
  PFcontext ctx = accumContext(px, 8, 8, 16);
  ASSERT_NE(ctx, nullptr);
  pfglClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglAccum(GL_LOAD, 1.0f);
  std::vector<unsigned char> bigger(40 * 24 * 4, 0);
  ASSERT_TRUE(pfMakeCurrent(ctx, bigger.data(), GL_UNSIGNED_BYTE, 40, 24));
  pfglClearColor(0.5f, 0.25f, 0.75f, 1.0f);
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglAccum(GL_RETURN, 1.0f);  // a zero buffer: black everywhere
  pfglFinish();
  for (size_t i = 0; i < bigger.size(); ++i) ASSERT_EQ(bigger[i], 0) << i;
  pfglClearColor(0.5f, 0.25f, 0.75f, 1.0f);
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglAccum(GL_LOAD, 1.0f);
  pfglAccum(GL_MULT, 0.5f);
  pfglAccum(GL_RETURN, 2.0f);
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  for (size_t i = 0; i < bigger.size(); i += 4) {  // 128 / 255 halved and doubled: within a step
    ASSERT_NEAR(bigger[i], 128, 1) << i;
    ASSERT_NEAR(bigger[i + 3], 255, 1) << i;
  }
  release(ctx);
}

}  // namespace
