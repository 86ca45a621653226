/* accum_blur.c -- client suite (tests/clients): the accumulation buffer as the Red Book uses it
 * (chapter 10, "The Accumulation Buffer"), offscreen: a lit box spinning, blurred by its
 * positions over a shutter interval accumulated with decreasing weights (GL_MULT ages the
 * trail), and a row of boxes antialiased by accpersp.c's jittered frustum, returned over a
 * scissored half of the frame. A context with 24 depth bits and an accumulation buffer (16
 * bits a channel: OSMESA_ACCUM_BITS / PF_ACCUM_BITS). Built three ways
 * (tests/clients/CMakeLists.txt); no GLU. Usage: accum_blur OUT.pam [DEPTH] */
#ifdef PF_CLIENT_MANGLE
#include <primflow/gl_mangle.h>
#else
#include <GL/osmesa.h>
#endif
#define CLIENT_ACCUM_BITS 16
#include "client_context.h"
#include "client_cube.h"

#define WIDTH 240
#define HEIGHT 180

/* accpersp.c's frustum, shifted by (pixdx, pixdy) pixels. */
static void jittered_frustum(double left, double right, double bottom, double top, double znear, double zfar,
                             double pixdx, double pixdy) {
  const double dx = -(pixdx * (right - left) / WIDTH);
  const double dy = -(pixdy * (top - bottom) / HEIGHT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(left + dx, right + dx, bottom + dy, top + dy, znear, zfar);
  glMatrixMode(GL_MODELVIEW);
}

static void box(GLfloat x, GLfloat turn, const GLfloat colour[4]) {
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, colour);
  glPushMatrix();
  glTranslatef(x, 0.0f, -6.0f);
  glRotatef(turn, 0.4f, 1.0f, 0.3f);
  client_unit_cube();
  glPopMatrix();
}

int main(int argc, char *argv[]) {
  static const GLfloat light_position[4] = {-2.0f, 3.0f, 4.0f, 1.0f};
  static const GLfloat warm[4] = {0.9f, 0.5f, 0.2f, 1.0f}, cool[4] = {0.2f, 0.6f, 0.9f, 1.0f};
  static const double jitter[4][2] = {{0.375, 0.25}, {0.125, 0.75}, {0.875, 0.25}, {0.625, 0.75}};
  GLint bits = 0;
  int i;
  client_context c;
  if (!client_begin(&c, argc, argv, WIDTH, HEIGHT, 24, 0)) return argc < 2 ? 2 : 1;
  glGetIntegerv(GL_ACCUM_RED_BITS, &bits);
  if (bits != 16) {
    fprintf(stderr, "accum_blur: GL_ACCUM_RED_BITS is %d, not 16\n", (int)bits);
    return 1;
  }
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, light_position);
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClearAccum(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_ACCUM_BUFFER_BIT);

  /* Motion blur: eight positions of a spinning box moving right; each earlier image is aged
   * by GL_MULT before the next is added. */
  for (i = 0; i < 8; ++i) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    jittered_frustum(-1.2, 1.2, -0.9, 0.9, 2.0, 20.0, 0.0, 0.0);
    glLoadIdentity();
    glTranslatef(-1.5f, 1.0f, 0.0f);
    box(0.12f * i, 12.0f * i, warm);
    glAccum(GL_MULT, 0.8f);
    glAccum(GL_ACCUM, 0.2f);
  }
  glAccum(GL_RETURN, 1.0f);

  /* Antialiasing over the lower half only: the scissor box limits the accumulation too. */
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, WIDTH, HEIGHT / 2);
  glClear(GL_ACCUM_BUFFER_BIT);
  for (i = 0; i < 4; ++i) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    jittered_frustum(-1.2, 1.2, -0.9, 0.9, 2.0, 20.0, jitter[i][0], jitter[i][1]);
    glLoadIdentity();
    glTranslatef(0.0f, -1.1f, 0.0f);
    box(-1.6f, 30.0f, cool);
    box(0.0f, 55.0f, warm);
    box(1.6f, 80.0f, cool);
    glAccum(GL_ACCUM, 0.25f);
  }
  glAccum(GL_RETURN, 1.0f);
  glDisable(GL_SCISSOR_TEST);
  glFinish();
  return client_end(&c, argc, argv);
}
