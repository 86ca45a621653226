// glPushAttrib / glPopAttrib where GL 1.5 (tables 6.5-6.31) and OSMesa part: primflow restores
// what the groups hold, as GL says -- a light's enable under GL_ENABLE_BIT, the material under
// GL_LIGHTING_BIT, the current colour popped inside a display list. (Everything else about the
// stacks is compared with OSMesa: tests/conformance/cases_gl1x.inc, attrib_stacks.)
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include "gl_context.h"

namespace {

GLint integer(GLenum pname) {
  GLint v = -1;
  pfglGetIntegerv(pname, &v);
  return v;
}

}  // namespace

TEST(AttribStack, EnableBitRestoresTheLights) {
  pf::test::GlContext c(8, 8);
  pfglEnable(GL_LIGHT0);
  pfglDisable(GL_LIGHT5);
  pfglPushAttrib(GL_ENABLE_BIT);
  pfglDisable(GL_LIGHT0);
  pfglEnable(GL_LIGHT5);
  pfglPopAttrib();
  EXPECT_EQ(integer(GL_LIGHT0), GL_TRUE);
  EXPECT_EQ(integer(GL_LIGHT5), GL_FALSE);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(AttribStack, LightingBitRestoresTheMaterialNotTheNormalize) {
  pf::test::GlContext c(8, 8);
  const GLfloat red[4] = {1, 0, 0, 1}, green[4] = {0, 1, 0, 1};
  pfglMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, red);
  pfglPushAttrib(GL_LIGHTING_BIT);
  pfglMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, green);
  pfglMaterialf(GL_BACK, GL_SHININESS, 50);
  pfglEnable(GL_NORMALIZE);  // GL_TRANSFORM_BIT and GL_ENABLE_BIT: not restored here
  pfglPopAttrib();
  GLfloat v[4];
  pfglGetMaterialfv(GL_FRONT, GL_DIFFUSE, v);
  EXPECT_EQ(v[0], 1.0f);
  EXPECT_EQ(v[1], 0.0f);
  pfglGetMaterialfv(GL_BACK, GL_SHININESS, v);
  EXPECT_EQ(v[0], 0.0f);
  EXPECT_EQ(integer(GL_NORMALIZE), GL_TRUE);
}

TEST(AttribStack, CurrentBitPoppedInADisplayList) {
  pf::test::GlContext c(8, 8);
  pfglColor3f(0.25f, 0.5f, 0.75f);
  pfglNewList(1, GL_COMPILE);
  pfglPushAttrib(GL_CURRENT_BIT);
  pfglColor3f(1, 0, 0);
  pfglNormal3f(1, 0, 0);
  pfglPopAttrib();
  pfglEndList();
  pfglCallList(1);
  GLfloat v[4];
  pfglGetFloatv(GL_CURRENT_COLOR, v);
  EXPECT_EQ(v[0], 0.25f);
  EXPECT_EQ(v[2], 0.75f);
  pfglGetFloatv(GL_CURRENT_NORMAL, v);
  EXPECT_EQ(v[0], 0.0f);
  EXPECT_EQ(v[2], 1.0f);
  EXPECT_EQ(integer(GL_ATTRIB_STACK_DEPTH), 0);
}
