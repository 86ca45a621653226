// The matrix commands (GL 1.5 section 2.11): modes, stacks, and the operations that multiply
// the current matrix on the right. Matrices are kept in float, as GL implementations keep
// them; the ones GL defines by formula are built in double (GLM) and rounded once.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <primflow/gl.h>

#include "api/src/context_state.h"

namespace {

using pf::contextOutsideBegin;

void multiply(const glm::dmat4& m) {
  if (PFcontextRec* ctx = contextOutsideBegin()) ctx->matrixStack().top = ctx->matrixStack().top * glm::mat4(m);
}

// GL's rotation by `angle` degrees about (x, y, z), normalised; a zero axis leaves the matrix
// as it is (GL leaves it undefined; Mesa does nothing).
void rotate(double angle, double x, double y, double z) {
  PFcontextRec* ctx = contextOutsideBegin();
  if (!ctx) return;
  double len = std::sqrt(x * x + y * y + z * z);
  if (!(len > 0) || !std::isfinite(len)) return;
  ctx->matrixStack().top = ctx->matrixStack().top *
                           glm::mat4(glm::rotate(glm::dmat4(1.0), glm::radians(angle), glm::dvec3(x, y, z) / len));
}

}  // namespace

extern "C" {

void pfglMatrixMode(GLenum mode) {
  PFcontextRec* ctx = contextOutsideBegin();
  if (!ctx) return;
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE) {
    ctx->setError(GL_INVALID_ENUM);
    return;
  }
  ctx->matrix_mode = mode;
}

void pfglLoadIdentity(void) {
  if (PFcontextRec* ctx = contextOutsideBegin()) ctx->matrixStack().top = glm::mat4(1.0f);
}

// GL's m is column-major, as GLM's.
void pfglLoadMatrixf(const GLfloat* m) {
  PFcontextRec* ctx = contextOutsideBegin();
  if (ctx && m) ctx->matrixStack().top = glm::make_mat4(m);
}

void pfglLoadMatrixd(const GLdouble* m) {
  PFcontextRec* ctx = contextOutsideBegin();
  if (ctx && m) ctx->matrixStack().top = glm::mat4(glm::make_mat4(m));
}

void pfglMultMatrixf(const GLfloat* m) {
  PFcontextRec* ctx = contextOutsideBegin();
  if (ctx && m) ctx->matrixStack().top = ctx->matrixStack().top * glm::make_mat4(m);
}

void pfglMultMatrixd(const GLdouble* m) {
  PFcontextRec* ctx = contextOutsideBegin();
  if (ctx && m) ctx->matrixStack().top = ctx->matrixStack().top * glm::mat4(glm::make_mat4(m));
}

void pfglTranslatef(GLfloat x, GLfloat y, GLfloat z) { multiply(glm::translate(glm::dmat4(1.0), glm::dvec3(x, y, z))); }
void pfglTranslated(GLdouble x, GLdouble y, GLdouble z) { multiply(glm::translate(glm::dmat4(1.0), glm::dvec3(x, y, z))); }
void pfglScalef(GLfloat x, GLfloat y, GLfloat z) { multiply(glm::scale(glm::dmat4(1.0), glm::dvec3(x, y, z))); }
void pfglScaled(GLdouble x, GLdouble y, GLdouble z) { multiply(glm::scale(glm::dmat4(1.0), glm::dvec3(x, y, z))); }
void pfglRotatef(GLfloat angle, GLfloat x, GLfloat y, GLfloat z) { rotate(angle, x, y, z); }
void pfglRotated(GLdouble angle, GLdouble x, GLdouble y, GLdouble z) { rotate(angle, x, y, z); }

void pfglOrtho(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  PFcontextRec* ctx = contextOutsideBegin();
  if (!ctx) return;
  if (l == r || b == t || n == f) {
    ctx->setError(GL_INVALID_VALUE);
    return;
  }
  multiply(glm::ortho(l, r, b, t, n, f));
}

void pfglFrustum(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  PFcontextRec* ctx = contextOutsideBegin();
  if (!ctx) return;
  if (n <= 0 || f <= 0 || l == r || b == t || n == f) {
    ctx->setError(GL_INVALID_VALUE);
    return;
  }
  multiply(glm::frustum(l, r, b, t, n, f));
}

void pfglPushMatrix(void) {
  PFcontextRec* ctx = contextOutsideBegin();
  if (!ctx) return;
  pf::MatrixStack& s = ctx->matrixStack();
  if (s.depth() >= s.max_depth) {
    ctx->setError(GL_STACK_OVERFLOW);
    return;
  }
  s.below.push_back(s.top);
}

void pfglPopMatrix(void) {
  PFcontextRec* ctx = contextOutsideBegin();
  if (!ctx) return;
  pf::MatrixStack& s = ctx->matrixStack();
  if (s.below.empty()) {
    ctx->setError(GL_STACK_UNDERFLOW);
    return;
  }
  s.top = s.below.back();
  s.below.pop_back();
}

}  // extern "C"
