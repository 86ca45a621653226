/* glu_mipmaps.c -- client suite (tests/clients): the system libGLU's texture path on
 * libprimflow-osmesa, which has no textures: gluBuild2DMipmaps calls glTexImage2D (through its
 * proxy-texture probe), gluScaleImage, glGetTexLevelParameteriv. They must reach primflow's stubs
 * -- GL_INVALID_OPERATION, no crash, nothing sent to libOpenGL -- and the context must draw on.
 * Prints the GL error and exits 0 when that holds. */
#include <GL/osmesa.h>
#include <GL/glu.h>
#include <stdio.h>
#include <stdlib.h>

int main(void) {
  static unsigned char image[64 * 48 * 4];
  static unsigned char buffer[8 * 8 * 4];
  OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
  GLint result;
  GLenum error;
  int i;
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 8, 8)) return 1;
  for (i = 0; i < (int)sizeof image; ++i) image[i] = (unsigned char)(i * 7);
  result = gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 64, 48, GL_RGBA, GL_UNSIGNED_BYTE, image);
  error = glGetError();
  printf("gluBuild2DMipmaps -> %d, glGetError 0x%x\n", (int)result, error);
  /* still a working context */
  glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  printf("drawing after it: %s\n", buffer[1] == 255 && glGetError() == GL_NO_ERROR ? "fine" : "broken");
  OSMesaDestroyContext(ctx);
  return error == GL_INVALID_OPERATION && buffer[1] == 255 ? 0 : 1;
}
