// The benchmark scenes drawn by OSMesa (llvmpipe), the reference.
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <chrono>
#include <vector>

#include "bench/scene_data.h"

#include "bench/scenes.inc"

namespace pfbench {

std::vector<double> timeOsmesa(const SceneData& s, int warmup, int frames, std::vector<unsigned char>* image) {
  std::vector<double> times;
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!ctx) return times;
  std::vector<unsigned char> buffer(static_cast<size_t>(s.width) * s.height * 4);
  if (!OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, s.width, s.height)) {
    OSMesaDestroyContext(ctx);
    return times;
  }
  for (int i = 0; i < warmup + frames; ++i) {
    auto t0 = std::chrono::steady_clock::now();
    drawSceneFrame(s);
    auto t1 = std::chrono::steady_clock::now();
    if (i >= warmup) times.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
  }
  if (image) *image = readFrame(s);
  OSMesaDestroyContext(ctx);
  return times;
}

}  // namespace pfbench
