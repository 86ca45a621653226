// Display lists: every family of recorded commands does, replayed from a list, exactly what it
// does issued directly -- the whole GL state (every glGet value, every light and material,
// the named parameters' current values, the shading bindings), the error and the image are
// compared -- under GL_COMPILE (which must change nothing until the list is called) and
// GL_COMPILE_AND_EXECUTE. Then what is not recorded, the name bookkeeping, limits, and bad
// input. (OSMesa's behaviour for the same commands: tests/conformance/cases_lists.inc.)
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <chrono>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "api/src/context_state.h"
#include "gl_context.h"

namespace {

constexpr int kW = 48, kH = 48;

// A context in window coordinates, cleared to dark grey.
struct Ctx : pf::test::GlContext {
  Ctx() : GlContext(kW, kH) {
    pfglMatrixMode(GL_PROJECTION);
    pfglOrtho(0, kW, 0, kH, -1, 1);
    pfglMatrixMode(GL_MODELVIEW);
    pfglClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
};

// Everything a command could have changed, as numbers, and the image.
struct Snapshot {
  std::vector<double> state;
  std::vector<unsigned char> pixels;
  GLenum error = GL_NO_ERROR;
};

const GLenum kQueries[] = {
    GL_VIEWPORT, GL_DEPTH_RANGE, GL_COLOR_CLEAR_VALUE, GL_DEPTH_CLEAR_VALUE, GL_DEPTH_FUNC, GL_DEPTH_WRITEMASK,
    GL_DEPTH_TEST, GL_CULL_FACE, GL_CULL_FACE_MODE, GL_FRONT_FACE, GL_SHADE_MODEL, GL_COLOR_WRITEMASK,
    GL_MATRIX_MODE, GL_MODELVIEW_MATRIX, GL_PROJECTION_MATRIX, GL_TEXTURE_MATRIX, GL_MODELVIEW_STACK_DEPTH,
    GL_PROJECTION_STACK_DEPTH, GL_TEXTURE_STACK_DEPTH, GL_LIGHTING, GL_COLOR_MATERIAL, GL_COLOR_MATERIAL_FACE,
    GL_COLOR_MATERIAL_PARAMETER, GL_NORMALIZE, GL_RESCALE_NORMAL, GL_PER_PIXEL_LIGHTING_EXT,
    GL_LIGHT_MODEL_AMBIENT, GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE, GL_VERTEX_ARRAY, GL_COLOR_ARRAY,
    GL_NORMAL_ARRAY, GL_CURRENT_COLOR, GL_CURRENT_NORMAL, GL_CURRENT_TEXTURE_COORDS, GL_PACK_ALIGNMENT,
    GL_LIST_BASE, GL_PERSPECTIVE_CORRECTION_HINT, GL_FOG_HINT, GL_ATTRIB_STACK_DEPTH, GL_LIGHT0, GL_LIGHT1, GL_LIGHT2, GL_LIGHT3, GL_LIGHT4, GL_LIGHT5, GL_LIGHT6, GL_LIGHT7};

Snapshot snapshot(const Ctx& c) {
  Snapshot s;
  for (GLenum q : kQueries) {
    GLdouble v[16];
    std::fill(std::begin(v), std::end(v), -7.0);
    pfglGetDoublev(q, v);
    s.state.insert(s.state.end(), std::begin(v), std::end(v));
  }
  const GLenum light_params[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION, GL_SPOT_DIRECTION,
                                 GL_SPOT_EXPONENT, GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION,
                                 GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION};
  for (GLenum l = GL_LIGHT0; l <= GL_LIGHT7; ++l)
    for (GLenum p : light_params) {
      GLfloat v[4] = {-7, -7, -7, -7};
      pfglGetLightfv(l, p, v);
      s.state.insert(s.state.end(), std::begin(v), std::end(v));
    }
  for (GLenum face : {GL_FRONT, GL_BACK})
    for (GLenum p : {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS}) {
      GLfloat v[4] = {-7, -7, -7, -7};
      pfglGetMaterialfv(face, p, v);
      s.state.insert(s.state.end(), std::begin(v), std::end(v));
    }
  // What GL cannot query: the named parameters' current values, the shading bindings.
  const PFcontextRec& ctx = *c.ctx;
  for (const pf::ParamValue& p : ctx.current_params) {
    s.state.push_back(p.count);
    s.state.insert(s.state.end(), std::begin(p.v), std::end(p.v));
  }
  for (const auto& [mode, bound] : ctx.shading_bindings)
    for (const auto& [param, interpolator] : bound) s.state.insert(s.state.end(), {double(mode), double(param), double(interpolator)});
  s.state.push_back(ctx.in_begin);
  s.error = pfglGetError();
  pfglFinish();
  s.pixels = c.px;
  return s;
}

void expectSame(const Snapshot& want, const Snapshot& got, const std::string& what) {
  EXPECT_EQ(got.error, want.error) << what;
  ASSERT_EQ(got.state.size(), want.state.size()) << what;
  for (size_t i = 0; i < want.state.size(); ++i) {
    // (NaN never arises here; the values are compared exactly.)
    EXPECT_EQ(got.state[i], want.state[i]) << what << ": state value " << i;
  }
  size_t differing = 0;
  for (size_t i = 0; i < want.pixels.size(); ++i) differing += got.pixels[i] != want.pixels[i];
  EXPECT_EQ(differing, 0u) << what << ": image bytes differ";
}

// A family of commands: `prepare` runs first in every context (never recorded: lists and names
// the commands use), `commands` is what is issued directly or recorded.
struct Family {
  const char* name;
  std::function<void()> prepare;
  std::function<void()> commands;
};

void drawTriangle(float x, float y) {
  pfglBegin(GL_TRIANGLES);
  pfglVertex2f(x, y);
  pfglVertex2f(x + 20.0f, y + 2.0f);
  pfglVertex2f(x + 4.0f, y + 18.0f);
  pfglEnd();
}

std::vector<Family> families() {
  auto none = [] {};
  std::vector<Family> f;
  f.push_back({"framebuffer state", none, [] {
                 drawTriangle(4, 4);
                 pfglClearColor(0.25f, 0.5f, 2.0f, -1.0f);
                 pfglClearDepth(0.75);
                 pfglColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
                 pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
                 pfglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
                 pfglViewport(2, 3, 40, 41);
                 pfglDepthFunc(GL_GEQUAL);
                 pfglDepthMask(GL_FALSE);
                 pfglDepthRange(0.2, 0.9);
                 pfglEnable(GL_DEPTH_TEST);
                 drawTriangle(10, 10);
               }});
  f.push_back({"enables and modes", none, [] {
                 for (GLenum cap : {GL_CULL_FACE, GL_LIGHTING, GL_LIGHT3, GL_COLOR_MATERIAL, GL_NORMALIZE,
                                    GL_RESCALE_NORMAL, GL_PER_PIXEL_LIGHTING_EXT, GL_DEPTH_TEST})
                   pfglEnable(cap);
                 pfglDisable(GL_LIGHTING);
                 pfglDisable(GL_DEPTH_TEST);
                 pfglCullFace(GL_FRONT);
                 pfglFrontFace(GL_CW);
                 pfglShadeModel(GL_FLAT);
                 pfglColor3f(0.2f, 0.9f, 0.4f);
                 drawTriangle(5, 5);
               }});
  f.push_back({"lighting", none, [] {
                 const GLfloat pos[4] = {1, 2, 3, 1}, col[4] = {0.5f, 0.25f, 0.125f, 1}, dir[3] = {0, -1, -1};
                 const GLint icol[4] = {2147483647, 1073741823, 0, 2147483647}, ipos[4] = {3, 2, 1, 0};
                 pfglTranslatef(1, 2, 0);
                 pfglLightfv(GL_LIGHT1, GL_POSITION, pos);
                 pfglLightiv(GL_LIGHT2, GL_POSITION, ipos);
                 pfglLightfv(GL_LIGHT1, GL_DIFFUSE, col);
                 pfglLightiv(GL_LIGHT1, GL_SPECULAR, icol);
                 pfglLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, dir);
                 pfglLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 45);
                 pfglLighti(GL_LIGHT1, GL_SPOT_EXPONENT, 7);
                 pfglLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.5f);
                 pfglLightModelfv(GL_LIGHT_MODEL_AMBIENT, col);
                 pfglLightModeliv(GL_LIGHT_MODEL_AMBIENT, icol);
                 pfglLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
                 pfglLightModelf(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
                 pfglMaterialfv(GL_FRONT, GL_EMISSION, col);
                 pfglMaterialiv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, icol);
                 pfglMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 12.5f);
                 pfglMateriali(GL_BACK, GL_SHININESS, 3);
                 pfglColorMaterial(GL_BACK, GL_SPECULAR);
                 pfglEnable(GL_LIGHTING);
                 pfglEnable(GL_LIGHT1);
                 pfglNormal3f(0.0f, 0.6f, 0.8f);
                 pfglBegin(GL_TRIANGLES);
                 pfglMaterialfv(GL_FRONT, GL_DIFFUSE, col);  // inside glBegin, per vertex
                 pfglVertex2f(3, 3);
                 pfglVertex2f(40, 8);
                 pfglMaterialf(GL_FRONT, GL_SHININESS, 80);
                 pfglVertex2f(10, 40);
                 pfglEnd();
               }});
  f.push_back({"matrices", none, [] {
                 const GLfloat mf[16] = {1, 0.1f, 0, 0, 0, 1, 0.2f, 0, 0, 0, 1, 0, 0.5f, 0.25f, 0, 1};
                 const GLdouble md[16] = {0.9, 0, 0, 0, 0, 1.1, 0, 0, 0, 0, 1, 0, 1, 2, 0, 1};
                 pfglMatrixMode(GL_TEXTURE);
                 pfglLoadMatrixd(md);
                 pfglRotated(12.5, 0, 0, 1);
                 pfglMatrixMode(GL_PROJECTION);
                 pfglPushMatrix();
                 pfglLoadIdentity();
                 pfglOrtho(-1, kW, -2, kH, -5, 5);
                 pfglFrustum(-1, 1, -1, 1, 1, 3);
                 pfglPopMatrix();
                 pfglMatrixMode(GL_MODELVIEW);
                 pfglPushMatrix();
                 pfglLoadMatrixf(mf);
                 pfglMultMatrixd(md);
                 pfglMultMatrixf(mf);
                 pfglTranslated(1.5, 0.5, 0);
                 pfglScaled(1.1, 0.9, 1);
                 pfglRotatef(5, 0, 0, 1);
                 pfglScalef(0.9f, 1.0f, 1.0f);
                 pfglTranslatef(0.25f, 0, 0);
                 pfglPushMatrix();
                 pfglRotatef(0, 0, 0, 0);  // a zero axis: unchanged
                 drawTriangle(3, 3);
                 pfglPopMatrix();
               }});
  f.push_back({"immediate mode, every vertex attribute form", none, [] {
                 const GLfloat v2[2] = {30, 30}, v3[3] = {40, 30, 0}, v4[4] = {70, 80, 0, 2};
                 const GLdouble d2[2] = {3, 30}, d3[3] = {3, 44, 0}, d4[4] = {40, 88, 0, 2};
                 const GLfloat c3[3] = {0.1f, 0.2f, 0.3f}, c4[4] = {0.3f, 0.2f, 0.1f, 0.5f}, n[3] = {0, 0, 1};
                 pfglBegin(GL_TRIANGLES);
                 pfglColor3f(1, 0, 0);
                 pfglVertex2f(2, 2);
                 pfglColor4f(0, 1, 0, 1);
                 pfglVertex3f(20, 2, 0);
                 pfglColor3ub(10, 200, 30);
                 pfglVertex4f(4, 40, 0, 2);
                 pfglColor4ub(200, 10, 30, 128);
                 pfglVertex2d(24, 4);
                 pfglColor3fv(c3);
                 pfglVertex3d(44, 6, 0);
                 pfglColor4fv(c4);
                 pfglVertex4d(50, 50, 0, 2);
                 pfglNormal3fv(n);
                 pfglNormal3f(0.1f, 0.2f, 0.9f);
                 pfglTexCoord1f(0.5f);
                 pfglVertex2fv(v2);
                 pfglVertex3fv(v3);
                 pfglTexCoord2f(0.25f, 0.75f);
                 pfglVertex4fv(v4);
                 pfglVertex2dv(d2);
                 pfglVertex3dv(d3);
                 pfglVertex4dv(d4);
                 pfglEnd();
                 pfglBegin(GL_LINE_LOOP);
                 pfglVertex2f(1, 1);
                 pfglVertex2f(46, 1);
                 pfglVertex2f(46, 46);
                 pfglEnd();
                 pfglColor3f(0.5f, 0.5f, 0.5f);  // outside glBegin: current values
                 pfglVertex2f(9, 9);               // ignored outside glBegin
               }});
  f.push_back({"attribute forms of every type, glRect", none, [] {
                 const GLbyte b[3] = {-100, 50, 127};
                 const GLushort us[4] = {1, 30000, 65535, 40000};
                 const GLint i[4] = {30, 4, 40, 2};
                 const GLdouble d[4] = {0.5, 0.25, 0.125, 1.0};
                 pfglNormal3bv(b);
                 pfglTexCoord3d(d[0], d[1], d[2]);
                 pfglBegin(GL_TRIANGLES);
                 pfglColor4usv(us);
                 pfglVertex2s(2, 2);
                 pfglColor3bv(b);
                 pfglVertex4iv(i);
                 pfglColor4dv(d);
                 pfglVertex3i(3, 40, 0);
                 pfglEnd();
                 pfglColor3ui(4000000000u, 0, 2000000000u);
                 pfglTexCoord1s(7);
                 pfglRectd(30.5, 30.5, 45.0, 20.0);
                 pfglRectiv(i + 2, i);
               }});
  f.push_back({"attribute stack, hints", none, [] {
                 pfglHint(GL_FOG_HINT, GL_NICEST);
                 pfglPushAttrib(GL_LIGHTING_BIT | GL_HINT_BIT);
                 pfglShadeModel(GL_FLAT);
                 pfglHint(GL_FOG_HINT, GL_FASTEST);
                 pfglHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
                 pfglPopAttrib();
                 pfglPushAttrib(GL_VIEWPORT_BIT);  // left pushed
                 pfglViewport(1, 1, 20, 20);
                 pfglHint(0x1234, GL_NICEST);
               }});
  f.push_back({"vertex arrays", [] {
                 static const GLfloat xy[8] = {2, 2, 40, 4, 6, 40, 44, 44};
                 static const GLubyte rgb[12] = {250, 20, 20, 20, 250, 20, 20, 20, 250, 240, 240, 30};
                 static const GLshort normals[12] = {0, 0, 32767, 0, 32767, 0, 32767, 0, 0, 0, 0, 32767};
                 pfglVertexPointer(2, GL_FLOAT, 0, xy);
                 pfglColorPointer(3, GL_UNSIGNED_BYTE, 0, rgb);
                 static const GLdouble st[8] = {0.5, 0.25, 1, 2, 3, 4, 5, 6};
                 pfglNormalPointer(GL_SHORT, 0, normals);
                 pfglTexCoordPointer(2, GL_DOUBLE, 0, st);
                 pfglEnableClientState(GL_TEXTURE_COORD_ARRAY);
                 pfglEnableClientState(GL_VERTEX_ARRAY);
                 pfglEnableClientState(GL_COLOR_ARRAY);
                 pfglEnableClientState(GL_NORMAL_ARRAY);
               },
               [] {
                 static const GLuint indices[3] = {3, 2, 1};
                 pfglDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
                 pfglTranslatef(2, 1, 0);
                 pfglDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, indices);
                 pfglBegin(GL_LINES);
                 pfglArrayElement(0);
                 pfglArrayElement(3);
                 pfglEnd();
                 pfglArrayElement(2);  // outside glBegin: colour and normal only
               }});
  f.push_back({"the extension: named parameters, sequence points, interpolators", [] {
                 pfglGetParamNameEXT("center");
                 pfglGetParamNameEXT("radius");
                 pfglGetParamNameEXT("weights");
                 pfglGetParamNameEXT("texture_scale");
               },
               [] {
                 const GLuint center = pfglGetParamNameEXT("center"), radius = pfglGetParamNameEXT("radius");
                 const GLuint weights = pfglGetParamNameEXT("weights");
                 const GLfloat w[5] = {1, 2, 3, 4, 5};
                 const GLint wi[3] = {7, -8, 9};
                 const GLenum sphere = pfglGetPrimitiveEXT("sphere");
                 pfglRastParamfvEXT(weights, 5, w);
                 pfglRastParamivEXT(weights, 3, wi);
                 pfglRastParamiEXT(pfglGetParamNameEXT("texture_scale"), 3);
                 pfglMaterialInterpEXT(pfglGetParamNameEXT("color"), GL_TRIANGLES, pfglGetInterpolatorEXT("planar"));
                 pfglMaterialInterpEXT(pfglGetParamNameEXT("color"), GL_TRIANGLES, GL_PERSPECTIVE_LINEAR_INTERPOLATOR_EXT);
                 pfglBegin(sphere);
                 pfglColor3f(0.9f, 0.5f, 0.1f);
                 pfglRastParamfEXT(radius, 8.0f);
                 pfglRastParam3fEXT(center, 14, 14, 0);
                 pfglSequencePointEXT();
                 pfglMaterialf(GL_FRONT, radius, 5.0f);  // glMaterial on a parameter name
                 pfglRastParam4fEXT(center, 60, 60, 0, 2);
                 pfglSequencePointEXT();
                 pfglEnd();
               }});
  f.push_back({"lists inside lists, glListBase, glCallLists", [] {
                 for (GLuint n = 1; n <= 3; ++n) {
                   pfglNewList(n, GL_COMPILE);
                   pfglColor3f(0.3f * static_cast<float>(n), 0.2f, 0.9f);
                   drawTriangle(4.0f * static_cast<float>(n), 2.0f);
                   pfglTranslatef(3, 5, 0);
                   pfglEndList();
                 }
               },
               [] {
                 const GLubyte ids[4] = {2, 0, 1, 2};
                 pfglCallList(1);
                 pfglListBase(1);
                 pfglCallLists(4, GL_UNSIGNED_BYTE, ids);
                 pfglListBase(0);
               }});
  f.push_back({"errors, each raised when it executes", none, [] {
                 pfglEnable(0x1234);  // the first one sticks
                 pfglPopMatrix();
                 pfglBegin(GL_TRIANGLES);
                 pfglClear(GL_COLOR_BUFFER_BIT);  // not in glBegin: GL_INVALID_OPERATION, nothing cleared
                 pfglVertex2f(1, 1);
                 pfglVertex2f(30, 1);
                 pfglVertex2f(1, 30);
                 pfglEnd();
                 pfglEnd();
                 pfglDrawArrays(0x1234, 0, 3);
                 pfglRastParamfvEXT(12345, 17, nullptr);
                 pfglLightfv(GL_LIGHT0, GL_POSITION, nullptr);  // NULL: ignored
                 pfglLoadMatrixf(nullptr);
               }});
  return f;
}

