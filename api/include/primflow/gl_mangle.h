/* primflow/gl_mangle.h: renames the standard GL entry points to primflow's, so that unchanged
 * GL-1.x source compiles against primflow:
 *     #include <primflow/gl_mangle.h>   // instead of, or after, <GL/gl.h> and the other GL headers
 * One program can therefore link both OSMesa and primflow, one translation unit each.
 *
 * Every GL 1.0 - 1.5 entry point is named here (the names <GL/gl.h> and <GL/glext.h> declare for
 * GL_VERSION_1_1 ... GL_VERSION_1_5), one of two ways:
 *   - implemented: #define glX pfglX. The PixelFlow extensions keep the paper's names too
 *     (glRastParamfEXT -> pfglRastParamfEXT, ...).
 *   - not implemented: a use of the name stops the compilation with
 *     "error: primflow does not implement glX", so that it cannot silently call another GL
 *     library linked into the same program (OSMesa, libGL) on no context.
 * This header is the one list: libprimflow-osmesa's unprefixed gl* symbols and its
 * OSMesaGetProcAddress table are generated from these lines at configure time
 * (api/osmesa/CMakeLists.txt), so keep each on one line in these two forms. */
#ifndef PRIMFLOW_GL_MANGLE_H
#define PRIMFLOW_GL_MANGLE_H

#include <primflow/gl.h>

/* ---- GL 1.x, implemented ---------------------------------------------------------------- */
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
#define glHint pfglHint
#define glScissor pfglScissor
#define glAlphaFunc pfglAlphaFunc
#define glBlendFunc pfglBlendFunc
#define glBlendFuncSeparate pfglBlendFuncSeparate
#define glBlendEquation pfglBlendEquation
#define glBlendColor pfglBlendColor
#define glLogicOp pfglLogicOp
#define glStencilFunc pfglStencilFunc
#define glStencilOp pfglStencilOp
#define glStencilMask pfglStencilMask
#define glClearStencil pfglClearStencil
#define glPushAttrib pfglPushAttrib
#define glPopAttrib pfglPopAttrib
#define glPushClientAttrib pfglPushClientAttrib
#define glPopClientAttrib pfglPopClientAttrib
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
#define glPixelStoref pfglPixelStoref
#define glReadPixels pfglReadPixels
#define glTexImage1D pfglTexImage1D
#define glTexImage2D pfglTexImage2D
#define glTexSubImage1D pfglTexSubImage1D
#define glTexSubImage2D pfglTexSubImage2D
#define glCopyTexImage1D pfglCopyTexImage1D
#define glCopyTexImage2D pfglCopyTexImage2D
#define glCopyTexSubImage1D pfglCopyTexSubImage1D
#define glCopyTexSubImage2D pfglCopyTexSubImage2D
#define glGetTexImage pfglGetTexImage
#define glGetTexLevelParameteriv pfglGetTexLevelParameteriv
#define glGetTexLevelParameterfv pfglGetTexLevelParameterfv
#define glGenTextures pfglGenTextures
#define glDeleteTextures pfglDeleteTextures
#define glBindTexture pfglBindTexture
#define glIsTexture pfglIsTexture
#define glPrioritizeTextures pfglPrioritizeTextures
#define glAreTexturesResident pfglAreTexturesResident
#define glTexParameterf pfglTexParameterf
#define glTexParameteri pfglTexParameteri
#define glTexParameterfv pfglTexParameterfv
#define glTexParameteriv pfglTexParameteriv
#define glGetTexParameterfv pfglGetTexParameterfv
#define glGetTexParameteriv pfglGetTexParameteriv
#define glTexEnvf pfglTexEnvf
#define glTexEnvi pfglTexEnvi
#define glTexEnvfv pfglTexEnvfv
#define glTexEnviv pfglTexEnviv
#define glGetTexEnvfv pfglGetTexEnvfv
#define glGetTexEnviv pfglGetTexEnviv
#define glTexGeni pfglTexGeni
#define glTexGenf pfglTexGenf
#define glTexGend pfglTexGend
#define glTexGenfv pfglTexGenfv
#define glTexGeniv pfglTexGeniv
#define glTexGendv pfglTexGendv
#define glGetTexGeniv pfglGetTexGeniv
#define glGetTexGenfv pfglGetTexGenfv
#define glGetTexGendv pfglGetTexGendv
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
#define glTexCoordPointer pfglTexCoordPointer
#define glInterleavedArrays pfglInterleavedArrays
#define glGetPointerv pfglGetPointerv
#define glArrayElement pfglArrayElement
#define glDrawArrays pfglDrawArrays
#define glDrawElements pfglDrawElements
#define glVertex2i pfglVertex2i
#define glVertex3i pfglVertex3i
#define glVertex4i pfglVertex4i
#define glVertex2iv pfglVertex2iv
#define glVertex3iv pfglVertex3iv
#define glVertex4iv pfglVertex4iv
#define glVertex2s pfglVertex2s
#define glVertex3s pfglVertex3s
#define glVertex4s pfglVertex4s
#define glVertex2sv pfglVertex2sv
#define glVertex3sv pfglVertex3sv
#define glVertex4sv pfglVertex4sv
#define glColor3b pfglColor3b
#define glColor4b pfglColor4b
#define glColor3bv pfglColor3bv
#define glColor4bv pfglColor4bv
#define glColor3ubv pfglColor3ubv
#define glColor4ubv pfglColor4ubv
#define glColor3s pfglColor3s
#define glColor4s pfglColor4s
#define glColor3sv pfglColor3sv
#define glColor4sv pfglColor4sv
#define glColor3us pfglColor3us
#define glColor4us pfglColor4us
#define glColor3usv pfglColor3usv
#define glColor4usv pfglColor4usv
#define glColor3i pfglColor3i
#define glColor4i pfglColor4i
#define glColor3iv pfglColor3iv
#define glColor4iv pfglColor4iv
#define glColor3ui pfglColor3ui
#define glColor4ui pfglColor4ui
#define glColor3uiv pfglColor3uiv
#define glColor4uiv pfglColor4uiv
#define glColor3d pfglColor3d
#define glColor4d pfglColor4d
#define glColor3dv pfglColor3dv
#define glColor4dv pfglColor4dv
#define glNormal3b pfglNormal3b
#define glNormal3bv pfglNormal3bv
#define glNormal3s pfglNormal3s
#define glNormal3sv pfglNormal3sv
#define glNormal3i pfglNormal3i
#define glNormal3iv pfglNormal3iv
#define glNormal3d pfglNormal3d
#define glNormal3dv pfglNormal3dv
#define glTexCoord1s pfglTexCoord1s
#define glTexCoord2s pfglTexCoord2s
#define glTexCoord3s pfglTexCoord3s
#define glTexCoord4s pfglTexCoord4s
#define glTexCoord1sv pfglTexCoord1sv
#define glTexCoord2sv pfglTexCoord2sv
#define glTexCoord3sv pfglTexCoord3sv
#define glTexCoord4sv pfglTexCoord4sv
#define glTexCoord1i pfglTexCoord1i
#define glTexCoord2i pfglTexCoord2i
#define glTexCoord3i pfglTexCoord3i
#define glTexCoord4i pfglTexCoord4i
#define glTexCoord1iv pfglTexCoord1iv
#define glTexCoord2iv pfglTexCoord2iv
#define glTexCoord3iv pfglTexCoord3iv
#define glTexCoord4iv pfglTexCoord4iv
#define glTexCoord3f pfglTexCoord3f
#define glTexCoord4f pfglTexCoord4f
#define glTexCoord1fv pfglTexCoord1fv
#define glTexCoord2fv pfglTexCoord2fv
#define glTexCoord3fv pfglTexCoord3fv
#define glTexCoord4fv pfglTexCoord4fv
#define glTexCoord1d pfglTexCoord1d
#define glTexCoord2d pfglTexCoord2d
#define glTexCoord3d pfglTexCoord3d
#define glTexCoord4d pfglTexCoord4d
#define glTexCoord1dv pfglTexCoord1dv
#define glTexCoord2dv pfglTexCoord2dv
#define glTexCoord3dv pfglTexCoord3dv
#define glTexCoord4dv pfglTexCoord4dv
#define glRects pfglRects
#define glRectsv pfglRectsv
#define glRecti pfglRecti
#define glRectiv pfglRectiv
#define glRectf pfglRectf
#define glRectfv pfglRectfv
#define glRectd pfglRectd
#define glRectdv pfglRectdv
#define glGenLists pfglGenLists
#define glNewList pfglNewList
#define glEndList pfglEndList
#define glCallList pfglCallList
#define glCallLists pfglCallLists
#define glListBase pfglListBase
#define glDeleteLists pfglDeleteLists
#define glIsList pfglIsList

