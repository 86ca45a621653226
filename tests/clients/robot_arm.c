/* robot_arm.c -- client suite (tests/clients): a lit robot arm in the shape of the Red Book's
 * robot.c -- shoulder, elbow and three two-joint fingers, each a box placed with the modelview
 * matrix stack (glPushMatrix / glTranslatef / glRotatef / glScalef / glPopMatrix) -- under
 * glFrustum, drawn offscreen at two poses side by side (two viewports) and written to a file.
 * Built three ways (tests/clients/CMakeLists.txt); no GLU. Usage: robot_arm OUT.pam [DEPTH] */
#ifdef PF_CLIENT_MANGLE
#include <primflow/gl_mangle.h>
#else
#include <GL/osmesa.h>
#endif
#include <stdio.h>
#include <stdlib.h>

#include "client_output.h"

#define WIDTH 320
#define HEIGHT 200

/* A unit cube centred on the origin, each face with its normal. */
static void solid_cube(void) {
  static const GLfloat n[6][3] = {{-1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  static const GLint faces[6][4] = {{0, 1, 2, 3}, {3, 2, 6, 7}, {7, 6, 5, 4}, {4, 5, 1, 0}, {5, 6, 2, 1}, {7, 4, 0, 3}};
  GLfloat v[8][3];
  int i;
  v[0][0] = v[1][0] = v[2][0] = v[3][0] = -0.5f;
  v[4][0] = v[5][0] = v[6][0] = v[7][0] = 0.5f;
  v[0][1] = v[1][1] = v[4][1] = v[5][1] = -0.5f;
  v[2][1] = v[3][1] = v[6][1] = v[7][1] = 0.5f;
  v[0][2] = v[3][2] = v[4][2] = v[7][2] = -0.5f;
  v[1][2] = v[2][2] = v[5][2] = v[6][2] = 0.5f;
  for (i = 5; i >= 0; i--) {
    glBegin(GL_QUADS);
    glNormal3fv(&n[i][0]);
    glVertex3fv(&v[faces[i][0]][0]);
    glVertex3fv(&v[faces[i][1]][0]);
    glVertex3fv(&v[faces[i][2]][0]);
    glVertex3fv(&v[faces[i][3]][0]);
    glEnd();
  }
}

/* A segment of the arm: a box `length` long from the joint, `thickness` across. */
static void segment(GLfloat length, GLfloat thickness) {
  glPushMatrix();
  glTranslatef(length / 2.0f, 0.0f, 0.0f);
  glScalef(length, thickness, thickness);
  solid_cube();
  glPopMatrix();
}

static void finger(GLfloat base_angle, GLfloat tip_angle, GLfloat offset_z) {
  static const GLfloat finger_color[4] = {0.9f, 0.8f, 0.3f, 1.0f};
  glPushMatrix();
  glTranslatef(0.0f, 0.0f, offset_z);
  glRotatef(base_angle, 0.0f, 0.0f, 1.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, finger_color);
  segment(0.5f, 0.15f);
  glTranslatef(0.5f, 0.0f, 0.0f);
  glRotatef(tip_angle, 0.0f, 0.0f, 1.0f);
  segment(0.4f, 0.12f);
  glPopMatrix();
}

static void arm(GLfloat shoulder, GLfloat elbow, GLfloat grip) {
  static const GLfloat upper_color[4] = {0.3f, 0.5f, 0.9f, 1.0f};
  static const GLfloat lower_color[4] = {0.9f, 0.3f, 0.3f, 1.0f};
  glPushMatrix();
  glTranslatef(-1.0f, 0.0f, 0.0f);
  glRotatef(shoulder, 0.0f, 0.0f, 1.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, upper_color);
  segment(2.0f, 0.4f);
  glTranslatef(2.0f, 0.0f, 0.0f);
  glRotatef(elbow, 0.0f, 0.0f, 1.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, lower_color);
  segment(2.0f, 0.3f);
  glTranslatef(2.0f, 0.0f, 0.0f);
  finger(grip, -2.0f * grip, 0.1f);
  finger(-grip, 2.0f * grip, 0.1f);
  finger(grip * 0.5f, -grip, -0.12f);
  glPopMatrix();
}

static void pose(int x, int width, int height, GLfloat shoulder, GLfloat elbow, GLfloat grip, GLfloat turn) {
  glViewport(x, 0, width, height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -(GLdouble)height / width, (GLdouble)height / width, 1.5, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(-1.3f, -0.9f, -4.5f);
  glRotatef(turn, 0.0f, 1.0f, 0.0f);
  arm(shoulder, elbow, grip);
}

int main(int argc, char *argv[]) {
  static const GLfloat light_position[4] = {-2.0f, 3.0f, 4.0f, 1.0f};
  static const GLfloat fill_position[4] = {3.0f, -1.0f, 2.0f, 0.0f};
  static const GLfloat fill_colour[4] = {0.3f, 0.3f, 0.4f, 1.0f};
  static const GLfloat specular[4] = {0.5f, 0.5f, 0.5f, 1.0f};
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
  ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
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

  glClearColor(0.85f, 0.85f, 0.8f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  glEnable(GL_NORMALIZE);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, light_position);  /* eye space: placed before the camera */
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.05f);
  glLightfv(GL_LIGHT1, GL_POSITION, fill_position);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, fill_colour);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMateriali(GL_FRONT, GL_SHININESS, 32);

  pose(0, WIDTH / 2, HEIGHT, 30.0f, 45.0f, 20.0f, -20.0f);
  pose(WIDTH / 2, WIDTH / 2, HEIGHT, -15.0f, 80.0f, 5.0f, 35.0f);
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