enum class Way { Direct, Compile, CompileAndExecute };

Snapshot run(const Family& family, Way way) {
  Ctx c;
  family.prepare();
  if (way == Way::Direct) {
    family.commands();
    return snapshot(c);
  }
  if (way == Way::Compile) {
    const Snapshot before = snapshot(c);
    pfglNewList(100, GL_COMPILE);
    family.commands();
    pfglEndList();
    expectSame(before, snapshot(c), std::string(family.name) + ": compiling changed something");
    pfglCallList(100);
    return snapshot(c);
  }
  pfglNewList(100, GL_COMPILE_AND_EXECUTE);
  family.commands();
  pfglEndList();
  return snapshot(c);
}

}  // namespace

TEST(DisplayLists, EveryCommandFamilyReplaysAsIssuedDirectly) {
  for (const Family& family : families()) {
    const Snapshot direct = run(family, Way::Direct);
    expectSame(direct, run(family, Way::Compile), std::string(family.name) + ", GL_COMPILE then glCallList");
    expectSame(direct, run(family, Way::CompileAndExecute), std::string(family.name) + ", GL_COMPILE_AND_EXECUTE");
  }
}

// The same list called twice does its commands twice; a list of commands changes the state
// the next call starts from (here: the modelview, a translation per call).
TEST(DisplayLists, EachCallRunsTheCommandsAgain) {
  Ctx c;
  pfglNewList(3, GL_COMPILE);
  pfglTranslatef(1.5f, 0, 0);
  pfglEndList();
  for (int i = 0; i < 5; ++i) pfglCallList(3);
  GLfloat m[16];
  pfglGetFloatv(GL_MODELVIEW_MATRIX, m);
  EXPECT_EQ(m[12], 7.5f);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// Commands GL never compiles run at once while a list is compiled, and are not in it.
TEST(DisplayLists, CommandsNeverCompiledExecuteAtOnce) {
  Ctx c;
  static const GLfloat xy[6] = {1, 1, 30, 1, 1, 30};
  pfglNewList(7, GL_COMPILE);
  pfglPixelStorei(GL_PACK_ALIGNMENT, 2);
  pfglVertexPointer(2, GL_FLOAT, 0, xy);
  pfglEnableClientState(GL_VERTEX_ARRAY);
  pfglEnableClientState(GL_NORMAL_ARRAY);
  pfglDisableClientState(GL_NORMAL_ARRAY);
  const GLuint generated = pfglGenLists(2);
  EXPECT_EQ(generated, 1u);
  EXPECT_EQ(pfglIsList(generated), GL_TRUE);
  pfglDeleteLists(generated + 1, 1);
  EXPECT_EQ(pfglIsList(generated + 1), GL_FALSE);
  EXPECT_EQ(pfglIsList(7), GL_FALSE) << "not a list before glEndList";
  GLint value = 0;
  pfglGetIntegerv(GL_PACK_ALIGNMENT, &value);
  EXPECT_EQ(value, 2);
  EXPECT_EQ(pfglIsEnabled(GL_VERTEX_ARRAY), GL_TRUE);
  pfglFinish();
  pfglFlush();
  unsigned char pixel[4] = {9, 9, 9, 9};
  pfglReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  EXPECT_NE(pixel[0], 9) << "read at once";
  EXPECT_NE(pfglGetString(GL_VERSION), nullptr);
  EXPECT_NE(pfglGetParamNameEXT("a_new_name"), 0u);
  const GLuint module = pfglCompilePrimitivesEXT("primitive nothing_at_all(inout varying float Z) { return; }\n");
  EXPECT_NE(module, 0u) << "compiled at once";
  EXPECT_NE(pfglGetPrimitiveEXT("nothing_at_all"), 0u);
  pfglEndList();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  // The list is empty: calling it changes none of that.
  pfglPixelStorei(GL_PACK_ALIGNMENT, 4);
  pfglDisableClientState(GL_VERTEX_ARRAY);
  EXPECT_EQ(pfglIsList(7), GL_TRUE);
  EXPECT_TRUE(c.ctx->lists.names->defined.at(7).empty());
  pfglCallList(7);
  pfglGetIntegerv(GL_PACK_ALIGNMENT, &value);
  EXPECT_EQ(value, 4);
  EXPECT_EQ(pfglIsEnabled(GL_VERTEX_ARRAY), GL_FALSE);
}

// A glBegin in one list and its glEnd in another draw as one primitive, as their commands
// issued in that order would (GL 1.5 section 5.4: a list's commands are as if issued there);
// a list of vertices alone called between glBegin and glEnd adds them to that primitive.
TEST(DisplayLists, APrimitiveMaySpanLists) {
  auto draw = [](bool lists) {
    Ctx c;
    if (lists) {
      pfglNewList(1, GL_COMPILE);
      pfglBegin(GL_TRIANGLES);
      pfglColor3f(1, 0, 0);
      pfglVertex2f(2, 2);
      pfglEndList();
      pfglNewList(2, GL_COMPILE);
      pfglVertex2f(40, 4);
      pfglVertex2f(6, 40);
      pfglEndList();
      pfglNewList(3, GL_COMPILE);
      pfglEnd();
      pfglEndList();
      pfglCallList(1);
      pfglCallList(2);
      pfglCallList(3);
      pfglBegin(GL_TRIANGLES);
      pfglColor3f(0, 1, 0);
      pfglVertex2f(46, 46);
      pfglCallList(2);
      pfglEnd();
    } else {
      pfglBegin(GL_TRIANGLES);
      pfglColor3f(1, 0, 0);
      pfglVertex2f(2, 2);
      pfglVertex2f(40, 4);
      pfglVertex2f(6, 40);
      pfglEnd();
      pfglBegin(GL_TRIANGLES);
      pfglColor3f(0, 1, 0);
      pfglVertex2f(46, 46);
      pfglVertex2f(40, 4);
      pfglVertex2f(6, 40);
      pfglEnd();
    }
    return snapshot(c);
  };
  expectSame(draw(false), draw(true), "a primitive across lists");
}

// glGenLists hands out the names above the highest in use, as Mesa; once those run out, the
// lowest free block. Ranges are kept as ranges: 2^31 - 1 names at once are cheap, and so is
// deleting them.
TEST(DisplayLists, NamesAreHandedOutAndFreedAsRanges) {
  Ctx c;
  EXPECT_EQ(pfglGenLists(3), 1u);
  pfglNewList(10, GL_COMPILE);
  pfglEndList();
  EXPECT_EQ(pfglGenLists(1), 11u);
  const auto start = std::chrono::steady_clock::now();
  const GLuint big = pfglGenLists(0x7fffffff);
  EXPECT_EQ(big, 12u);
  EXPECT_EQ(pfglIsList(big + 0x7ffffffe), GL_TRUE);
  EXPECT_EQ(pfglIsList(big + 0x7fffffff), GL_FALSE);
  pfglDeleteLists(20, 0x7fffffff);
  EXPECT_EQ(pfglIsList(19), GL_TRUE);
  EXPECT_EQ(pfglIsList(20), GL_FALSE);
  EXPECT_EQ(pfglIsList(big + 0x7ffffffe), GL_FALSE);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  // The names above the highest are taken by a list at the top: the lowest free block next
  // (in use: 1..3, 10, 11..19).
  pfglNewList(0xfffffffeu, GL_COMPILE);
  pfglEndList();
  EXPECT_EQ(pfglGenLists(2), 4u);
  EXPECT_EQ(pfglGenLists(5), 20u);
  pfglDeleteLists(2, 1);
  EXPECT_EQ(pfglGenLists(1), 2u);
  EXPECT_EQ(pfglGenLists(0x7fffffff), 25u);
  EXPECT_EQ(pfglGenLists(0x7fffffff), 0u) << "no block that large is left";
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  // glDeleteLists to the last name does not wrap around.
  pfglDeleteLists(0xfffffff0u, 100);
  EXPECT_EQ(pfglIsList(0xfffffffeu), GL_FALSE);
  EXPECT_EQ(pfglIsList(1), GL_TRUE);
}

// GL_MAX_LIST_NESTING: a list calling itself runs 64 deep, then the call is ignored, without
// an error, also through glCallLists and under GL_COMPILE_AND_EXECUTE.
TEST(DisplayLists, NestingStopsAtSixtyFourWithoutAnError) {
  Ctx c;
  GLint max = 0;
  pfglGetIntegerv(GL_MAX_LIST_NESTING, &max);
  EXPECT_EQ(max, 64);
  const GLint self = 1;
  pfglNewList(1, GL_COMPILE);
  pfglTranslatef(1, 0, 0);
  pfglCallLists(1, GL_INT, &self);
  pfglEndList();
  pfglCallList(1);
  GLfloat m[16];
  pfglGetFloatv(GL_MODELVIEW_MATRIX, m);
  EXPECT_EQ(m[12], 64.0f);
  pfglLoadIdentity();
  pfglNewList(2, GL_COMPILE_AND_EXECUTE);
  pfglCallList(1);
  pfglEndList();
  pfglGetFloatv(GL_MODELVIEW_MATRIX, m);
  EXPECT_EQ(m[12], 64.0f);
  pfglCallList(2);  // list 2 at depth 1: list 1 runs 63 deep under it
  pfglGetFloatv(GL_MODELVIEW_MATRIX, m);
  EXPECT_EQ(m[12], 127.0f);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// Vertex arrays are read when the list is compiled: what the list draws does not change with
// them afterwards, nor with the client state.
TEST(DisplayLists, ArraysAreReadWhenCompiled) {
  auto draw = [](bool list) {
    Ctx c;
    GLfloat xy[6] = {2, 2, 40, 4, 6, 40};
    pfglVertexPointer(2, GL_FLOAT, 0, xy);
    pfglEnableClientState(GL_VERTEX_ARRAY);
    if (list) {
      pfglNewList(5, GL_COMPILE);
      pfglDrawArrays(GL_TRIANGLES, 0, 3);
      pfglEndList();
      for (GLfloat& v : xy) v = 0;
      pfglDisableClientState(GL_VERTEX_ARRAY);
      pfglCallList(5);
    } else {
      pfglDrawArrays(GL_TRIANGLES, 0, 3);
      pfglDisableClientState(GL_VERTEX_ARRAY);
    }
    return snapshot(c);
  };
  expectSame(draw(false), draw(true), "arrays read when compiled");
}

// Bad input while compiling: huge and negative counts, NULL arrays, every glCallLists type
// out of range -- errors, never a crash; glGet of the list state.
TEST(DisplayLists, BadInputWhileCompilingAndTheListState) {
  Ctx c;
  GLint v = -1;
  pfglNewList(4, GL_COMPILE_AND_EXECUTE);
  pfglGetIntegerv(GL_LIST_INDEX, &v);
  EXPECT_EQ(v, 4);
  pfglGetIntegerv(GL_LIST_MODE, &v);
  EXPECT_EQ(v, GL_COMPILE_AND_EXECUTE);
  pfglCallLists(5, GL_INT, nullptr);
  pfglCallLists(-5, GL_FLOAT, nullptr);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  const GLfloat odd[4] = {1e30f, -1e30f, std::numeric_limits<float>::quiet_NaN(), 4294967296.0f};
  pfglCallLists(4, GL_FLOAT, odd);
  pfglRastParamfvEXT(pfglGetParamNameEXT("x"), 1 << 30, nullptr);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglRastParamivEXT(pfglGetParamNameEXT("x"), -3, nullptr);
  pfglMaterialfv(GL_FRONT, 0x1234, nullptr);
  pfglLightModelfv(0x1234, nullptr);
  pfglLightiv(GL_LIGHT0, 0x1234, nullptr);
  pfglMultMatrixd(nullptr);
  pfglListBase(static_cast<GLuint>(-5));
  pfglEndList();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglGetIntegerv(GL_LIST_INDEX, &v);
  EXPECT_EQ(v, 0);
  pfglGetIntegerv(GL_LIST_MODE, &v);
  EXPECT_EQ(v, 0);
  pfglGetIntegerv(GL_LIST_BASE, &v);
  EXPECT_EQ(v, -5);
  pfglCallList(4);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// Without a current context the list commands do nothing and return 0.
TEST(DisplayLists, NoContextNoEffect) {
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfglNewList(1, GL_COMPILE);
  pfglEndList();
  pfglCallList(1);
  pfglCallLists(1, GL_INT, nullptr);
  pfglListBase(2);
  pfglDeleteLists(1, 1);
  EXPECT_EQ(pfglGenLists(1), 0u);
  EXPECT_EQ(pfglIsList(1), GL_FALSE);
}

// The shorter glTexCoord forms fill what they do not give with (t, r, q) = (0, 0, 1), whatever
// came before (GL 1.5 section 2.7; OSMesa keeps stale components there, see cases_gl1x.inc).
TEST(VertexAttributes, ShorterTexCoordFormsFillZeroZeroOne) {
  Ctx c;
  GLfloat t[4];
  pfglTexCoord4f(9, 9, 9, 9);
  pfglTexCoord2s(5, 6);
  pfglGetFloatv(GL_CURRENT_TEXTURE_COORDS, t);
  EXPECT_EQ(std::vector<GLfloat>(t, t + 4), (std::vector<GLfloat>{5, 6, 0, 1}));
  pfglTexCoord3i(1, 2, 3);
  pfglTexCoord1d(0.5);
  pfglGetFloatv(GL_CURRENT_TEXTURE_COORDS, t);
  EXPECT_EQ(std::vector<GLfloat>(t, t + 4), (std::vector<GLfloat>{0.5f, 0, 0, 1}));
}

// Under GL_COMPILE_AND_EXECUTE, glEndList between glBegin and glEnd ends the list without an
// error (as Mesa does); the glBegin goes on and draws, and the list holds what came before.
TEST(DisplayLists, EndListInsideAnExecutingBegin) {
  Ctx c;
  pfglNewList(1, GL_COMPILE_AND_EXECUTE);
  pfglBegin(GL_TRIANGLES);
  pfglColor3f(1, 0, 0);
  pfglVertex2f(2, 2);
  pfglVertex2f(40, 2);
  pfglEndList();
  pfglVertex2f(2, 40);
  pfglEnd();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(pfglIsList(1), GL_TRUE);
  pfglFinish();
  EXPECT_EQ(c.at(8, 8)[0], 255) << "the triangle begun in the list and ended outside it is drawn";
  // Called later, the list opens a glBegin with two vertices; one more and glEnd complete it.
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglCallList(1);
  pfglVertex2f(2, 40);
  pfglEnd();
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(c.at(8, 8)[0], 255);
}
