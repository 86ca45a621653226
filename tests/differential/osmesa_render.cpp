// The differential scenes rendered by OSMesa (Mesa's llvmpipe), the reference GL.
// fan_scene.inc's gl* calls go to libOSMesa here.
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "differential/scenes.h"

#include "differential/fan_scene.inc"

namespace pfdiff {

Image renderOsmesa(Scene scene, int width, int height) {
  Image img;
  img.width = width;
  img.height = height;
  img.rgba.assign(static_cast<size_t>(width) * height * 4, 0);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  if (!ctx) return img;
  if (!OSMesaMakeCurrent(ctx, img.rgba.data(), GL_UNSIGNED_BYTE, width, height)) {
    OSMesaDestroyContext(ctx);
    return img;
  }
  drawScene(scene, width, height);  // ends with glFinish: the buffers are written
  GLint dw = 0, dh = 0, bytes = 0;
  void* depth = nullptr;
  if (OSMesaGetDepthBuffer(ctx, &dw, &dh, &bytes, &depth) && depth && dw == width && dh == height) {
    img.depth.resize(static_cast<size_t>(width) * height);
    for (size_t i = 0; i < img.depth.size(); ++i) {
      if (bytes == 4) {  // 24 bits in the low bits of 32
        uint32_t z = static_cast<const uint32_t*>(depth)[i] & 0xFFFFFFu;
        img.depth[i] = z / double(0xFFFFFF);
      } else if (bytes == 2) {
        img.depth[i] = static_cast<const uint16_t*>(depth)[i] / double(0xFFFF);
      }
    }
  }
  OSMesaMakeCurrent(NULL, NULL, GL_UNSIGNED_BYTE, 0, 0);
  OSMesaDestroyContext(ctx);
  img.ok = true;
  return img;
}

}  // namespace pfdiff

std::vector<uint8_t> renderFanOsmesa(int w, int h) {
  return pfdiff::renderOsmesa(pfdiff::Scene::FanIds, w, h).rgba;
}
