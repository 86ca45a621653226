// Example 1, primflow side: the lit, rotating cube of cube_scene.inc -- plain GL 1.x, compiled
// unchanged against primflow through <primflow/gl_mangle.h> -- four frames into one PNG.
//   lit_cube_primflow [output.png]
#include <primflow/gl_mangle.h>

#include <cstdio>
#include <string>
#include <vector>

#include "frames.h"
#include "png_image.h"

#include "cube_scene.inc"

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "lit_cube_primflow.png";
  PFcontext ctx = pfCreateContext(GL_RGBA, 24);
  std::vector<uint8_t> frame(static_cast<size_t>(kSize) * kSize * 4), strip(frame.size() * kFrames);
  if (!ctx || !pfMakeCurrent(ctx, frame.data(), GL_UNSIGNED_BYTE, kSize, kSize)) {
    std::fprintf(stderr, "lit_cube_primflow: no primflow context\n");
    return 1;
  }
  for (int f = 0; f < kFrames; ++f) {
    drawCubeFrame(f, kSize, kSize);
    placeFrame(strip, frame, f);
  }
  const GLenum error = glGetError();
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
  std::string message;
  if (error != GL_NO_ERROR || !pf::writePngBottomUp(out, strip.data(), kSize * kFrames, kSize, &message)) {
    std::fprintf(stderr, "lit_cube_primflow: %s\n", error != GL_NO_ERROR ? "GL error" : message.c_str());
    return 1;
  }
  std::printf("wrote %s\n", out.c_str());
  return 0;
}
