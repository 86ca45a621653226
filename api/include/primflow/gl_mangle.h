/* primflow/gl_mangle.h: renames the standard GL entry points to primflow's, so that unchanged
 * GL-1.x source compiles against primflow:
 *     #include <primflow/gl_mangle.h>   // instead of, or before, <GL/gl.h>
 * One program can therefore link both OSMesa and primflow, one translation unit each. */
#ifndef PRIMFLOW_GL_MANGLE_H
#define PRIMFLOW_GL_MANGLE_H

#include <primflow/gl.h>

#define glGetError pfglGetError
#define glGetString pfglGetString
#define glFinish pfglFinish
#define glFlush pfglFlush
#define glClear pfglClear
#define glClearColor pfglClearColor
#define glClearDepth pfglClearDepth
#define glViewport pfglViewport
#define glDepthFunc pfglDepthFunc
#define glDepthMask pfglDepthMask
#define glDepthRange pfglDepthRange
#define glEnable pfglEnable
#define glDisable pfglDisable
#define glIsEnabled pfglIsEnabled
#define glMatrixMode pfglMatrixMode
#define glLoadIdentity pfglLoadIdentity
#define glOrtho pfglOrtho
#define glFrustum pfglFrustum
#define glBegin pfglBegin
#define glEnd pfglEnd
#define glVertex2f pfglVertex2f
#define glVertex3f pfglVertex3f
#define glColor3f pfglColor3f
#define glColor4f pfglColor4f

#endif