/* ---- The PixelFlow extensions by the paper's names (Olano et al. 1997, figure 3) ------- */
#define glCompileFieldEXT pfglCompileFieldEXT
#define glCompileFieldParamsEXT pfglCompileFieldParamsEXT
#define glCompilePrimitivesEXT pfglCompilePrimitivesEXT
#define glGetCompileLogEXT pfglGetCompileLogEXT
#define glGetFieldEXT pfglGetFieldEXT
#define glGetFieldLogEXT pfglGetFieldLogEXT
#define glGetInterpolatorEXT pfglGetInterpolatorEXT
#define glGetParamNameEXT pfglGetParamNameEXT
#define glGetPrimitiveEXT pfglGetPrimitiveEXT
#define glMaterialInterpEXT pfglMaterialInterpEXT
#define glRastParam3fEXT pfglRastParam3fEXT
#define glRastParam4fEXT pfglRastParam4fEXT
#define glRastParamfEXT pfglRastParamfEXT
#define glRastParamfvEXT pfglRastParamfvEXT
#define glRastParamiEXT pfglRastParamiEXT
#define glRastParamivEXT pfglRastParamivEXT
#define glSampledFieldEXT pfglSampledFieldEXT
#define glSequencePointEXT pfglSequencePointEXT

/* ---- GL 1.x, not implemented (yet): using one is a compile error ---------------------------- */
#include <primflow/gl_mangle_unsupported.h>

#endif
