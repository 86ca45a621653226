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
#include "client_context.h"
#include "client_cube.h"

#define WIDTH 320
#define HEIGHT 200

/* A segment of the arm: a box `length` long from the joint, `thickness` across. */
static void segment(GLfloat length, GLfloat thickness) {
  glPushMatrix();
  glTranslatef(length / 2.0f, 0.0f, 0.0f);
  glScalef(length, thickness, thickness);
  client_unit_cube();
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
  client_context c;
  if (!client_begin(&c, argc, argv, WIDTH, HEIGHT, 24, 0)) return argc < 2 ? 2 : 1;

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

  return client_end(&c, argc, argv);
}
