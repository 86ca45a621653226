// Example 1, OSMesa side: the same cube_scene.inc compiled against <GL/gl.h> and drawn by
// OSMesa (llvmpipe), for comparison with lit_cube_primflow's image.
//   lit_cube_osmesa [output.png]
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <cstdio>
#include <string>
#include <vector>

#include "frames.h"
#include "png_image.h"

#include "cube_scene.inc"

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "lit_cube_osmesa.png";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  std::vector<uint8_t> frame(static_cast<size_t>(kSize) * kSize * 4), strip(frame.size() * kFrames);
  if (!ctx || !OSMesaMakeCurrent(ctx, frame.data(), GL_UNSIGNED_BYTE, kSize, kSize)) {
    std::fprintf(stderr, "lit_cube_osmesa: no OSMesa context\n");
    return 1;
  }
  for (int f = 0; f < kFrames; ++f) {
    drawCubeFrame(f, kSize, kSize);
    placeFrame(strip, frame, f);
  }
  OSMesaDestroyContext(ctx);
  std::string message;
  if (!pf::writePngBottomUp(out, strip.data(), kSize * kFrames, kSize, &message)) {
    std::fprintf(stderr, "lit_cube_osmesa: %s\n", message.c_str());
    return 1;
  }
  std::printf("wrote %s\n", out.c_str());
  return 0;
}
