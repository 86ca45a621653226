// glPixelTransfer, glPixelMap and glGetPixelMap (GL 1.5 sections 3.6.5, 6.1.3): the errors in
// Mesa's order, the conversions of integer tables and their readings back, the queries, the
// attribute group and display lists. The expected numbers are OSMesa's (Mesa 22.3) answers to the
// same calls, measured; the conformance case pixel_transfer_state compares them with OSMesa live.
#include <gtest/gtest.h>

#include <cstring>

#include <primflow/gl.h>

#include "gl_context.h"

namespace {

GLenum error() { return pfglGetError(); }

GLint integer(GLenum pname) {
  GLint v = -12345;
  pfglGetIntegerv(pname, &v);
  return v;
}

GLfloat number(GLenum pname) {
  GLfloat v = -12345.0f;
  pfglGetFloatv(pname, &v);
  return v;
}

uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}

}  // namespace

TEST(PixelMaps, ErrorsInMesasOrder) {
  pf::test::GlContext c(8, 8);
  GLfloat v[300] = {};
  pfglPixelMapfv(GL_PIXEL_MAP_R_TO_R, 0, v);
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));
  pfglPixelMapfv(GL_PIXEL_MAP_R_TO_R, 257, v);
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));
  pfglPixelMapfv(GL_PIXEL_MAP_R_TO_R, 256, v);  // GL_MAX_PIXEL_MAP_TABLE
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  pfglPixelMapfv(GL_PIXEL_MAP_A_TO_A, 3, v);  // (the colour tables: any size)
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  pfglPixelMapfv(GL_PIXEL_MAP_I_TO_I, 3, v);  // (Mesa checks no power of two for I_TO_I)
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  for (GLenum map : {GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_R, GL_PIXEL_MAP_I_TO_A}) {
    pfglPixelMapfv(map, 3, v);
    EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE)) << map;
  }
  pfglPixelMapfv(GL_RED_SCALE, 4, v);
  EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM));
  pfglPixelMapfv(GL_RED_SCALE, 0, v);  // the size first
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));
  pfglPixelMapfv(0x1234, 4, nullptr);  // a NULL table: nothing, even of an unknown map
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  pfglPixelMapfv(GL_PIXEL_MAP_S_TO_S, 3, nullptr);
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));
  pfglPixelMapuiv(GL_PIXEL_MAP_R_TO_R, -1, nullptr);
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));
  pfglPixelMapusv(0x1234, 6, reinterpret_cast<const GLushort*>(v));
  EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM));
  pfglGetPixelMapfv(0x1234, v);
  EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM));
  pfglGetPixelMapuiv(GL_PIXEL_MAP_R_TO_R, nullptr);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  pfglPixelTransferf(0x1234, 1.0f);
  EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM));
  pfglPixelTransferi(GL_ZOOM_X, 2);
  EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM));
  pfglBegin(GL_POINTS);
  pfglPixelTransferf(0x1234, 0.0f);
  pfglEnd();
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  pfglBegin(GL_POINTS);
  pfglPixelMapfv(GL_PIXEL_MAP_R_TO_R, 0, v);
  pfglEnd();
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  pfglBegin(GL_POINTS);
  pfglGetPixelMapfv(0x1234, v);
  pfglEnd();
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
}

TEST(PixelMaps, TransferModesAsMesaStoresThem) {
  pf::test::GlContext c(8, 8);
  EXPECT_EQ(integer(GL_MAX_PIXEL_MAP_TABLE), 256);
  EXPECT_EQ(number(GL_RED_SCALE), 1.0f);
  EXPECT_EQ(integer(GL_PIXEL_MAP_I_TO_I_SIZE), 1);
  pfglPixelTransferf(GL_MAP_COLOR, 0.25f);  // any value but 0: true
  EXPECT_EQ(integer(GL_MAP_COLOR), 1);
  pfglPixelTransferf(GL_MAP_STENCIL, -0.5f);
  EXPECT_EQ(integer(GL_MAP_STENCIL), 1);
  pfglPixelTransferi(GL_MAP_STENCIL, 0);
  EXPECT_EQ(integer(GL_MAP_STENCIL), 0);
  pfglPixelTransferf(GL_INDEX_SHIFT, -2.7f);  // truncated
  EXPECT_EQ(integer(GL_INDEX_SHIFT), -2);
  pfglPixelTransferf(GL_INDEX_OFFSET, 3.5f);
  EXPECT_EQ(number(GL_INDEX_OFFSET), 3.0f);
  pfglPixelTransferf(GL_INDEX_OFFSET, 1e10f);  // out of range: INT_MIN, as x86 truncates
  EXPECT_EQ(integer(GL_INDEX_OFFSET), INT32_MIN);
  pfglPixelTransferi(GL_RED_SCALE, 3);
  EXPECT_EQ(number(GL_RED_SCALE), 3.0f);
  pfglPixelTransferf(GL_GREEN_BIAS, -0.5f);
  EXPECT_EQ(integer(GL_GREEN_BIAS), -1);  // (glGetIntegerv rounds, halves away from zero)
  pfglPixelTransferf(GL_DEPTH_SCALE, 2.5f);
  EXPECT_EQ(number(GL_DEPTH_SCALE), 2.5f);
  pfglPixelTransferf(GL_DEPTH_BIAS, 0.4f);
  EXPECT_EQ(number(GL_DEPTH_BIAS), 0.4f);
  GLboolean b = GL_FALSE;
  pfglGetBooleanv(GL_DEPTH_BIAS, &b);
  EXPECT_EQ(b, GL_TRUE);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
}

