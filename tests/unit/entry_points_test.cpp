// Every form of the vertex-attribute, matrix and lighting entry points that other tests do not
// reach directly: each must land at the same place as its plain float form.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include "gl_context.h"

#include <cstring>
#include <vector>

namespace {

constexpr int kN = 16;

struct Ctx : pf::test::GlContext {
  Ctx() : GlContext(kN, kN) {
    pfglMatrixMode(GL_PROJECTION);
    pfglOrtho(0, kN, 0, kN, -1, 1);
    pfglMatrixMode(GL_MODELVIEW);
  }
  // The pixel a GL_POINTS vertex landed on, or -1.
  int drawnPixel() {
    pfglFinish();
    int found = -1;
    for (int i = 0; i < kN * kN; ++i)
      if (px[size_t(i) * 4 + 3] != 0) found = found < 0 ? i : -2;
    return found;
  }
  void clear() {
    pfglClearColor(0, 0, 0, 0);
    pfglClear(GL_COLOR_BUFFER_BIT);
  }
};

}  // namespace

TEST(EntryPoints, EveryVertexFormPlacesThePoint) {
  Ctx c;
  const GLfloat f2[2] = {5.5f, 9.5f}, f3[3] = {5.5f, 9.5f, 0.0f}, f4[4] = {11.0f, 19.0f, 0.0f, 2.0f};
  const GLdouble d2[2] = {5.5, 9.5}, d3[3] = {5.5, 9.5, 0.0}, d4[4] = {11.0, 19.0, 0.0, 2.0};
  const int want = 9 * kN + 5;
  auto check = [&](const char* form, auto&& vertex) {
    c.clear();
    pfglColor3f(1, 1, 1);
    pfglBegin(GL_POINTS);
    vertex();
    pfglEnd();
    EXPECT_EQ(c.drawnPixel(), want) << form;
  };
  check("2f", [] { pfglVertex2f(5.5f, 9.5f); });
  check("3f", [] { pfglVertex3f(5.5f, 9.5f, 0.0f); });
  check("4f (w = 2)", [] { pfglVertex4f(11.0f, 19.0f, 0.0f, 2.0f); });
  check("2d", [] { pfglVertex2d(5.5, 9.5); });
  check("3d", [] { pfglVertex3d(5.5, 9.5, 0.0); });
  check("4d", [] { pfglVertex4d(11.0, 19.0, 0.0, 2.0); });
  check("2fv", [&] { pfglVertex2fv(f2); });
  check("3fv", [&] { pfglVertex3fv(f3); });
  check("4fv", [&] { pfglVertex4fv(f4); });
  check("2dv", [&] { pfglVertex2dv(d2); });
  check("3dv", [&] { pfglVertex3dv(d3); });
  check("4dv", [&] { pfglVertex4dv(d4); });
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(EntryPoints, EveryColourFormSetsTheCurrentColour) {
  Ctx c;
  const GLfloat f3[3] = {0.2f, 0.4f, 0.6f}, f4[4] = {0.2f, 0.4f, 0.6f, 0.8f};
  GLfloat got[4];
  pfglColor3fv(f3);
  pfglGetFloatv(GL_CURRENT_COLOR, got);
  EXPECT_EQ(got[2], 0.6f);
  EXPECT_EQ(got[3], 1.0f);
  pfglColor4fv(f4);
  pfglGetFloatv(GL_CURRENT_COLOR, got);
  EXPECT_EQ(got[3], 0.8f);
  pfglColor4ub(51, 102, 153, 204);
  pfglGetFloatv(GL_CURRENT_COLOR, got);
  EXPECT_FLOAT_EQ(got[0], 0.2f);
  EXPECT_FLOAT_EQ(got[3], 0.8f);
  pfglColor3fv(nullptr);  // ignored
  pfglGetFloatv(GL_CURRENT_COLOR, got);
  EXPECT_FLOAT_EQ(got[3], 0.8f);
  const GLfloat n[3] = {0.0f, 0.6f, 0.8f};
  pfglNormal3fv(n);
  pfglGetFloatv(GL_CURRENT_NORMAL, got);
  EXPECT_EQ(got[2], 0.8f);
  pfglTexCoord1f(0.25f);
  pfglGetFloatv(GL_CURRENT_TEXTURE_COORDS, got);
  EXPECT_EQ(got[0], 0.25f);
  EXPECT_EQ(got[1], 0.0f);
  EXPECT_EQ(got[3], 1.0f);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(EntryPoints, MatrixFormsAgree) {
  Ctx c;
  GLfloat a[16], b[16];
  pfglTranslated(1.0, 2.0, 3.0);
  pfglScaled(2.0, 3.0, 4.0);
  pfglRotated(30.0, 0.0, 0.0, 1.0);
  pfglGetFloatv(GL_MODELVIEW_MATRIX, a);
  pfglLoadIdentity();
  pfglTranslatef(1.0f, 2.0f, 3.0f);
  pfglScalef(2.0f, 3.0f, 4.0f);
  pfglRotatef(30.0f, 0.0f, 0.0f, 1.0f);
  pfglGetFloatv(GL_MODELVIEW_MATRIX, b);
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(a[i], b[i], 1e-6) << i;
  pfglLoadMatrixf(a);
  pfglMultMatrixf(b);
  GLdouble ad[16], prod[16];
  for (int i = 0; i < 16; ++i) ad[i] = a[i];
  pfglGetDoublev(GL_MODELVIEW_MATRIX, prod);
  pfglLoadMatrixd(ad);
  pfglMultMatrixd(ad);
  pfglGetFloatv(GL_MODELVIEW_MATRIX, b);
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(prod[i], b[i], 1e-4) << i;
}

TEST(EntryPoints, LightingFormsAgree) {
  Ctx c;
  GLfloat v[4];
  pfglLighti(GL_LIGHT3, GL_SPOT_CUTOFF, 45);
  pfglGetLightfv(GL_LIGHT3, GL_SPOT_CUTOFF, v);
  EXPECT_EQ(v[0], 45.0f);
  const GLint half[4] = {1073741824, 0, 2147483647, 2147483647};  // integer colours: 2^31 - 1 is 1.0
  pfglLightiv(GL_LIGHT3, GL_DIFFUSE, half);
  pfglGetLightfv(GL_LIGHT3, GL_DIFFUSE, v);
  EXPECT_NEAR(v[0], 0.5f, 1e-6);
  EXPECT_EQ(v[2], 1.0f);
  const GLint pos[4] = {1, 2, 3, 1};  // positions as they are
  pfglLightiv(GL_LIGHT3, GL_POSITION, pos);
  pfglGetLightfv(GL_LIGHT3, GL_POSITION, v);
  EXPECT_EQ(v[2], 3.0f);
  pfglLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 1.0f);
  GLboolean b;
  pfglGetBooleanv(GL_LIGHT_MODEL_TWO_SIDE, &b);
  EXPECT_EQ(b, GL_TRUE);
  const GLfloat amb[4] = {0.1f, 0.2f, 0.3f, 1.0f};
  pfglLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
  pfglGetFloatv(GL_LIGHT_MODEL_AMBIENT, v);
  EXPECT_EQ(v[1], 0.2f);
  const GLint amb_i[4] = {0, 0, 2147483647, 2147483647};
  pfglLightModeliv(GL_LIGHT_MODEL_AMBIENT, amb_i);
  pfglGetFloatv(GL_LIGHT_MODEL_AMBIENT, v);
  EXPECT_EQ(v[2], 1.0f);
  pfglLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
  pfglGetBooleanv(GL_LIGHT_MODEL_LOCAL_VIEWER, &b);
  EXPECT_EQ(b, GL_TRUE);
  pfglMateriali(GL_BACK, GL_SHININESS, 64);
  pfglGetMaterialfv(GL_BACK, GL_SHININESS, v);
  EXPECT_EQ(v[0], 64.0f);
  pfglMaterialiv(GL_FRONT, GL_EMISSION, half);
  pfglGetMaterialfv(GL_FRONT, GL_EMISSION, v);
  EXPECT_NEAR(v[0], 0.5f, 1e-6);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(EntryPoints, ArrayElementNormalPointerAndClientState) {
  Ctx c;
  const GLfloat xy[4] = {2.5f, 3.5f, 7.5f, 8.5f};
  const GLshort normals[6] = {0, 0, 32767, 0, 32767, 0};
  pfglEnableClientState(GL_VERTEX_ARRAY);
  pfglEnableClientState(GL_NORMAL_ARRAY);
  EXPECT_EQ(pfglIsEnabled(GL_NORMAL_ARRAY), GL_TRUE);
  pfglVertexPointer(2, GL_FLOAT, 0, xy);
  pfglNormalPointer(GL_SHORT, 0, normals);
  c.clear();
  pfglColor3f(1, 1, 1);
  pfglBegin(GL_POINTS);
  pfglArrayElement(1);
  pfglEnd();
  EXPECT_EQ(c.drawnPixel(), 8 * kN + 7);
  GLfloat n[3];
  pfglGetFloatv(GL_CURRENT_NORMAL, n);
  EXPECT_NEAR(n[1], 1.0f, 1e-4) << "normalised short normals";
  pfglDisableClientState(GL_NORMAL_ARRAY);
  EXPECT_EQ(pfglIsEnabled(GL_NORMAL_ARRAY), GL_FALSE);
  pfglVertexPointer(1, GL_FLOAT, 0, xy);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglVertexPointer(2, GL_UNSIGNED_BYTE, 0, xy);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglDrawArrays(GL_POINTS, 0, -1);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglDrawElements(GL_POINTS, 1, GL_FLOAT, xy);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglDrawArrays(0x31FFF, 0, 1);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglEnableClientState(GL_INDEX_ARRAY);  // an array primflow does not have
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
}

TEST(EntryPoints, StringsAndSynchronisation) {
  Ctx c;
  EXPECT_STREQ(reinterpret_cast<const char*>(pfglGetString(GL_VENDOR)), "primflow");
  EXPECT_NE(pfglGetString(GL_VERSION), nullptr);
  EXPECT_EQ(pfglGetString(GL_SHADING_LANGUAGE_VERSION), nullptr);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  c.clear();
  pfglBegin(GL_POINTS);
  pfglVertex2f(1.5f, 1.5f);
  pfglEnd();
  pfglFlush();  // like glFinish here: the drawing lands
  EXPECT_NE(c.px[(size_t(1) * kN + 1) * 4 + 3], 0);
}
