// The vertex attribute entry points -- glVertex, glColor, glNormal, glTexCoord, glEdgeFlag in
// every form GL 1.x has -- and glRect. Each form converts its arguments to one recorded command
// (commands.h; the work is in immediate_mode.cpp): integer colours and normals are normalised
// as GL 1.5 table 2.9 says (normalized.h), other integers and doubles are taken as values, a
// 3-component colour gets alpha 1, glTexCoord1 to 3 fill the rest of (s, t, r, q) with
// (0, 0, 1). The vector forms ignore a NULL pointer.
#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/normalized.h"

namespace {

using pf::dispatch;
using pf::GlOp;

template <class T>
float unit(T c) {  // a colour or normal component
  return static_cast<float>(pf::normalized(c));
}

template <class T>
float value(T c) {  // a texture coordinate
  return static_cast<float>(c);
}

}  // namespace

namespace pf::cmd {

// glRect: a polygon with the rectangle's corners, counter-clockwise from (x1, y1) (GL 1.5
// section 2.10). Not between glBegin and glEnd.
void rect(PFcontextRec& ctx, GLdouble x1, GLdouble y1, GLdouble x2, GLdouble y2) {
  if (!outsideBegin(ctx)) return;
  begin(ctx, GL_POLYGON);
  vertex(ctx, x1, y1, 0.0, 1.0, 2);
  vertex(ctx, x2, y1, 0.0, 1.0, 2);
  vertex(ctx, x2, y2, 0.0, 1.0, 2);
  vertex(ctx, x1, y2, 0.0, 1.0, 2);
  end(ctx);
}

}  // namespace pf::cmd

// glVertex2, 3 and 4 and their vector forms for a component type; z = 0, w = 1 where missing.
#define PF_VERTEX_FORMS(T, s)                                                                           \
  void pfglVertex2##s(T x, T y) { dispatch<GlOp::Vertex>(double(x), double(y), 0.0, 1.0, 2); }           \
  void pfglVertex3##s(T x, T y, T z) { dispatch<GlOp::Vertex>(double(x), double(y), double(z), 1.0, 3); } \
  void pfglVertex4##s(T x, T y, T z, T w) {                                                              \
    dispatch<GlOp::Vertex>(double(x), double(y), double(z), double(w), 4);                               \
  }                                                                                                      \
  void pfglVertex2##s##v(const T* v) {                                                                   \
    if (v) pfglVertex2##s(v[0], v[1]);                                                                   \
  }                                                                                                      \
  void pfglVertex3##s##v(const T* v) {                                                                   \
    if (v) pfglVertex3##s(v[0], v[1], v[2]);                                                             \
  }                                                                                                      \
  void pfglVertex4##s##v(const T* v) {                                                                   \
    if (v) pfglVertex4##s(v[0], v[1], v[2], v[3]);                                                       \
  }

// glColor3 and 4 and their vector forms.
#define PF_COLOR_FORMS(T, s)                                                                             \
  void pfglColor3##s(T r, T g, T b) { dispatch<GlOp::Color>(unit(r), unit(g), unit(b), 1.0f); }          \
  void pfglColor4##s(T r, T g, T b, T a) { dispatch<GlOp::Color>(unit(r), unit(g), unit(b), unit(a)); }  \
  void pfglColor3##s##v(const T* v) {                                                                    \
    if (v) pfglColor3##s(v[0], v[1], v[2]);                                                              \
  }                                                                                                      \
  void pfglColor4##s##v(const T* v) {                                                                    \
    if (v) pfglColor4##s(v[0], v[1], v[2], v[3]);                                                        \
  }

#define PF_NORMAL_FORMS(T, s)                                                                            \
  void pfglNormal3##s(T x, T y, T z) { dispatch<GlOp::Normal>(unit(x), unit(y), unit(z)); }              \
  void pfglNormal3##s##v(const T* v) {                                                                   \
    if (v) pfglNormal3##s(v[0], v[1], v[2]);                                                             \
  }

