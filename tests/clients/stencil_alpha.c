/* stencil_alpha.c -- client suite (tests/clients): the Red Book's stencil.c and alpha3D.c in
 * one offscreen program: a diamond written into the stencil buffer (colour writes off), then
 * lit boxes drawn one colour where the stencil holds 1 and another where it does not; over them
 * translucent boxes blended with GL_SRC_ALPHA / GL_ONE_MINUS_SRC_ALPHA, depth writes off, and a
 * scissored band cleared. A context with 24 depth and 8 stencil bits. Built three ways
 * (tests/clients/CMakeLists.txt); no GLU. Usage: stencil_alpha OUT.pam [DEPTH] */
#ifdef PF_CLIENT_MANGLE
#include <primflow/gl_mangle.h>
#else
#include <GL/osmesa.h>
#endif
#include "client_context.h"
#include "client_cube.h"

#define WIDTH 256
#define HEIGHT 200

static void boxes(const GLfloat colour[4], GLfloat turn) {
  int i;
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, colour);
  for (i = 0; i < 3; ++i) {
    glPushMatrix();
    glTranslatef(-1.6f + 1.6f * i, 0.2f * i - 0.2f, -0.5f * i);
    glRotatef(turn + 25.0f * i, 0.3f, 1.0f, 0.2f);
    glScalef(0.9f, 1.4f - 0.3f * i, 0.7f);
    client_unit_cube();
    glPopMatrix();
  }
}

int main(int argc, char *argv[]) {
  static const GLfloat light_position[4] = {-2.0f, 3.0f, 4.0f, 1.0f};
  static const GLfloat inside[4] = {0.9f, 0.4f, 0.2f, 1.0f}, outside[4] = {0.2f, 0.5f, 0.9f, 1.0f};
  static const GLfloat glass[4] = {0.3f, 0.9f, 0.4f, 0.45f};
  client_context c;
  if (!client_begin(&c, argc, argv, WIDTH, HEIGHT, 24, 8)) return argc < 2 ? 2 : 1;

  glClearColor(0.85f, 0.85f, 0.8f, 1.0f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

  /* The diamond, into the stencil buffer only (window coordinates). */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, WIDTH, 0, HEIGHT, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glBegin(GL_QUADS);
  glVertex2f(WIDTH / 2.0f, 55.0f);
  glVertex2f(WIDTH - 70.0f, HEIGHT / 2.0f);
  glVertex2f(WIDTH / 2.0f, HEIGHT - 55.0f);
  glVertex2f(70.0f, HEIGHT / 2.0f);
  glEnd();
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);

  /* The lit boxes: one colour inside the diamond, another outside. */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -(GLdouble)HEIGHT / WIDTH, (GLdouble)HEIGHT / WIDTH, 1.5, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, light_position);
  glTranslatef(0.0f, 0.0f, -6.0f);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  boxes(inside, 20.0f);
  glStencilFunc(GL_NOTEQUAL, 1, 0xff);
  boxes(outside, 20.0f);
  glDisable(GL_STENCIL_TEST);

  /* Translucent boxes in front, blended, without depth writes. */
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glPushMatrix();
  glTranslatef(0.4f, -0.3f, 1.2f);
  boxes(glass, -30.0f);
  glPopMatrix();
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);

  /* A band cleared under the scissor box. */
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, HEIGHT - 24, WIDTH, 12);
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glFinish();

  return client_end(&c, argc, argv);
}
