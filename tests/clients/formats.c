/* formats.c -- client suite (tests/clients): one lit scene drawn into the caller's buffer in an
 * OSMesa format and type (OSMESA_RGBA / BGRA / ARGB / RGB / RGB_565 x GL_UNSIGNED_BYTE /
 * GL_UNSIGNED_SHORT / GL_FLOAT / GL_UNSIGNED_SHORT_5_6_5), with OSMESA_Y_UP and
 * OSMESA_ROW_LENGTH, and the buffer dumped byte for byte -- so that pfclientcompare can hold
 * libprimflow-osmesa's layout against OSMesa's. Also dumps OSMesaGetDepthBuffer's bytes.
 * Usage: formats FORMAT TYPE Y_UP ROW_LENGTH DEPTH_BITS OUT.raw [DEPTH.raw]
 *   FORMAT rgba|bgra|argb|rgb|565, TYPE ubyte|ushort|float|565 */
#include <GL/osmesa.h>
#include <GL/glu.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WIDTH 64
#define HEIGHT 48

static GLenum parse(const char *s) {
  if (!strcmp(s, "rgba")) return OSMESA_RGBA;
  if (!strcmp(s, "bgra")) return OSMESA_BGRA;
  if (!strcmp(s, "argb")) return OSMESA_ARGB;
  if (!strcmp(s, "rgb")) return OSMESA_RGB;
  if (!strcmp(s, "565")) return OSMESA_RGB_565;
  if (!strcmp(s, "ubyte")) return GL_UNSIGNED_BYTE;
  if (!strcmp(s, "ushort")) return GL_UNSIGNED_SHORT;
  if (!strcmp(s, "float")) return GL_FLOAT;
  if (!strcmp(s, "ushort565")) return GL_UNSIGNED_SHORT_5_6_5;
  return 0;
}

static int dump(const char *path, GLenum format, GLenum type, int row, int y_up, const void *data, size_t bytes) {
  FILE *f = fopen(path, "wb");
  if (!f) return 0;
  fprintf(f, "PFRAW %x %x %d %d %d %d %zu\n", format, type, WIDTH, HEIGHT, row, y_up, bytes);
  fwrite(data, 1, bytes, f);
  return fclose(f) == 0;
}

static void draw(void) {
  static const GLfloat light[4] = {1.0f, 2.0f, 3.0f, 0.0f};
  GLUquadric *q = gluNewQuadric();
  glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (double)WIDTH / HEIGHT, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -4.0f);
  /* an unlit triangle with a colour per corner, half transparent in alpha */
  glBegin(GL_TRIANGLES);
  glColor4f(1.0f, 0.0f, 0.0f, 1.0f);
  glVertex3f(-1.8f, -1.2f, -1.0f);
  glColor4f(0.0f, 1.0f, 0.0f, 0.5f);
  glVertex3f(1.8f, -1.2f, 0.5f);
  glColor4f(0.0f, 0.0f, 1.0f, 0.25f);
  glVertex3f(0.0f, 1.4f, -0.5f);
  glEnd();
  /* a lit sphere through it */
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glColor3f(0.9f, 0.7f, 0.2f);
  gluSphere(q, 0.8, 16, 12);
  gluDeleteQuadric(q);
  glFinish();
}

int main(int argc, char *argv[]) {
  GLenum format, type;
  int y_up, row, depth_bits, pixel_bytes;
  size_t bytes;
  unsigned char *buffer;
  OSMesaContext ctx;
  GLint w, h, per;
  void *depth;
  if (argc < 7) {
    fprintf(stderr, "usage: %s FORMAT TYPE Y_UP ROW_LENGTH DEPTH_BITS OUT.raw [DEPTH.raw]\n", argv[0]);
    return 2;
  }
  format = parse(argv[1]);
  type = parse(argv[2]);
  y_up = atoi(argv[3]);
  row = atoi(argv[4]);
  depth_bits = atoi(argv[5]);
  pixel_bytes = (format == OSMESA_RGB ? 3 : format == OSMESA_RGB_565 ? 1 : 4) *
                (type == GL_UNSIGNED_BYTE ? 1 : type == GL_FLOAT ? 4 : 2);
  bytes = (size_t)(row > WIDTH ? row : WIDTH) * HEIGHT * pixel_bytes;
  buffer = (unsigned char *)malloc(bytes);
  if (!buffer) return 1;
  memset(buffer, 0xEE, bytes); /* what the context does not write stays so */
  ctx = OSMesaCreateContextExt(format, depth_bits, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, type, WIDTH, HEIGHT)) {
    fprintf(stderr, "no context for this format and type\n");
    return 1;
  }
  printf("%s\n", (const char *)glGetString(GL_RENDERER));
  OSMesaPixelStore(OSMESA_Y_UP, y_up);
  OSMesaPixelStore(OSMESA_ROW_LENGTH, row);
  draw();
  if (!dump(argv[6], format, type, row, y_up, buffer, bytes)) return 1;
  if (argc > 7) {
    if (!OSMesaGetDepthBuffer(ctx, &w, &h, &per, &depth)) return 1;
    if (!dump(argv[7], 0, 0, 0, 1, depth, (size_t)w * h * per)) return 1;
  }
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(ctx);
  free(buffer);
  return 0;
}