#define PF_TEXCOORD_FORMS(T, s)                                                                          \
  void pfglTexCoord1##s(T a) { dispatch<GlOp::TexCoord>(value(a), 0.0f, 0.0f, 1.0f); }                   \
  void pfglTexCoord2##s(T a, T b) { dispatch<GlOp::TexCoord>(value(a), value(b), 0.0f, 1.0f); }          \
  void pfglTexCoord3##s(T a, T b, T c) { dispatch<GlOp::TexCoord>(value(a), value(b), value(c), 1.0f); } \
  void pfglTexCoord4##s(T a, T b, T c, T d) {                                                            \
    dispatch<GlOp::TexCoord>(value(a), value(b), value(c), value(d));                                    \
  }                                                                                                      \
  void pfglTexCoord1##s##v(const T* v) {                                                                 \
    if (v) pfglTexCoord1##s(v[0]);                                                                       \
  }                                                                                                      \
  void pfglTexCoord2##s##v(const T* v) {                                                                 \
    if (v) pfglTexCoord2##s(v[0], v[1]);                                                                 \
  }                                                                                                      \
  void pfglTexCoord3##s##v(const T* v) {                                                                 \
    if (v) pfglTexCoord3##s(v[0], v[1], v[2]);                                                           \
  }                                                                                                      \
  void pfglTexCoord4##s##v(const T* v) {                                                                 \
    if (v) pfglTexCoord4##s(v[0], v[1], v[2], v[3]);                                                     \
  }

#define PF_RECT_FORMS(T, s)                                                                               \
  void pfglRect##s(T x1, T y1, T x2, T y2) { dispatch<GlOp::Rect>(double(x1), double(y1), double(x2), double(y2)); } \
  void pfglRect##s##v(const T* v1, const T* v2) {                                                         \
    if (v1 && v2) pfglRect##s(v1[0], v1[1], v2[0], v2[1]);                                                \
  }

extern "C" {

// Vertices in float go through the compact commands of 2 and 3 floats.
void pfglVertex2f(GLfloat x, GLfloat y) { dispatch<GlOp::Vertex2f>(x, y); }
void pfglVertex3f(GLfloat x, GLfloat y, GLfloat z) { dispatch<GlOp::Vertex3f>(x, y, z); }
void pfglVertex4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) { dispatch<GlOp::Vertex>(x, y, z, w, 4); }
void pfglVertex2fv(const GLfloat* v) { if (v) pfglVertex2f(v[0], v[1]); }
void pfglVertex3fv(const GLfloat* v) { if (v) pfglVertex3f(v[0], v[1], v[2]); }
void pfglVertex4fv(const GLfloat* v) { if (v) pfglVertex4f(v[0], v[1], v[2], v[3]); }
PF_VERTEX_FORMS(GLdouble, d)
PF_VERTEX_FORMS(GLint, i)
PF_VERTEX_FORMS(GLshort, s)

PF_COLOR_FORMS(GLbyte, b)
PF_COLOR_FORMS(GLubyte, ub)
PF_COLOR_FORMS(GLshort, s)
PF_COLOR_FORMS(GLushort, us)
PF_COLOR_FORMS(GLint, i)
PF_COLOR_FORMS(GLuint, ui)
PF_COLOR_FORMS(GLfloat, f)
PF_COLOR_FORMS(GLdouble, d)

PF_NORMAL_FORMS(GLbyte, b)
PF_NORMAL_FORMS(GLshort, s)
PF_NORMAL_FORMS(GLint, i)
PF_NORMAL_FORMS(GLfloat, f)
PF_NORMAL_FORMS(GLdouble, d)

PF_TEXCOORD_FORMS(GLshort, s)
PF_TEXCOORD_FORMS(GLint, i)
PF_TEXCOORD_FORMS(GLfloat, f)
PF_TEXCOORD_FORMS(GLdouble, d)

PF_RECT_FORMS(GLshort, s)
PF_RECT_FORMS(GLint, i)
PF_RECT_FORMS(GLfloat, f)
PF_RECT_FORMS(GLdouble, d)

// The edge flag (GL 1.5 section 2.6.2): which edges of a polygon drawn GL_LINE or GL_POINT are
// its boundary (primitives/triangles.pfl reads it as the "edge_flag" parameter).
void pfglEdgeFlag(GLboolean flag) { dispatch<GlOp::EdgeFlag>(flag); }
void pfglEdgeFlagv(const GLboolean* flag) {
  if (flag) pfglEdgeFlag(*flag);
}

}  // extern "C"