// Tables set by floats: I_TO_I as given, S_TO_S rounded, the colour tables clamped; read back
// as integers the way Mesa converts them.
TEST(PixelMaps, FloatTablesReadBackAsMesaReadsThem) {
  pf::test::GlContext c(8, 8);
  const GLfloat in[8] = {-1.5f, -0.25f, 0.0f, 0.3f, 1.0f, 2.6f, 70000.5f, 3.5f};
  GLfloat f[8];
  GLuint u[8];
  GLushort s[8];
  pfglPixelMapfv(GL_PIXEL_MAP_I_TO_I, 8, in);
  pfglGetPixelMapfv(GL_PIXEL_MAP_I_TO_I, f);
  pfglGetPixelMapuiv(GL_PIXEL_MAP_I_TO_I, u);
  pfglGetPixelMapusv(GL_PIXEL_MAP_I_TO_I, s);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(f[i], in[i]);
  const GLuint u_i[8] = {2147483650u, 3221225473u, 0, 1288490239u, 4294967295u, 2576979965u, 2147413647u, 2147483644u};
  const GLushort s_i[8] = {0, 0, 0, 0, 1, 2, 65535, 3};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(u[i], u_i[i]) << i;
  for (int i = 0; i < 8; ++i) EXPECT_EQ(s[i], s_i[i]) << i;
  pfglPixelMapfv(GL_PIXEL_MAP_S_TO_S, 8, in);
  pfglGetPixelMapfv(GL_PIXEL_MAP_S_TO_S, f);
  pfglGetPixelMapuiv(GL_PIXEL_MAP_S_TO_S, u);
  const GLfloat f_s[8] = {-2.0f, -0.0f, 0.0f, 0.0f, 1.0f, 3.0f, 70001.0f, 4.0f};
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(bits(f[i]), bits(f_s[i])) << i;
    EXPECT_EQ(u[i], bits(f_s[i])) << i;  // (Mesa hands out the float table's bits)
  }
  pfglPixelMapfv(GL_PIXEL_MAP_I_TO_R, 8, in);
  pfglGetPixelMapfv(GL_PIXEL_MAP_I_TO_R, f);
  pfglGetPixelMapuiv(GL_PIXEL_MAP_I_TO_R, u);
  pfglGetPixelMapusv(GL_PIXEL_MAP_I_TO_R, s);
  const GLfloat f_c[8] = {0, 0, 0, 0.3f, 1, 1, 1, 1};
  const GLuint u_c[8] = {0, 0, 0, 1288490239u, 4294967295u, 4294967295u, 4294967295u, 4294967295u};
  const GLushort s_c[8] = {0, 0, 0, 19660, 65535, 65535, 65535, 65535};  // (0.3: 19660.5, to even)
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(f[i], f_c[i]) << i;
    EXPECT_EQ(u[i], u_c[i]) << i;
    EXPECT_EQ(s[i], s_c[i]) << i;
  }
  EXPECT_EQ(integer(GL_PIXEL_MAP_I_TO_R_SIZE), 8);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
}

