/* primflow/gl.h: the GL-1.x-style entry points, prefixed pfgl, with the standard <GL/gl.h>
 * types and enums. Include <primflow/gl_mangle.h> instead to compile unchanged GL source
 * against primflow. Commands with no current context do nothing, as in GL. */
#ifndef PRIMFLOW_GL_H
#define PRIMFLOW_GL_H

#include <GL/gl.h>
#include <primflow/context.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Errors, strings, synchronisation */
GLenum pfglGetError(void);
const GLubyte *pfglGetString(GLenum name);
void pfglFinish(void);
void pfglFlush(void);

/* Framebuffer */
void pfglClear(GLbitfield mask);
void pfglClearColor(GLclampf red, GLclampf green, GLclampf blue, GLclampf alpha);
void pfglClearDepth(GLclampd depth);
void pfglViewport(GLint x, GLint y, GLsizei width, GLsizei height);
void pfglDepthFunc(GLenum func);
void pfglDepthMask(GLboolean flag);
void pfglDepthRange(GLclampd zNear, GLclampd zFar);
void pfglEnable(GLenum cap);
void pfglDisable(GLenum cap);
GLboolean pfglIsEnabled(GLenum cap);

/* Matrices */
void pfglMatrixMode(GLenum mode);
void pfglLoadIdentity(void);
void pfglOrtho(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top, GLdouble zNear,
               GLdouble zFar);
void pfglFrustum(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top, GLdouble zNear,
                 GLdouble zFar);

/* Immediate mode */
void pfglBegin(GLenum mode);
void pfglEnd(void);
void pfglVertex2f(GLfloat x, GLfloat y);
void pfglVertex3f(GLfloat x, GLfloat y, GLfloat z);
void pfglColor3f(GLfloat red, GLfloat green, GLfloat blue);
void pfglColor4f(GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha);

/* ---- PixelFlow extensions (tokens in primflow's own range, 0x31000-0x31FFF) ---------------- */
#define GL_TOO_MANY_ITERATIONS_EXT 0x31001 /* error: a primitive program hit the iteration cap */
#define GL_FIRST_PRIMITIVE_MODE_EXT 0x31800 /* glBegin modes of compiled primitives start here */

/* Compiles primitive-language source (docs/language.md) and registers its primitives, as the
 * built-in ones are registered. Returns a module id, or 0 if it does not compile (then
 * pfglGetCompileLogEXT(0, ...) holds the diagnostics). NULL source: GL_INVALID_VALUE, 0.
 * A primitive whose name is already registered replaces it for later glBegin calls. */
GLuint pfglCompilePrimitivesEXT(const GLchar *source);
/* The diagnostics of the last compilation (module 0: the last failed one), as
 * glGetShaderInfoLog: at most bufSize - 1 characters and a NUL; *length (if not NULL) gets the
 * count written. An unknown module id: GL_INVALID_VALUE. */
void pfglGetCompileLogEXT(GLuint module, GLsizei bufSize, GLsizei *length, GLchar *log);
/* The glBegin mode of a registered primitive by name (built-in ones included, e.g.
 * "triangles" gives GL_TRIANGLES); 0 and GL_INVALID_VALUE if there is none. */
GLenum pfglGetPrimitiveEXT(const GLchar *name);

#ifdef __cplusplus
}
#endif

#endif
