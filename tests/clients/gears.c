/* gears.c -- client suite (tests/clients): three gears in the shape of glxgears -- each gear
 * compiled once into a display list (glGenLists / glNewList / glCallList), flat-shaded faces
 * and smooth teeth, one light, glFrustum -- drawn offscreen and written to a file. Built three
 * ways (tests/clients/CMakeLists.txt); no GLU. Usage: gears OUT.pam [DEPTH] */
#ifdef PF_CLIENT_MANGLE
#include <primflow/gl_mangle.h>
#else
#include <GL/osmesa.h>
#endif
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "client_output.h"

#define WIDTH 300
#define HEIGHT 300

/* A gear: inner radius, outer radius at the teeth's root, width, tooth count, tooth depth. */
static void gear(GLfloat inner, GLfloat outer, GLfloat width, GLint teeth, GLfloat tooth_depth) {
  const GLfloat r0 = inner, r1 = outer - tooth_depth / 2.0f, r2 = outer + tooth_depth / 2.0f;
  const GLfloat da = 2.0f * (GLfloat)M_PI / teeth / 4.0f;
  GLint i;

  glShadeModel(GL_FLAT);
  glNormal3f(0.0f, 0.0f, 1.0f);
  /* front face */
  glBegin(GL_QUAD_STRIP);
  for (i = 0; i <= teeth; i++) {
    const GLfloat angle = i * 2.0f * (GLfloat)M_PI / teeth;
    glVertex3f(r0 * cosf(angle), r0 * sinf(angle), width * 0.5f);
    glVertex3f(r1 * cosf(angle), r1 * sinf(angle), width * 0.5f);
    if (i < teeth) {
      glVertex3f(r0 * cosf(angle), r0 * sinf(angle), width * 0.5f);
      glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), width * 0.5f);
    }
  }
  glEnd();
  /* front sides of the teeth */
  glBegin(GL_QUADS);
  for (i = 0; i < teeth; i++) {
    const GLfloat angle = i * 2.0f * (GLfloat)M_PI / teeth;
    glVertex3f(r1 * cosf(angle), r1 * sinf(angle), width * 0.5f);
    glVertex3f(r2 * cosf(angle + da), r2 * sinf(angle + da), width * 0.5f);
    glVertex3f(r2 * cosf(angle + 2 * da), r2 * sinf(angle + 2 * da), width * 0.5f);
    glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), width * 0.5f);
  }
  glEnd();

  glNormal3f(0.0f, 0.0f, -1.0f);
  /* back face */
  glBegin(GL_QUAD_STRIP);
  for (i = 0; i <= teeth; i++) {
    const GLfloat angle = i * 2.0f * (GLfloat)M_PI / teeth;
    glVertex3f(r1 * cosf(angle), r1 * sinf(angle), -width * 0.5f);
    glVertex3f(r0 * cosf(angle), r0 * sinf(angle), -width * 0.5f);
    if (i < teeth) {
      glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), -width * 0.5f);
      glVertex3f(r0 * cosf(angle), r0 * sinf(angle), -width * 0.5f);
    }
  }
  glEnd();
  /* back sides of the teeth */
  glBegin(GL_QUADS);
  for (i = 0; i < teeth; i++) {
    const GLfloat angle = i * 2.0f * (GLfloat)M_PI / teeth;
    glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), -width * 0.5f);
    glVertex3f(r2 * cosf(angle + 2 * da), r2 * sinf(angle + 2 * da), -width * 0.5f);
    glVertex3f(r2 * cosf(angle + da), r2 * sinf(angle + da), -width * 0.5f);
    glVertex3f(r1 * cosf(angle), r1 * sinf(angle), -width * 0.5f);
  }
  glEnd();

  /* outward faces of the teeth */
  glBegin(GL_QUAD_STRIP);
  for (i = 0; i < teeth; i++) {
    const GLfloat angle = i * 2.0f * (GLfloat)M_PI / teeth;
    GLfloat u, v, len;
    glVertex3f(r1 * cosf(angle), r1 * sinf(angle), width * 0.5f);
    glVertex3f(r1 * cosf(angle), r1 * sinf(angle), -width * 0.5f);
    u = r2 * cosf(angle + da) - r1 * cosf(angle);
    v = r2 * sinf(angle + da) - r1 * sinf(angle);
    len = sqrtf(u * u + v * v);
    glNormal3f(v / len, -u / len, 0.0f);
    glVertex3f(r2 * cosf(angle + da), r2 * sinf(angle + da), width * 0.5f);
    glVertex3f(r2 * cosf(angle + da), r2 * sinf(angle + da), -width * 0.5f);
    glNormal3f(cosf(angle), sinf(angle), 0.0f);
    glVertex3f(r2 * cosf(angle + 2 * da), r2 * sinf(angle + 2 * da), width * 0.5f);
    glVertex3f(r2 * cosf(angle + 2 * da), r2 * sinf(angle + 2 * da), -width * 0.5f);
    u = r1 * cosf(angle + 3 * da) - r2 * cosf(angle + 2 * da);
    v = r1 * sinf(angle + 3 * da) - r2 * sinf(angle + 2 * da);
    glNormal3f(v, -u, 0.0f);
    glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), width * 0.5f);
    glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), -width * 0.5f);
    glNormal3f(cosf(angle), sinf(angle), 0.0f);
  }
  glVertex3f(r1, 0.0f, width * 0.5f);
  glVertex3f(r1, 0.0f, -width * 0.5f);
  glEnd();

  glShadeModel(GL_SMOOTH);
  /* the hole's inside */
  glBegin(GL_QUAD_STRIP);
  for (i = 0; i <= teeth; i++) {
    const GLfloat angle = i * 2.0f * (GLfloat)M_PI / teeth;
    glNormal3f(-cosf(angle), -sinf(angle), 0.0f);
    glVertex3f(r0 * cosf(angle), r0 * sinf(angle), -width * 0.5f);
    glVertex3f(r0 * cosf(angle), r0 * sinf(angle), width * 0.5f);
  }
  glEnd();
}

