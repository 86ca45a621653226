// Test helper: a primflow context over a width x height RGBA8 buffer (with a 24-bit depth
// buffer), current on this thread for the helper's lifetime.
#pragma once

#include <primflow/gl.h>

#include <vector>

namespace pf::test {

struct GlContext {
  PFcontext ctx;
  int width, height;
  std::vector<unsigned char> px;
  GlContext(int w, int h) : ctx(pfCreateContext(GL_RGBA, 24)), width(w), height(h), px(size_t(w) * h * 4) {
    pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, w, h);
  }
  ~GlContext() {
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
    pfDestroyContext(ctx);
  }
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;
  const unsigned char* at(int x, int y) const { return &px[(size_t(y) * width + x) * 4]; }
  // The depth buffer (floats, window depth, row 0 at the bottom); nullptr if there is none.
  const float* depth() const {
    GLint w, h, bits;
    void* data = nullptr;
    return pfGetDepthBuffer(ctx, &w, &h, &bits, &data) ? static_cast<const float*>(data) : nullptr;
  }
};

// Window coordinates as object coordinates: a w x h viewport, an orthographic projection of it.
inline void windowOrtho(int w, int h) {
  pfglViewport(0, 0, w, h);
  pfglMatrixMode(GL_PROJECTION);
  pfglLoadIdentity();
  pfglOrtho(0, w, 0, h, -1, 1);
  pfglMatrixMode(GL_MODELVIEW);
  pfglLoadIdentity();
}

}  // namespace pf::test
