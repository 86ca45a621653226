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
#define glColorMask pfglColorMask
#define glCullFace pfglCullFace
#define glFrontFace pfglFrontFace
#define glShadeModel pfglShadeModel
#define glLightf pfglLightf
#define glLighti pfglLighti
#define glLightfv pfglLightfv
#define glLightiv pfglLightiv
#define glLightModelf pfglLightModelf
#define glLightModeli pfglLightModeli
#define glLightModelfv pfglLightModelfv
#define glLightModeliv pfglLightModeliv
#define glMaterialf pfglMaterialf
#define glMateriali pfglMateriali
#define glMaterialfv pfglMaterialfv
#define glMaterialiv pfglMaterialiv
#define glColorMaterial pfglColorMaterial
#define glGetLightfv pfglGetLightfv
#define glGetMaterialfv pfglGetMaterialfv
#define glGetBooleanv pfglGetBooleanv
#define glGetIntegerv pfglGetIntegerv
#define glGetFloatv pfglGetFloatv
#define glGetDoublev pfglGetDoublev
#define glPixelStorei pfglPixelStorei
#define glReadPixels pfglReadPixels
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
#define glLoadMatrixf pfglLoadMatrixf
#define glLoadMatrixd pfglLoadMatrixd
#define glMultMatrixf pfglMultMatrixf
#define glMultMatrixd pfglMultMatrixd
#define glTranslatef pfglTranslatef
#define glTranslated pfglTranslated
#define glRotatef pfglRotatef
#define glRotated pfglRotated
#define glScalef pfglScalef
#define glScaled pfglScaled
#define glPushMatrix pfglPushMatrix
#define glPopMatrix pfglPopMatrix
#define glVertex4f pfglVertex4f
#define glVertex2d pfglVertex2d
#define glVertex3d pfglVertex3d
#define glVertex4d pfglVertex4d
#define glVertex2fv pfglVertex2fv
#define glVertex3fv pfglVertex3fv
#define glVertex4fv pfglVertex4fv
#define glVertex2dv pfglVertex2dv
#define glVertex3dv pfglVertex3dv
#define glVertex4dv pfglVertex4dv
#define glColor3fv pfglColor3fv
#define glColor4fv pfglColor4fv
#define glColor3ub pfglColor3ub
#define glColor4ub pfglColor4ub
#define glNormal3f pfglNormal3f
#define glNormal3fv pfglNormal3fv
#define glTexCoord1f pfglTexCoord1f
#define glTexCoord2f pfglTexCoord2f
#define glEnableClientState pfglEnableClientState
#define glDisableClientState pfglDisableClientState
#define glVertexPointer pfglVertexPointer
#define glColorPointer pfglColorPointer
#define glNormalPointer pfglNormalPointer
#define glArrayElement pfglArrayElement
#define glDrawArrays pfglDrawArrays
#define glDrawElements pfglDrawElements
#define glGenLists pfglGenLists
#define glNewList pfglNewList
#define glEndList pfglEndList
#define glCallList pfglCallList
#define glCallLists pfglCallLists
#define glListBase pfglListBase
#define glDeleteLists pfglDeleteLists
#define glIsList pfglIsList

#endif
