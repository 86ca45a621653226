/* osdemo.c -- client suite (tests/clients): an offscreen program in the shape of Mesa's osdemo:
 * a lit torus, cone and sphere under glOrtho, the cone and sphere drawn with GLU quadrics, the
 * image and depth written to files. Built three ways (tests/clients/CMakeLists.txt): against
 * OSMesa, against libprimflow-osmesa unchanged, and through primflow/gl_mangle.h with
 * pfCreateContext (PF_CLIENT_MANGLE) -- the port docs/api.md describes.
 * Usage: osdemo OUT.pam [DEPTH] */
#ifdef PF_CLIENT_MANGLE
#include <primflow/gl_mangle.h>
#else
#include <GL/osmesa.h>
#endif
#include <GL/glu.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "client_output.h"

#define WIDTH 256
#define HEIGHT 256

static void Sphere(float radius, int slices, int stacks) {
  GLUquadric *q = gluNewQuadric();
  gluQuadricNormals(q, GLU_SMOOTH);
  gluSphere(q, radius, slices, stacks);
  gluDeleteQuadric(q);
}

static void Cone(float base, float height, int slices, int stacks) {
  GLUquadric *q = gluNewQuadric();
  gluQuadricDrawStyle(q, GLU_FILL);
  gluQuadricNormals(q, GLU_SMOOTH);
  gluCylinder(q, base, 0.0, height, slices, stacks);
  gluDeleteQuadric(q);
}

/* A torus of quad strips around the z axis, with smooth normals. */
static void Torus(float inner, float outer, int sides, int rings) {
  const double two_pi = 6.283185307179586;
  int i, j, k;
  for (i = 0; i < rings; ++i) {
    glBegin(GL_QUAD_STRIP);
    for (j = 0; j <= sides; ++j) {
      for (k = 1; k >= 0; --k) {
        const double phi = (i + k) % rings * two_pi / rings, theta = j % sides * two_pi / sides;
        const double r = outer + inner * cos(theta);
        glNormal3f((GLfloat)(cos(phi) * cos(theta)), (GLfloat)(sin(phi) * cos(theta)), (GLfloat)sin(theta));
        glVertex3f((GLfloat)(r * cos(phi)), (GLfloat)(r * sin(phi)), (GLfloat)(inner * sin(theta)));
      }
    }
    glEnd();
  }
}

static void render_image(void) {
  GLfloat light_ambient[] = {0.0f, 0.0f, 0.0f, 1.0f};
  GLfloat light_diffuse[] = {1.0f, 1.0f, 1.0f, 1.0f};
  GLfloat light_specular[] = {1.0f, 1.0f, 1.0f, 1.0f};
  GLfloat light_position[] = {1.0f, 1.0f, 1.0f, 0.0f};
  GLfloat red_mat[] = {1.0f, 0.2f, 0.2f, 1.0f};
  GLfloat green_mat[] = {0.2f, 1.0f, 0.2f, 1.0f};
  GLfloat blue_mat[] = {0.2f, 0.2f, 1.0f, 1.0f};
  GLfloat white[] = {0.6f, 0.6f, 0.6f, 1.0f};

  glLightfv(GL_LIGHT0, GL_AMBIENT, light_ambient);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, light_diffuse);
  glLightfv(GL_LIGHT0, GL_SPECULAR, light_specular);
  glLightfv(GL_LIGHT0, GL_POSITION, light_position);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_NORMALIZE);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-2.5, 2.5, -2.5, 2.5, -10.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  glPushMatrix();
  glRotatef(20.0f, 1.0f, 0.0f, 0.0f);

  glPushMatrix();
  glTranslatef(-0.75f, 0.5f, 0.0f);
  glRotatef(90.0f, 1.0f, 0.0f, 0.0f);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, red_mat);
  Torus(0.275f, 0.85f, 20, 20);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(-0.75f, -0.5f, 0.0f);
  glRotatef(270.0f, 1.0f, 0.0f, 0.0f);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, green_mat);
  Cone(1.0f, 2.0f, 16, 1);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(0.75f, 0.0f, -1.0f);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, blue_mat);
  Sphere(1.0f, 20, 20);
  glPopMatrix();

  glPopMatrix();

  /* Make sure the image is in the buffer. */
  glFinish();
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
  /* RGBA, with OSMesa's default depth buffer (24 bits; 8 bits of stencil too). */
#ifdef PF_CLIENT_MANGLE
  ctx = pfCreateContext(GL_RGBA, 24);
#else
  ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
#endif
  if (!ctx) {
    printf("OSMesaCreateContext failed!\n");
    return 1;
  }
  buffer = (GLubyte *)malloc(WIDTH * HEIGHT * 4 * sizeof(GLubyte));
  if (!buffer) return 1;
#ifdef PF_CLIENT_MANGLE
  ok = pfMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, WIDTH, HEIGHT);
#else
  ok = OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, WIDTH, HEIGHT);
#endif
  if (!ok) {
    printf("OSMesaMakeCurrent failed!\n");
    return 1;
  }
  printf("%s\n", (const char *)glGetString(GL_RENDERER));

  render_image();

  if (!client_write_pam(argv[1], WIDTH, HEIGHT, buffer)) return 1;
#ifdef PF_CLIENT_MANGLE
  if (pfGetDepthBuffer(ctx, &w, &h, &bytes, &depth)) z = client_depth_to_float(depth, w, h, bytes, 1);
#else
  if (OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, &depth)) z = client_depth_to_float(depth, w, h, bytes, 0);
#endif
  if (argc > 2 && (!z || !client_write_depth(argv[2], w, h, z))) return 1;
  free(z);
  free(buffer);
#ifdef PF_CLIENT_MANGLE
  pfDestroyContext(ctx);
#else
  OSMesaDestroyContext(ctx);
#endif
  return glGetError() == GL_NO_ERROR ? 0 : 3;
}
