// The matrix commands (GL 1.5 section 2.11): modes, stacks, and the operations that multiply
// the current matrix on the right. Matrices are kept in float, as GL implementations keep
// them; the ones GL defines by formula are built in double (GLM) and rounded once.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/context_state.h"

namespace {

void multiply(PFcontextRec& ctx, const glm::dmat4& m) {
  if (pf::outsideBegin(ctx)) ctx.matrixStack().top = ctx.matrixStack().top * glm::mat4(m);
}

}  // namespace

namespace pf::cmd {

void matrixMode(PFcontextRec& ctx, GLenum mode) {
  if (!outsideBegin(ctx)) return;
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE) {
    ctx.setError(GL_INVALID_ENUM);
    return;
  }
  ctx.matrix_mode = mode;
}

void loadIdentity(PFcontextRec& ctx) {
  if (outsideBegin(ctx)) ctx.matrixStack().top = glm::mat4(1.0f);
}

// GL's m is column-major, as GLM's; count 0: a NULL matrix, ignored.
void loadMatrix(PFcontextRec& ctx, Values16f m) {
  if (outsideBegin(ctx) && m.count) ctx.matrixStack().top = glm::make_mat4(m.v);
}

void multMatrix(PFcontextRec& ctx, Values16f m) {
  if (outsideBegin(ctx) && m.count) ctx.matrixStack().top = ctx.matrixStack().top * glm::make_mat4(m.v);
}

void translate(PFcontextRec& ctx, GLdouble x, GLdouble y, GLdouble z) {
  multiply(ctx, glm::translate(glm::dmat4(1.0), glm::dvec3(x, y, z)));
}

void scale(PFcontextRec& ctx, GLdouble x, GLdouble y, GLdouble z) {
  multiply(ctx, glm::scale(glm::dmat4(1.0), glm::dvec3(x, y, z)));
}

// GL's rotation by `angle` degrees about (x, y, z), normalised; a zero axis leaves the matrix
// as it is (GL leaves it undefined; Mesa does nothing).
void rotate(PFcontextRec& ctx, GLdouble angle, GLdouble x, GLdouble y, GLdouble z) {
  if (!outsideBegin(ctx)) return;
  double len = std::sqrt(x * x + y * y + z * z);
  if (!(len > 0) || !std::isfinite(len)) return;
  ctx.matrixStack().top = ctx.matrixStack().top *
                          glm::mat4(glm::rotate(glm::dmat4(1.0), glm::radians(angle), glm::dvec3(x, y, z) / len));
}

void ortho(PFcontextRec& ctx, GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  if (!outsideBegin(ctx)) return;
  if (l == r || b == t || n == f) {
    ctx.setError(GL_INVALID_VALUE);
    return;
  }
  multiply(ctx, glm::ortho(l, r, b, t, n, f));
}

void frustum(PFcontextRec& ctx, GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  if (!outsideBegin(ctx)) return;
  if (n <= 0 || f <= 0 || l == r || b == t || n == f) {
    ctx.setError(GL_INVALID_VALUE);
    return;
  }
  multiply(ctx, glm::frustum(l, r, b, t, n, f));
}

void pushMatrix(PFcontextRec& ctx) {
  if (!outsideBegin(ctx)) return;
  MatrixStack& s = ctx.matrixStack();
  if (s.depth() >= s.max_depth) {
    ctx.setError(GL_STACK_OVERFLOW);
    return;
  }
  s.below.push_back(s.top);
}

void popMatrix(PFcontextRec& ctx) {
  if (!outsideBegin(ctx)) return;
  MatrixStack& s = ctx.matrixStack();
  if (s.below.empty()) {
    ctx.setError(GL_STACK_UNDERFLOW);
    return;
  }
  s.top = s.below.back();
  s.below.pop_back();
}

}  // namespace pf::cmd

extern "C" {

using pf::GlOp;
using pf::dispatch;

void pfglMatrixMode(GLenum mode) { dispatch<GlOp::MatrixMode>(mode); }
void pfglLoadIdentity(void) { dispatch<GlOp::LoadIdentity>(); }
void pfglLoadMatrixf(const GLfloat* m) { dispatch<GlOp::LoadMatrix>(pf::valuesOf<GLfloat, 16>(m, 16, 16)); }
void pfglLoadMatrixd(const GLdouble* m) { dispatch<GlOp::LoadMatrix>(pf::valuesOf<GLfloat, 16>(m, 16, 16)); }
void pfglMultMatrixf(const GLfloat* m) { dispatch<GlOp::MultMatrix>(pf::valuesOf<GLfloat, 16>(m, 16, 16)); }
void pfglMultMatrixd(const GLdouble* m) { dispatch<GlOp::MultMatrix>(pf::valuesOf<GLfloat, 16>(m, 16, 16)); }
void pfglTranslatef(GLfloat x, GLfloat y, GLfloat z) { dispatch<GlOp::Translate>(x, y, z); }
void pfglTranslated(GLdouble x, GLdouble y, GLdouble z) { dispatch<GlOp::Translate>(x, y, z); }
void pfglScalef(GLfloat x, GLfloat y, GLfloat z) { dispatch<GlOp::Scale>(x, y, z); }
void pfglScaled(GLdouble x, GLdouble y, GLdouble z) { dispatch<GlOp::Scale>(x, y, z); }
void pfglRotatef(GLfloat angle, GLfloat x, GLfloat y, GLfloat z) { dispatch<GlOp::Rotate>(angle, x, y, z); }
void pfglRotated(GLdouble angle, GLdouble x, GLdouble y, GLdouble z) { dispatch<GlOp::Rotate>(angle, x, y, z); }
void pfglOrtho(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  dispatch<GlOp::Ortho>(l, r, b, t, n, f);
}
void pfglFrustum(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  dispatch<GlOp::Frustum>(l, r, b, t, n, f);
}
void pfglPushMatrix(void) { dispatch<GlOp::PushMatrix>(); }
void pfglPopMatrix(void) { dispatch<GlOp::PopMatrix>(); }

}  // extern "C"