static GLuint gear1, gear2, gear3;

static void init(void) {
  static GLfloat pos[4] = {5.0f, 5.0f, 10.0f, 0.0f};
  static GLfloat red[4] = {0.8f, 0.1f, 0.0f, 1.0f};
  static GLfloat green[4] = {0.0f, 0.8f, 0.2f, 1.0f};
  static GLfloat blue[4] = {0.2f, 0.2f, 1.0f, 1.0f};

  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glEnable(GL_CULL_FACE);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);

  gear1 = glGenLists(3);
  gear2 = gear1 + 1;
  gear3 = gear1 + 2;
  glNewList(gear1, GL_COMPILE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
  gear(1.0f, 4.0f, 1.0f, 20, 0.7f);
  glEndList();
  glNewList(gear2, GL_COMPILE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, green);
  gear(0.5f, 2.0f, 2.0f, 10, 0.7f);
  glEndList();
  glNewList(gear3, GL_COMPILE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blue);
  gear(1.3f, 2.0f, 0.5f, 10, 0.7f);
  glEndList();
  glEnable(GL_NORMALIZE);
}

static void reshape(int width, int height) {
  const GLfloat h = (GLfloat)height / (GLfloat)width;
  glViewport(0, 0, (GLint)width, (GLint)height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -h, h, 5.0, 60.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -40.0f);
}

static void draw(GLfloat view_rotx, GLfloat view_roty, GLfloat angle) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glPushMatrix();
  glRotatef(view_rotx, 1.0f, 0.0f, 0.0f);
  glRotatef(view_roty, 0.0f, 1.0f, 0.0f);

  glPushMatrix();
  glTranslatef(-3.0f, -2.0f, 0.0f);
  glRotatef(angle, 0.0f, 0.0f, 1.0f);
  glCallList(gear1);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(3.1f, -2.0f, 0.0f);
  glRotatef(-2.0f * angle - 9.0f, 0.0f, 0.0f, 1.0f);
  glCallList(gear2);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(-3.1f, 4.2f, 0.0f);
  glRotatef(-2.0f * angle - 25.0f, 0.0f, 0.0f, 1.0f);
  glCallList(gear3);
  glPopMatrix();

  glPopMatrix();
}

int main(int argc, char *argv[]) {
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
  ctx = pfCreateContext(GL_RGBA, 16);
#else
  ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
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

  init();
  reshape(WIDTH, HEIGHT);
  draw(20.0f, 30.0f, 10.0f);
  glFinish();

  if (!client_write_pam(argv[1], WIDTH, HEIGHT, buffer)) return 1;
#ifdef PF_CLIENT_MANGLE
  if (pfGetDepthBuffer(ctx, &w, &h, &bytes, &depth)) z = client_depth_to_float(depth, w, h, bytes, 1);
#else
  if (OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, &depth)) z = client_depth_to_float(depth, w, h, bytes, 0);
#endif
  if (argc > 2 && (!z || !client_write_depth(argv[2], w, h, z))) return 1;
  ok = glGetError() == GL_NO_ERROR;
  glDeleteLists(gear1, 3);
  free(z);
  free(buffer);
#ifdef PF_CLIENT_MANGLE
  pfDestroyContext(ctx);
#else
  OSMesaDestroyContext(ctx);
#endif
  return ok ? 0 : 3;
}
