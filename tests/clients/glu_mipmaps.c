/* glu_mipmaps.c -- client suite (tests/clients): the system libGLU's texture path, as the Red
 * Book's mipmap and texture programs use it. gluBuild2DMipmaps on a 64 x 48 image (not a power
 * of two: GLU probes GL_MAX_TEXTURE_SIZE and a proxy texture, scales the image with its own
 * gluScaleImage and uploads every level through glTexImage2D), gluScaleImage called directly for
 * a second texture, glGetTexLevelParameteriv on the levels; then a floor receding under a
 * perspective (every mipmap level in view, GL_LINEAR_MIPMAP_NEAREST) and a quad of the scaled
 * texture. Built three ways (tests/clients/CMakeLists.txt). Usage: glu_mipmaps OUT.pam [DEPTH] */
#ifdef PF_CLIENT_MANGLE
#include <primflow/gl_mangle.h>
#else
#include <GL/osmesa.h>
#endif
#include <GL/glu.h>
#include <stdio.h>
#include <stdlib.h>

#include "client_context.h"

#define WIDTH 200
#define HEIGHT 160

int main(int argc, char *argv[]) {
  static GLubyte image[48][64][4];
  static GLubyte scaled[16][16][3];
  client_context c;
  GLuint tex[2];
  GLint result, level, w;
  int i, j;
  if (!client_begin(&c, argc, argv, WIDTH, HEIGHT, 24, 0)) return argc < 2 ? 2 : 1;
  /* A checkerboard of 8-texel squares with a colour ramp, so that each level's average differs. */
  for (j = 0; j < 48; ++j)
    for (i = 0; i < 64; ++i) {
      const int dark = ((i / 8) + (j / 8)) & 1;
      image[j][i][0] = (GLubyte)(dark ? 30 : 60 + 3 * i);
      image[j][i][1] = (GLubyte)(dark ? 40 : 80 + 3 * j);
      image[j][i][2] = (GLubyte)(dark ? 120 : 200);
      image[j][i][3] = 255;
    }
  glGenTextures(2, tex);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  result = gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 64, 48, GL_RGBA, GL_UNSIGNED_BYTE, image);
  printf("gluBuild2DMipmaps -> %d, glGetError 0x%x\n", (int)result, glGetError());
  for (level = 0; level < 8; ++level) {
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_WIDTH, &w);
    printf("level %d: width %d\n", level, (int)w);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  result = gluScaleImage(GL_RGB, 64, 48, GL_UNSIGNED_BYTE, image, 16, 16, GL_UNSIGNED_BYTE, scaled);
  printf("gluScaleImage -> %d\n", (int)result);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, scaled);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

  glViewport(0, 0, WIDTH, HEIGHT);
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(60.0, (double)WIDTH / HEIGHT, 1.0, 100.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f); glVertex3f(-2.0f, -1.0f, -1.5f);
  glTexCoord2f(2.0f, 0.0f); glVertex3f(2.0f, -1.0f, -1.5f);
  glTexCoord2f(2.0f, 30.0f); glVertex3f(2.0f, -1.0f, -60.0f);
  glTexCoord2f(0.0f, 30.0f); glVertex3f(-2.0f, -1.0f, -60.0f);
  glEnd();
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f); glVertex3f(0.3f, 0.0f, -3.0f);
  glTexCoord2f(1.0f, 0.0f); glVertex3f(1.5f, 0.0f, -3.0f);
  glTexCoord2f(1.0f, 1.0f); glVertex3f(1.5f, 1.2f, -3.0f);
  glTexCoord2f(0.0f, 1.0f); glVertex3f(0.3f, 1.2f, -3.0f);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(2, tex);
  glFinish();
  return client_end(&c, argc, argv);
}
