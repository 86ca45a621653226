// A minimal primflow application: a 64x64 context, a clear, one coloured triangle, and a check
// of two pixels. Exit status 0 when the image is right.
#include <primflow/gl.h>

#include <cstdio>
#include <vector>

namespace {

int check(const std::vector<unsigned char>& px, int w, int x, int y, const unsigned char (&want)[4],
          const char* what) {
  const unsigned char* p = &px[(static_cast<size_t>(y) * w + x) * 4];
  if (p[0] == want[0] && p[1] == want[1] && p[2] == want[2] && p[3] == want[3]) return 0;
  std::fprintf(stderr, "consumer: %s pixel (%d, %d) is (%d, %d, %d, %d), expected (%d, %d, %d, %d)\n",
               what, x, y, p[0], p[1], p[2], p[3], want[0], want[1], want[2], want[3]);
  return 1;
}

}  // namespace

int main() {
  const int w = 64, h = 64;
  std::vector<unsigned char> pixels(static_cast<size_t>(w) * h * 4, 0x5a);

  PFcontext ctx = pfCreateContext(GL_RGBA, 24);
  if (!ctx) {
    std::fprintf(stderr, "consumer: pfCreateContext failed\n");
    return 1;
  }
  if (!pfMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, w, h)) {
    std::fprintf(stderr, "consumer: pfMakeCurrent failed\n");
    pfDestroyContext(ctx);
    return 1;
  }

  pfglViewport(0, 0, w, h);
  pfglMatrixMode(GL_PROJECTION);
  pfglLoadIdentity();
  pfglMatrixMode(GL_MODELVIEW);
  pfglLoadIdentity();
  pfglClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglBegin(GL_TRIANGLES);
  pfglColor3f(1.0f, 0.0f, 0.0f);
  pfglVertex3f(-0.8f, -0.8f, 0.0f);
  pfglVertex3f(0.8f, -0.8f, 0.0f);
  pfglVertex3f(0.0f, 0.8f, 0.0f);
  pfglEnd();
  pfglFinish();

  int failures = 0;
  GLenum error = pfglGetError();
  if (error != GL_NO_ERROR) {
    std::fprintf(stderr, "consumer: glGetError() = 0x%04x\n", error);
    ++failures;
  }
  const unsigned char red[4] = {255, 0, 0, 255};
  const unsigned char blue[4] = {0, 0, 255, 255};
  failures += check(pixels, w, w / 2, h / 2, red, "centre");
  failures += check(pixels, w, 0, h - 1, blue, "top-left corner");
  failures += check(pixels, w, w - 1, 0, blue, "bottom-right corner");

  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
  if (failures == 0) std::printf("consumer: ok\n");
  return failures == 0 ? 0 : 1;
}