TEST(PixelMaps, IntegerTablesConvertAsMesaConvertsThem) {
  pf::test::GlContext c(8, 8);
  const GLuint ui[8] = {0, 1, 2, 0x7fffffffu, 0x80000000u, 0xffffffffu, 65535, 12345678};
  const GLushort us[8] = {0, 1, 2, 255, 256, 32768, 65534, 65535};
  GLfloat f[8];
  GLuint u[8];
  GLushort s[8];
  pfglPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 8, ui);
  pfglGetPixelMapfv(GL_PIXEL_MAP_I_TO_I, f);
  pfglGetPixelMapuiv(GL_PIXEL_MAP_I_TO_I, u);
  const GLuint u_i[8] = {0, 4294967295u, 4294967294u, 2147483648u, 2147483648u, 0, 4294901761u, 4282621616u};
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(f[i], static_cast<GLfloat>(ui[i])) << i;
    EXPECT_EQ(u[i], u_i[i]) << i;
  }
  pfglPixelMapuiv(GL_PIXEL_MAP_R_TO_R, 8, ui);
  pfglGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, f);
  pfglGetPixelMapuiv(GL_PIXEL_MAP_R_TO_R, u);
  pfglGetPixelMapusv(GL_PIXEL_MAP_R_TO_R, s);
  const GLfloat f_r[8] = {0, 2.32830644e-10f, 4.65661287e-10f, 0.5f, 0.5f, 1, 1.52585562e-05f, 0.00287445216f};
  const GLuint u_r[8] = {0, 0, 1, 2147483647u, 2147483647u, 4294967295u, 65534, 12345677};
  const GLushort s_r[8] = {0, 0, 0, 32768, 32768, 65535, 1, 188};
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(f[i], f_r[i]) << i;
    EXPECT_EQ(u[i], u_r[i]) << i;
    EXPECT_EQ(s[i], s_r[i]) << i;
  }
  pfglPixelMapusv(GL_PIXEL_MAP_G_TO_G, 8, us);
  pfglGetPixelMapfv(GL_PIXEL_MAP_G_TO_G, f);
  pfglGetPixelMapuiv(GL_PIXEL_MAP_G_TO_G, u);
  pfglGetPixelMapusv(GL_PIXEL_MAP_G_TO_G, s);
  const GLfloat f_g[8] = {0, 1.52590219e-05f, 3.05180438e-05f, 0.00389105058f, 0.0039063096f, 0.500007629f,
                          0.999984741f, 1};
  const GLuint u_g[8] = {0, 65536, 131073, 16711934, 16777471, 2147516415u, 4294901759u, 4294967295u};
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(f[i], f_g[i]) << i;
    EXPECT_EQ(u[i], u_g[i]) << i;
    EXPECT_EQ(s[i], us[i]) << i;
  }
  pfglPixelMapusv(GL_PIXEL_MAP_S_TO_S, 8, us);
  pfglGetPixelMapusv(GL_PIXEL_MAP_S_TO_S, s);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(s[i], us[i]) << i;
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
}

// GL_PIXEL_MODE_BIT holds the transfer modes; the tables are in no group.
TEST(PixelMaps, PixelModeBitHoldsTheModesNotTheTables) {
  pf::test::GlContext c(8, 8);
  const GLfloat two[2] = {0.25f, 0.75f}, four[4] = {0, 0.5f, 0.5f, 1};
  pfglPixelTransferf(GL_RED_SCALE, 2.0f);
  pfglPixelTransferi(GL_MAP_COLOR, 1);
  pfglPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, two);
  pfglPushAttrib(GL_PIXEL_MODE_BIT);
  pfglPixelTransferf(GL_RED_SCALE, 3.0f);
  pfglPixelTransferi(GL_MAP_COLOR, 0);
  pfglPixelTransferi(GL_INDEX_SHIFT, 5);
  pfglPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, four);
  pfglPopAttrib();
  EXPECT_EQ(number(GL_RED_SCALE), 2.0f);
  EXPECT_EQ(integer(GL_MAP_COLOR), 1);
  EXPECT_EQ(integer(GL_INDEX_SHIFT), 0);
  EXPECT_EQ(integer(GL_PIXEL_MAP_R_TO_R_SIZE), 4);
  pfglPushAttrib(GL_ALL_ATTRIB_BITS & ~GL_PIXEL_MODE_BIT);
  pfglPixelTransferf(GL_RED_SCALE, 5.0f);
  pfglPopAttrib();
  EXPECT_EQ(number(GL_RED_SCALE), 5.0f);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
}

