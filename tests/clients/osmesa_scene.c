/* osmesa_scene.c -- client suite (tests/clients): the kind of scene Mesa's own OSMesa test
 * draws, offscreen, in one program: a textured quad (a checkerboard, GL_MODULATE over smooth
 * colours, GL_LINEAR), translucent triangles blended over it (GL_SRC_ALPHA /
 * GL_ONE_MINUS_SRC_ALPHA, depth writes off), a wireframe box (glPolygonMode GL_LINE, lines 2
 * wide) over its own filled faces pushed back by glPolygonOffset -- hidden lines --, a
 * back-face point cloud (GL_POINT, size 3), and a stippled line loop 3 wide. A context with 24
 * depth bits. Built three ways (tests/clients/CMakeLists.txt); no GLU.
 * Usage: osmesa_scene OUT.pam [DEPTH] */
#ifdef PF_CLIENT_MANGLE
#include <primflow/gl_mangle.h>
#else
#include <GL/osmesa.h>
#endif
#include "client_context.h"
#include "client_cube.h"

#define WIDTH 256
#define HEIGHT 256

static void checker_texture(void) {
  static GLubyte texels[32][32][4];
  int i, j;
  for (i = 0; i < 32; ++i)
    for (j = 0; j < 32; ++j) {
      const GLubyte c = ((i & 4) ^ (j & 4)) ? 255 : 40;
      texels[i][j][0] = c;
      texels[i][j][1] = (GLubyte)(c / 2 + 60);
      texels[i][j][2] = (GLubyte)(255 - c / 2);
      texels[i][j][3] = 255;
    }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
}

int main(int argc, char *argv[]) {
  int i;
  client_context c;
  if (!client_begin(&c, argc, argv, WIDTH, HEIGHT, 24, 0)) return argc < 2 ? 2 : 1;
  glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -1.0, 1.0, 2.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  /* The textured quad, receding, inside the view volume: a smooth quad that llvmpipe must clip
   * is split along its other diagonal (its draw module's clipping path decomposes quads as
   * (0, 1, 3), (1, 2, 3)), which primflow does not copy (docs/api.md). */
  checker_texture();
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);
  glColor3f(1.0f, 1.0f, 1.0f);
  glTexCoord2f(0.0f, 0.0f);
  glVertex3f(-1.9f, -1.9f, -4.0f);
  glColor3f(1.0f, 0.8f, 0.6f);
  glTexCoord2f(3.0f, 0.0f);
  glVertex3f(1.9f, -1.9f, -4.0f);
  glColor3f(0.6f, 0.8f, 1.0f);
  glTexCoord2f(3.0f, 3.0f);
  glVertex3f(3.0f, 1.5f, -12.0f);
  glColor3f(0.9f, 1.0f, 0.7f);
  glTexCoord2f(0.0f, 3.0f);
  glVertex3f(-3.0f, 1.5f, -12.0f);
  glEnd();
  glDisable(GL_TEXTURE_2D);

  /* The wireframe box: faces filled and pushed back, then their edges 2 wide; the back faces'
   * corners as points. */
  glPushMatrix();
  glTranslatef(0.9f, 0.2f, -6.0f);
  glRotatef(35.0f, 0.3f, 1.0f, 0.2f);
  glScalef(1.6f, 1.6f, 1.6f);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  glColor3f(0.1f, 0.1f, 0.1f);
  client_unit_cube();
  glDisable(GL_POLYGON_OFFSET_FILL);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glLineWidth(2.0f);
  glColor3f(1.0f, 0.9f, 0.2f);
  client_unit_cube();
  glPolygonMode(GL_FRONT, GL_FILL);
  glPolygonMode(GL_BACK, GL_POINT);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  glPointSize(3.0f);
  glDisable(GL_DEPTH_TEST);
  glColor3f(0.2f, 1.0f, 0.4f);
  client_unit_cube();
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glPopMatrix();

  /* Translucent triangles over it all, no depth writes. */
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glBegin(GL_TRIANGLES);
  for (i = 0; i < 3; ++i) {
    const float x = -1.6f + 1.1f * i, z = -5.0f - 0.8f * i;
    glColor4f(1.0f, 0.3f * i, 0.2f, 0.5f);
    glVertex3f(x, -1.2f, z);
    glColor4f(0.2f, 1.0f, 0.3f * i, 0.35f);
    glVertex3f(x + 1.6f, -0.9f, z);
    glColor4f(0.3f, 0.4f, 1.0f, 0.6f);
    glVertex3f(x + 0.6f, 1.1f, z);
  }
  glEnd();
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);

  /* A stippled loop, 3 wide, in window coordinates. */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, WIDTH, 0, HEIGHT, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x33ff);
  glLineWidth(3.0f);
  glColor3f(1.0f, 1.0f, 1.0f);
  glBegin(GL_LINE_LOOP);
  glVertex2f(12.5f, 12.5f);
  glVertex2f(243.5f, 20.5f);
  glVertex2f(230.5f, 243.5f);
  glVertex2f(20.5f, 230.5f);
  glEnd();
  glDisable(GL_LINE_STIPPLE);
  glLineWidth(1.0f);
  glFinish();
  return client_end(&c, argc, argv);
}
