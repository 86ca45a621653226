// The vertex attribute entry points: glVertex, glColor, glNormal, glTexCoord in their forms.
// Each converts its arguments to one recorded command (commands.h; the work is in
// immediate_mode.cpp): glColor3ub's bytes become floats, a 3-component colour gets alpha 1,
// glTexCoord1 and 2 fill t, r, q with 0, 0, 1. The vector forms ignore a NULL pointer.
#include <primflow/gl.h>

#include "api/src/commands.h"

namespace {

using pf::dispatch;
using pf::GlOp;

float unorm(GLubyte v) { return static_cast<float>(v) / 255.0f; }

}  // namespace

extern "C" {

void pfglVertex2f(GLfloat x, GLfloat y) { dispatch<GlOp::Vertex2f>(x, y); }
void pfglVertex3f(GLfloat x, GLfloat y, GLfloat z) { dispatch<GlOp::Vertex3f>(x, y, z); }
void pfglVertex4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) { dispatch<GlOp::Vertex>(x, y, z, w, 4); }
void pfglVertex2d(GLdouble x, GLdouble y) { dispatch<GlOp::Vertex>(x, y, 0.0, 1.0, 2); }
void pfglVertex3d(GLdouble x, GLdouble y, GLdouble z) { dispatch<GlOp::Vertex>(x, y, z, 1.0, 3); }
void pfglVertex4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w) { dispatch<GlOp::Vertex>(x, y, z, w, 4); }
void pfglVertex2fv(const GLfloat* v) { if (v) pfglVertex2f(v[0], v[1]); }
void pfglVertex3fv(const GLfloat* v) { if (v) pfglVertex3f(v[0], v[1], v[2]); }
void pfglVertex4fv(const GLfloat* v) { if (v) pfglVertex4f(v[0], v[1], v[2], v[3]); }
void pfglVertex2dv(const GLdouble* v) { if (v) pfglVertex2d(v[0], v[1]); }
void pfglVertex3dv(const GLdouble* v) { if (v) pfglVertex3d(v[0], v[1], v[2]); }
void pfglVertex4dv(const GLdouble* v) { if (v) pfglVertex4d(v[0], v[1], v[2], v[3]); }

void pfglColor3f(GLfloat r, GLfloat g, GLfloat b) { dispatch<GlOp::Color>(r, g, b, 1.0f); }
void pfglColor4f(GLfloat r, GLfloat g, GLfloat b, GLfloat a) { dispatch<GlOp::Color>(r, g, b, a); }
void pfglColor3fv(const GLfloat* v) { if (v) pfglColor3f(v[0], v[1], v[2]); }
void pfglColor4fv(const GLfloat* v) { if (v) pfglColor4f(v[0], v[1], v[2], v[3]); }
void pfglColor3ub(GLubyte r, GLubyte g, GLubyte b) { pfglColor3f(unorm(r), unorm(g), unorm(b)); }
void pfglColor4ub(GLubyte r, GLubyte g, GLubyte b, GLubyte a) { pfglColor4f(unorm(r), unorm(g), unorm(b), unorm(a)); }

void pfglNormal3f(GLfloat x, GLfloat y, GLfloat z) { dispatch<GlOp::Normal>(x, y, z); }
void pfglNormal3fv(const GLfloat* v) { if (v) pfglNormal3f(v[0], v[1], v[2]); }

void pfglTexCoord1f(GLfloat s) { dispatch<GlOp::TexCoord>(s, 0.0f, 0.0f, 1.0f); }
void pfglTexCoord2f(GLfloat s, GLfloat t) { dispatch<GlOp::TexCoord>(s, t, 0.0f, 1.0f); }

}  // extern "C"
