/* glu_scene.c -- client suite (tests/clients): a GLU program -- gluPerspective, gluLookAt, and the
 * quadrics gluSphere, gluCylinder, gluDisk and gluPartialDisk with smooth and flat normals and
 * inside orientation -- lit by two lights, drawn offscreen and written to a file. The system
 * libGLU calls gl*: with libprimflow-osmesa (linked, or as libOSMesa.so.8 on LD_LIBRARY_PATH)
 * those calls must reach primflow, or this image stays empty. Built three ways
 * (tests/clients/CMakeLists.txt). Usage: glu_scene OUT.pam [DEPTH] */
#ifdef PF_CLIENT_MANGLE
#include <primflow/gl_mangle.h>
#else
#include <GL/osmesa.h>
#endif
#include <GL/glu.h>
#include <stdio.h>
#include <stdlib.h>

#include "client_output.h"

#define WIDTH 320
#define HEIGHT 240

static void material(GLfloat r, GLfloat g, GLfloat b) {
  const GLfloat colour[4] = {r, g, b, 1.0f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, colour);
}

static void draw_scene(GLUquadric *smooth, GLUquadric *flat) {
  /* the floor: a disk with a hole, facing up */
  glPushMatrix();
  glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
  material(0.6f, 0.6f, 0.55f);
  gluDisk(smooth, 0.5, 4.0, 40, 4);
  glPopMatrix();

  /* a smooth sphere and a faceted one */
  glPushMatrix();
  glTranslatef(-1.2f, 0.8f, 0.0f);
  material(0.9f, 0.3f, 0.2f);
  gluSphere(smooth, 0.8, 24, 16);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(1.3f, 0.6f, 0.8f);
  material(0.3f, 0.8f, 0.4f);
  gluSphere(flat, 0.6, 10, 8);
  glPopMatrix();

  /* a capped cylinder standing up, and a cone lying down */
  glPushMatrix();
  glTranslatef(0.6f, 0.0f, -1.5f);
  glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
  material(0.3f, 0.4f, 0.9f);
  gluCylinder(smooth, 0.5, 0.5, 1.6, 20, 3);
  glTranslatef(0.0f, 0.0f, 1.6f);
  gluDisk(smooth, 0.0, 0.5, 20, 1);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(-0.3f, 0.35f, 1.5f);
  glRotatef(70.0f, 0.0f, 1.0f, 0.0f);
  material(0.9f, 0.8f, 0.2f);
  gluCylinder(smooth, 0.35, 0.0, 1.2, 16, 2);
  glPopMatrix();

  /* a partial disk standing behind, seen from its inside */
  glPushMatrix();
  glTranslatef(-1.5f, 1.0f, -2.0f);
  gluQuadricOrientation(smooth, GLU_INSIDE);
  material(0.7f, 0.3f, 0.8f);
  gluPartialDisk(smooth, 0.3, 1.0, 24, 2, 30.0, 240.0);
  gluQuadricOrientation(smooth, GLU_OUTSIDE);
  glPopMatrix();
}

int main(int argc, char *argv[]) {
  static const GLfloat key[4] = {3.0f, 5.0f, 4.0f, 1.0f};
  static const GLfloat fill[4] = {-4.0f, 2.0f, -1.0f, 0.0f};
  static const GLfloat fill_colour[4] = {0.25f, 0.25f, 0.35f, 1.0f};
  static const GLfloat specular[4] = {0.6f, 0.6f, 0.6f, 1.0f};
  GLUquadric *smooth, *flat;
  GLubyte *buffer;
  GLint w = 0, h = 0, bytes = 0;
  void *depth = NULL;
  float *z = NULL;
  int ok;
#ifdef PF_CLIENT_MANGLE
  PFcontext ctx;
#else
  OSMesaContext ctx;
#endif
  if (argc < 2) {
    fprintf(stderr, "usage: %s OUT.pam [DEPTH]\n", argv[0]);
    return 2;
  }
#ifdef PF_CLIENT_MANGLE
  ctx = pfCreateContext(GL_RGBA, 24);
#else
  ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
#endif
  buffer = (GLubyte *)malloc(WIDTH * HEIGHT * 4);
  if (!ctx || !buffer) return 1;
#ifdef PF_CLIENT_MANGLE
  ok = pfMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, WIDTH, HEIGHT);
#else
  ok = OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, WIDTH, HEIGHT);
#endif
  if (!ok) return 1;
  printf("%s\n", (const char *)glGetString(GL_RENDERER));

  glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0f);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, (GLdouble)WIDTH / HEIGHT, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(2.5, 4.0, 7.0, 0.0, 0.5, 0.0, 0.0, 1.0, 0.0);
  glLightfv(GL_LIGHT0, GL_POSITION, key);
  glLightfv(GL_LIGHT1, GL_POSITION, fill);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, fill_colour);

  smooth = gluNewQuadric();
  flat = gluNewQuadric();
  if (!smooth || !flat) return 1;
  gluQuadricNormals(smooth, GLU_SMOOTH);
  gluQuadricNormals(flat, GLU_FLAT);
  draw_scene(smooth, flat);
  gluDeleteQuadric(smooth);
  gluDeleteQuadric(flat);
  glFinish();

  if (!client_write_pam(argv[1], WIDTH, HEIGHT, buffer)) return 1;
#ifdef PF_CLIENT_MANGLE
  if (pfGetDepthBuffer(ctx, &w, &h, &bytes, &depth)) z = client_depth_to_float(depth, w, h, bytes, 1);
#else
  if (OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, &depth)) z = client_depth_to_float(depth, w, h, bytes, 0);
#endif
  if (argc > 2 && (!z || !client_write_depth(argv[2], w, h, z))) return 1;
  ok = glGetError() == GL_NO_ERROR;
  free(z);
  free(buffer);
#ifdef PF_CLIENT_MANGLE
  pfDestroyContext(ctx);
#else
  OSMesaDestroyContext(ctx);
#endif
  return ok ? 0 : 3;
}
