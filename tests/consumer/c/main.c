/* A minimal primflow application in C99, GL source unchanged through <primflow/gl_mangle.h>: a
 * 64x64 context, a clear, a red triangle drawn from a display list twice (moved between the
 * calls), and a check of three pixels. Exit status 0 when the image is right. */
#include <primflow/gl_mangle.h>

#include <stdio.h>

static int check(const unsigned char *px, int w, int x, int y, const unsigned char want[4], const char *what) {
  const unsigned char *p = &px[((size_t)y * (size_t)w + (size_t)x) * 4];
  if (p[0] == want[0] && p[1] == want[1] && p[2] == want[2] && p[3] == want[3]) return 0;
  fprintf(stderr, "c consumer: %s pixel (%d, %d) is (%d, %d, %d, %d), expected (%d, %d, %d, %d)\n", what, x, y, p[0],
          p[1], p[2], p[3], want[0], want[1], want[2], want[3]);
  return 1;
}

int main(void) {
  enum { W = 64, H = 64 };
  static unsigned char pixels[W * H * 4];
  static const unsigned char red[4] = {255, 0, 0, 255}, blue[4] = {0, 0, 255, 255};
  int failures = 0;
  GLuint list;
  GLenum error;
  PFcontext ctx = pfCreateContext(GL_RGBA, 24);
  if (!ctx || !pfMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, W, H)) {
    fprintf(stderr, "c consumer: no context\n");
    return 1;
  }
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 0.0f, 0.0f);
  glVertex2f(2.0f, 2.0f);
  glVertex2f(30.0f, 2.0f);
  glVertex2f(2.0f, 30.0f);
  glEnd();
  glEndList();
  glCallList(list);
  glTranslatef(32.0f, 32.0f, 0.0f);
  glCallList(list);
  glFinish();
  error = glGetError();
  if (error != GL_NO_ERROR) {
    fprintf(stderr, "c consumer: glGetError() = 0x%04x\n", error);
    ++failures;
  }
  failures += check(pixels, W, 6, 6, red, "first triangle");
  failures += check(pixels, W, 38, 38, red, "second triangle");
  failures += check(pixels, W, 60, 10, blue, "background");
  pfMakeCurrent(NULL, NULL, 0, 0, 0);
  pfDestroyContext(ctx);
  if (failures == 0) printf("c consumer: ok\n");
  return failures == 0 ? 0 : 1;
}
