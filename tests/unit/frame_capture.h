// Test helper for the implicit-surface image tests: a primflow context with a given rasterizer
// thread count and native code on or off (PF_THREADS, PF_JIT), current for its lifetime over an
// RGBA8 frame, whose colour and float depth buffer finish() captures -- what the tests compare
// with references and with each other across thread counts and executors.
#pragma once

#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <vector>

namespace pf::test {

struct CapturedFrame {
  std::vector<unsigned char> rgba;
  std::vector<float> depth;  // window depth, row 0 at the bottom
};

class FrameCapture {
 public:
  FrameCapture(int width, int height, int threads, int native) : width_(width), height_(height) {
    const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, threads, PF_JIT, native, 0};
    ctx_ = pfCreateContextAttribs(attribs);
    frame_.rgba.resize(static_cast<size_t>(width) * height * 4);
    pfMakeCurrent(ctx_, frame_.rgba.data(), GL_UNSIGNED_BYTE, width, height);
  }
  ~FrameCapture() {
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
    pfDestroyContext(ctx_);
  }
  FrameCapture(const FrameCapture&) = delete;
  FrameCapture& operator=(const FrameCapture&) = delete;

  // glFinish, no GL error expected, and the frame with its depth buffer.
  CapturedFrame finish() {
    pfglFinish();
    EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
    GLint w, h, bits;
    void* data = nullptr;
    EXPECT_TRUE(pfGetDepthBuffer(ctx_, &w, &h, &bits, &data));
    if (data) {
      const float* d = static_cast<const float*>(data);
      frame_.depth.assign(d, d + static_cast<size_t>(width_) * height_);
    }
    return frame_;
  }

 private:
  PFcontext ctx_;
  int width_, height_;
  CapturedFrame frame_;
};

// The view of the image tests: orthographic onto [-1, 1]^2 looking down -z at the box [-1, 1]^3
// from 2 units away, so a pixel's centre is x, y = -1 + (i + 0.5) 2 / size and its window depth d
// the point z = 1 - 2 d.
inline void viewUnitBoxFromAbove() {
  pfglMatrixMode(GL_PROJECTION);
  pfglLoadIdentity();
  pfglOrtho(-1, 1, -1, 1, 1, 3);
  pfglMatrixMode(GL_MODELVIEW);
  pfglLoadIdentity();
  pfglTranslated(0, 0, -2);
}

}  // namespace pf::test
