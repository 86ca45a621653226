/* tests/clients/mangle: the paper's figure 3 (Olano et al. 1997: a sphere primitive fed with
 * named raster parameters and sequence points) by the paper's names, through gl_mangle.h. It must
 * compile unchanged, in C and C++. */
#include <primflow/gl_mangle.h>

void draw_sphere(GLfloat x, GLfloat y, GLfloat z, GLfloat radius) {
  GLenum sphere = glGetPrimitiveEXT("sphere");
  GLuint center = glGetParamNameEXT("center");
  GLuint radius_name = glGetParamNameEXT("radius");
  glMaterialInterpEXT(glGetParamNameEXT("color"), sphere, GL_PERSPECTIVE_LINEAR_INTERPOLATOR_EXT);
  glBegin(sphere);
  glColor3f(1.0f, 0.5f, 0.2f);
  glRastParam3fEXT(center, x, y, z);
  glRastParamfEXT(radius_name, radius);
  glSequencePointEXT();
  glEnd();
}
