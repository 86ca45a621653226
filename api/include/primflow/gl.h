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

#ifdef __cplusplus
}
#endif

#endif