// Both are recorded: their values copied when compiled (integers converted then), their errors
// raised when the list runs.
TEST(PixelMaps, DisplayListsRecordBoth) {
  pf::test::GlContext c(8, 8);
  GLuint entries[4] = {0, 0x7fffffffu, 0xffffffffu, 0};
  pfglNewList(1, GL_COMPILE);
  pfglPixelTransferf(GL_RED_SCALE, 5.0f);
  pfglPixelMapuiv(GL_PIXEL_MAP_B_TO_B, 4, entries);
  pfglPixelMapfv(GL_PIXEL_MAP_I_TO_R, 3, nullptr);
  pfglPixelTransferi(0x1234, 1);
  pfglEndList();
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(number(GL_RED_SCALE), 1.0f);
  EXPECT_EQ(integer(GL_PIXEL_MAP_B_TO_B_SIZE), 1);
  entries[1] = 0;  // (copied when compiled)
  pfglCallList(1);
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));  // (the first error the list raised)
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(number(GL_RED_SCALE), 5.0f);
  GLfloat f[4];
  pfglGetPixelMapfv(GL_PIXEL_MAP_B_TO_B, f);
  EXPECT_EQ(integer(GL_PIXEL_MAP_B_TO_B_SIZE), 4);
  EXPECT_EQ(f[1], 0.5f);
  EXPECT_EQ(f[2], 1.0f);
}

// glReadPixels under scale and bias, then the colour maps (indexed round(c (n - 1)), halves to
// even): OSMesa's bytes for the same framebuffer.
TEST(PixelMaps, ReadPixelsTransfersColours) {
  pf::test::GlContext c(4, 1);
  pfglClearColor(10 / 255.0f, 100 / 255.0f, 200 / 255.0f, 1.0f);
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglPixelTransferf(GL_RED_SCALE, 0.5f);
  pfglPixelTransferf(GL_GREEN_BIAS, 0.25f);
  pfglPixelTransferf(GL_BLUE_SCALE, 2.0f);
  pfglPixelTransferf(GL_BLUE_BIAS, -0.5f);
  pfglPixelTransferf(GL_ALPHA_SCALE, 0.75f);
  GLubyte px[4];
  pfglReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(px[0], 5);
  EXPECT_EQ(px[1], 164);
  EXPECT_EQ(px[2], 255);
  EXPECT_EQ(px[3], 191);
  GLfloat f[4];
  pfglReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, f);
  EXPECT_NEAR(f[2], 1.068628, 1e-6);  // (a float read is not clamped)
  const GLfloat r[4] = {0, 0.2f, 0.7f, 1}, g[2] = {0.9f, 0.1f}, a[1] = {0.6f};
  pfglPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, r);
  pfglPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, g);
  pfglPixelMapfv(GL_PIXEL_MAP_A_TO_A, 1, a);
  pfglPixelTransferi(GL_MAP_COLOR, 1);
  pfglReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(px[0], 0);
  EXPECT_EQ(px[1], 26);
  EXPECT_EQ(px[2], 0);  // B_TO_B's one entry, 0
  EXPECT_EQ(px[3], 153);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
}

// A display list keeps glTexImage's and glDrawPixels' images as unpacked and transfers them
// when it runs (as Mesa, which replays the command with the raw image): the tables and modes
// in effect then, not when compiled. (OSMesa gives the same bytes for the same calls.)
TEST(PixelMaps, ListsTransferImagesWhenTheyRun) {
  pf::test::GlContext c(4, 1);
  const GLubyte indices[2] = {1, 2};
  const GLubyte rgba[4] = {100, 100, 100, 200};
  pfglNewList(1, GL_COMPILE);
  pfglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, indices);
  pfglRasterPos2f(-0.99f, -0.99f);
  pfglDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  pfglEndList();
  const GLfloat red[4] = {0.0f, 0.25f, 0.5f, 1.0f};
  pfglPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, red);
  pfglPixelTransferi(GL_INDEX_OFFSET, 1);  // index 1 -> 2, 2 -> 3
  pfglPixelTransferf(GL_RED_SCALE, 0.5f);  // (not applied to colour indices)
  pfglCallList(1);
  GLubyte texels[8];
  pfglGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  EXPECT_EQ(texels[0], 128);  // 0.5
  EXPECT_EQ(texels[4], 255);  // 1.0
  EXPECT_EQ(texels[3], 0);    // I_TO_A's one entry, 0
  pfglFinish();
  EXPECT_EQ(c.at(0, 0)[0], 50);  // 100 scaled by 0.5
  EXPECT_EQ(c.at(0, 0)[3], 200);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
}
