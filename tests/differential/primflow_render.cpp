// The differential scenes rendered by primflow: fan_scene.inc's gl* calls are renamed to
// primflow's pfgl* entry points by <primflow/gl_mangle.h>.
#include <primflow/gl_mangle.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "differential/scenes.h"

#include "differential/fan_scene.inc"

namespace pfdiff {

Image renderPrimflow(Scene scene, int width, int height, int threads) {
  Image img;
  img.width = width;
  img.height = height;
  img.rgba.assign(static_cast<size_t>(width) * height * 4, 0);
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, threads, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  if (!ctx) return img;
  if (!pfMakeCurrent(ctx, img.rgba.data(), GL_UNSIGNED_BYTE, width, height)) {
    pfDestroyContext(ctx);
    return img;
  }
  drawScene(scene, width, height);  // ends with glFinish
  GLint dw = 0, dh = 0, bytes = 0;
  void* depth = nullptr;
  if (pfGetDepthBuffer(ctx, &dw, &dh, &bytes, &depth) && depth && dw == width && dh == height &&
      bytes == 4) {
    img.depth.resize(static_cast<size_t>(width) * height);
    for (size_t i = 0; i < img.depth.size(); ++i) img.depth[i] = static_cast<const float*>(depth)[i];
  }
  img.ok = glGetError() == GL_NO_ERROR;
  pfMakeCurrent(NULL, NULL, GL_UNSIGNED_BYTE, 0, 0);
  pfDestroyContext(ctx);
  return img;
}

}  // namespace pfdiff

std::vector<uint8_t> renderFanPrimflow(int w, int h, int threads) {
  return pfdiff::renderPrimflow(pfdiff::Scene::FanIds, w, h, threads).rgba;
}
