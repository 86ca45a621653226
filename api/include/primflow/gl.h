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
/* The accumulation buffer (a context created with accumulation bits: PF_ACCUM_BITS) */
void pfglAccum(GLenum op, GLfloat value);
void pfglClearAccum(GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha);
/* GL_DEPTH_TEST, GL_CULL_FACE, GL_LIGHTING, GL_LIGHT0..7, GL_COLOR_MATERIAL, GL_NORMALIZE,
 * GL_RESCALE_NORMAL, GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_STENCIL_TEST, GL_BLEND, GL_COLOR_LOGIC_OP,
 * GL_DITHER; others: GL_INVALID_ENUM (glIsEnabled also takes the client arrays) */
void pfglEnable(GLenum cap);
void pfglDisable(GLenum cap);
GLboolean pfglIsEnabled(GLenum cap);
void pfglColorMask(GLboolean red, GLboolean green, GLboolean blue, GLboolean alpha);

/* Per-fragment operations (GL 1.5 section 4.1): the scissor box (GL_SCISSOR_TEST), the alpha
 * test (GL_ALPHA_TEST), the stencil test (GL_STENCIL_TEST, below), blending (GL_BLEND) and the logic op (GL_COLOR_LOGIC_OP); GL_DITHER is
 * accepted and changes nothing (as in llvmpipe). A draw with the alpha test, the stencil test,
 * blending or the logic op is shaded in submission order rather than deferred
 * (docs/architecture.md). */
void pfglScissor(GLint x, GLint y, GLsizei width, GLsizei height);
void pfglAlphaFunc(GLenum func, GLclampf ref);
void pfglBlendFunc(GLenum sfactor, GLenum dfactor);
void pfglBlendFuncSeparate(GLenum sfactorRGB, GLenum dfactorRGB, GLenum sfactorAlpha, GLenum dfactorAlpha);
void pfglBlendEquation(GLenum mode);
void pfglBlendColor(GLclampf red, GLclampf green, GLclampf blue, GLclampf alpha);
void pfglLogicOp(GLenum opcode);
/* The stencil buffer (8 bits, when the context asks for one: PF_STENCIL_BITS, OSMesa's
 * stencil argument): GL_STENCIL_TEST and glClear(GL_STENCIL_BUFFER_BIT). */
void pfglStencilFunc(GLenum func, GLint ref, GLuint mask);
void pfglStencilOp(GLenum fail, GLenum zfail, GLenum zpass);
void pfglStencilMask(GLuint mask);
void pfglClearStencil(GLint s);

/* Fog (GL 1.5 section 3.10): GL_FOG_MODE (GL_LINEAR, GL_EXP, GL_EXP2), GL_FOG_DENSITY,
 * GL_FOG_START, GL_FOG_END, GL_FOG_COLOR, GL_FOG_INDEX; applied per pixel after texturing from
 * |z| in eye coordinates. User clip planes (section 2.11): GL_CLIP_PLANE0 .. GL_CLIP_PLANE7, each
 * kept in eye coordinates, applied per pixel by the depth test (docs/api.md, "Fog" and "Clip
 * planes"). */
void pfglFogf(GLenum pname, GLfloat param);
void pfglFogi(GLenum pname, GLint param);
void pfglFogfv(GLenum pname, const GLfloat *params);
void pfglFogiv(GLenum pname, const GLint *params);
void pfglClipPlane(GLenum plane, const GLdouble *equation);
void pfglGetClipPlane(GLenum plane, GLdouble *equation);

/* The current raster position (GL 1.5 section 2.13; glWindowPos: GL 1.4): glRasterPos transforms
 * and clips a vertex as a point's, taking its colour (lit under GL_LIGHTING), texture
 * coordinates and eye distance; glWindowPos sets window coordinates directly (docs/api.md,
 * "Raster position"). */
void pfglRasterPos2s(GLshort x, GLshort y);
void pfglRasterPos2sv(const GLshort *v);
void pfglRasterPos2i(GLint x, GLint y);
void pfglRasterPos2iv(const GLint *v);
void pfglRasterPos2f(GLfloat x, GLfloat y);
void pfglRasterPos2fv(const GLfloat *v);
void pfglRasterPos2d(GLdouble x, GLdouble y);
void pfglRasterPos2dv(const GLdouble *v);
void pfglRasterPos3s(GLshort x, GLshort y, GLshort z);
void pfglRasterPos3sv(const GLshort *v);
void pfglRasterPos3i(GLint x, GLint y, GLint z);
void pfglRasterPos3iv(const GLint *v);
void pfglRasterPos3f(GLfloat x, GLfloat y, GLfloat z);
void pfglRasterPos3fv(const GLfloat *v);
void pfglRasterPos3d(GLdouble x, GLdouble y, GLdouble z);
void pfglRasterPos3dv(const GLdouble *v);
void pfglRasterPos4s(GLshort x, GLshort y, GLshort z, GLshort w);
void pfglRasterPos4sv(const GLshort *v);
void pfglRasterPos4i(GLint x, GLint y, GLint z, GLint w);
void pfglRasterPos4iv(const GLint *v);
void pfglRasterPos4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w);
void pfglRasterPos4fv(const GLfloat *v);
void pfglRasterPos4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w);
void pfglRasterPos4dv(const GLdouble *v);
void pfglWindowPos2s(GLshort x, GLshort y);
void pfglWindowPos2sv(const GLshort *v);
void pfglWindowPos2i(GLint x, GLint y);
void pfglWindowPos2iv(const GLint *v);
void pfglWindowPos2f(GLfloat x, GLfloat y);
void pfglWindowPos2fv(const GLfloat *v);
void pfglWindowPos2d(GLdouble x, GLdouble y);
void pfglWindowPos2dv(const GLdouble *v);
void pfglWindowPos3s(GLshort x, GLshort y, GLshort z);
void pfglWindowPos3sv(const GLshort *v);
/* Pixel rectangles at the raster position (GL 1.5 sections 3.6 and 3.7), drawn as instances of
 * the built-in primitive pixel_rectangle through the per-fragment operations: glBitmap and
 * glDrawPixels unpacked by glPixelStore's unpack modes, glCopyPixels, both zoomed by
 * glPixelZoom (docs/api.md, "Raster position and pixel rectangles"). */
void pfglBitmap(GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, GLfloat xmove, GLfloat ymove,
                const GLubyte *bitmap);
void pfglDrawPixels(GLsizei width, GLsizei height, GLenum format, GLenum type, const GLvoid *pixels);
void pfglCopyPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum type);
void pfglPixelZoom(GLfloat xfactor, GLfloat yfactor);
/* Pixel transfer (GL 1.5 section 3.6.5): scale, bias and the colour maps on the colour images
 * that glDrawPixels, glCopyPixels, glReadPixels and glTexImage / glCopyTexImage move; the index
 * maps for colour-index images; depth scale and bias; stencil shift, offset and map -- each
 * where OSMesa applies it (docs/api.md, "Pixel transfer"). */
void pfglPixelTransferf(GLenum pname, GLfloat param);
void pfglPixelTransferi(GLenum pname, GLint param);
void pfglPixelMapfv(GLenum map, GLsizei mapsize, const GLfloat *values);
void pfglPixelMapuiv(GLenum map, GLsizei mapsize, const GLuint *values);
void pfglPixelMapusv(GLenum map, GLsizei mapsize, const GLushort *values);
void pfglGetPixelMapfv(GLenum map, GLfloat *values);
void pfglGetPixelMapuiv(GLenum map, GLuint *values);
void pfglGetPixelMapusv(GLenum map, GLushort *values);
void pfglWindowPos3i(GLint x, GLint y, GLint z);
void pfglWindowPos3iv(const GLint *v);
void pfglWindowPos3f(GLfloat x, GLfloat y, GLfloat z);
void pfglWindowPos3fv(const GLfloat *v);
void pfglWindowPos3d(GLdouble x, GLdouble y, GLdouble z);
void pfglWindowPos3dv(const GLdouble *v);
/* Points and lines (GL 1.5 sections 3.4, 3.5), aliased: glPointSize squares, glLineWidth runs
 * of pixels across the minor axis, rounded as OSMesa rounds them; glLineStipple under
 * GL_LINE_STIPPLE (docs/api.md, "Points and lines"). */
void pfglPointSize(GLfloat size);
void pfglLineWidth(GLfloat width);
void pfglLineStipple(GLint factor, GLushort pattern);
/* Polygons (GL 1.5 sections 3.5.2 - 3.5.5): glPolygonMode per face (GL_POINT, GL_LINE on the
 * polygon's boundary, GL_FILL), after culling; glPolygonOffset under GL_POLYGON_OFFSET_FILL,
 * _LINE, _POINT; glPolygonStipple's 32 x 32 pattern under GL_POLYGON_STIPPLE, for filled
 * polygons, unpacked / packed by glPixelStore's modes (docs/api.md, "Polygon modes and offset",
 * "Polygon stipple"). */
void pfglPolygonMode(GLenum face, GLenum mode);
void pfglPolygonOffset(GLfloat factor, GLfloat units);
void pfglPolygonStipple(const GLubyte *mask);
void pfglGetPolygonStipple(GLubyte *mask);

/* Hints: kept and read back (nothing primflow draws depends on them). Attribute stacks, 16 deep:
 * the groups primflow has (docs/api.md, "Attribute stacks"); glPushAttrib / glPopAttrib are
 * recorded in display lists, the client forms are not. */
void pfglHint(GLenum target, GLenum mode);
void pfglPushAttrib(GLbitfield mask);
void pfglPopAttrib(void);
void pfglPushClientAttrib(GLbitfield mask);
void pfglPopClientAttrib(void);

/* Polygons: face culling, winding, flat or smooth shading (GL's provoking vertex per mode) */
void pfglCullFace(GLenum mode);
void pfglFrontFace(GLenum mode);
void pfglShadeModel(GLenum mode);

/* Lighting (GL 1.5 section 2.14): 8 lights, front and back materials, the light model,
 * GL_COLOR_MATERIAL, GL_NORMALIZE, GL_RESCALE_NORMAL. Vertex primitives (those with a `vertex`
 * parameter) are lit per vertex, as GL lights them -- or per pixel with
 * glEnable(GL_PER_PIXEL_LIGHTING_EXT). glMaterial is allowed inside glBegin. */
void pfglLightf(GLenum light, GLenum pname, GLfloat param);
void pfglLighti(GLenum light, GLenum pname, GLint param);
void pfglLightfv(GLenum light, GLenum pname, const GLfloat *params);
void pfglLightiv(GLenum light, GLenum pname, const GLint *params);
void pfglLightModelf(GLenum pname, GLfloat param);
void pfglLightModeli(GLenum pname, GLint param);
void pfglLightModelfv(GLenum pname, const GLfloat *params);
void pfglLightModeliv(GLenum pname, const GLint *params);
void pfglMaterialf(GLenum face, GLenum pname, GLfloat param);
void pfglMateriali(GLenum face, GLenum pname, GLint param);
void pfglMaterialfv(GLenum face, GLenum pname, const GLfloat *params);
void pfglMaterialiv(GLenum face, GLenum pname, const GLint *params);
void pfglColorMaterial(GLenum face, GLenum mode);
void pfglGetLightfv(GLenum light, GLenum pname, GLfloat *params);
void pfglGetMaterialfv(GLenum face, GLenum pname, GLfloat *params);

/* Vertex arrays: GL_VERTEX_ARRAY, GL_COLOR_ARRAY, GL_NORMAL_ARRAY, GL_TEXTURE_COORD_ARRAY,
 * GL_EDGE_FLAG_ARRAY.
 * glDrawArrays / glDrawElements are glBegin, glArrayElement per index, glEnd, as GL defines
 * them; glInterleavedArrays sets them from one of GL's 14 layouts. */
void pfglEnableClientState(GLenum array);
void pfglDisableClientState(GLenum array);
void pfglVertexPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *pointer);
void pfglColorPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *pointer);
void pfglNormalPointer(GLenum type, GLsizei stride, const GLvoid *pointer);
void pfglTexCoordPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *pointer);
void pfglEdgeFlagPointer(GLsizei stride, const GLvoid *pointer);
void pfglInterleavedArrays(GLenum format, GLsizei stride, const GLvoid *pointer);
void pfglGetPointerv(GLenum pname, GLvoid **params);
void pfglArrayElement(GLint i);
void pfglDrawArrays(GLenum mode, GLint first, GLsizei count);
void pfglDrawElements(GLenum mode, GLsizei count, GLenum type, const GLvoid *indices);

/* State queries: every GL 1.x state variable (what primflow lacks reads as GL's initial value,
 * absent buffers as 0 bits; docs/api.md); others: GL_INVALID_ENUM; NULL: ignored */
void pfglGetBooleanv(GLenum pname, GLboolean *params);
void pfglGetIntegerv(GLenum pname, GLint *params);
void pfglGetFloatv(GLenum pname, GLfloat *params);
void pfglGetDoublev(GLenum pname, GLdouble *params);

/* Reading pixels: GL_RGBA / GL_RGB / GL_DEPTH_COMPONENT x GL_UNSIGNED_BYTE / GL_UNSIGNED_SHORT /
 * GL_UNSIGNED_INT / GL_FLOAT, written by the pack modes of glPixelStore (every pack and unpack
 * mode of GL 1.x is kept). Finishes drawing first. */
void pfglPixelStorei(GLenum pname, GLint param);
void pfglPixelStoref(GLenum pname, GLfloat param);
void pfglReadPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type,
                    GLvoid *pixels);

/* Texturing (GL 1.x: 1D and 2D textures, objects, mipmaps, filters, wraps, env modes, texture
 * coordinate generation; docs/api.md lists the errors). Images are read by the unpack modes of
 * glPixelStore (glGetTexImage writes by the pack modes) and stored with 8 bits a component. */
void pfglGenTextures(GLsizei n, GLuint *textures);
void pfglDeleteTextures(GLsizei n, const GLuint *textures);
void pfglBindTexture(GLenum target, GLuint texture);
GLboolean pfglIsTexture(GLuint texture);
void pfglPrioritizeTextures(GLsizei n, const GLuint *textures, const GLclampf *priorities);
GLboolean pfglAreTexturesResident(GLsizei n, const GLuint *textures, GLboolean *residences);
void pfglTexImage1D(GLenum target, GLint level, GLint internalformat, GLsizei width, GLint border, GLenum format,
                    GLenum type, const GLvoid *pixels);
void pfglTexImage2D(GLenum target, GLint level, GLint internalformat, GLsizei width, GLsizei height, GLint border,
                    GLenum format, GLenum type, const GLvoid *pixels);
void pfglTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLsizei width, GLenum format, GLenum type,
                       const GLvoid *pixels);
void pfglTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width, GLsizei height,
                       GLenum format, GLenum type, const GLvoid *pixels);
void pfglCopyTexImage1D(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y, GLsizei width,
                        GLint border);
void pfglCopyTexImage2D(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y, GLsizei width,
                        GLsizei height, GLint border);
void pfglCopyTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLint x, GLint y, GLsizei width);
void pfglCopyTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint x, GLint y, GLsizei width,
                           GLsizei height);
void pfglGetTexImage(GLenum target, GLint level, GLenum format, GLenum type, GLvoid *pixels);
void pfglGetTexLevelParameteriv(GLenum target, GLint level, GLenum pname, GLint *params);
void pfglGetTexLevelParameterfv(GLenum target, GLint level, GLenum pname, GLfloat *params);
void pfglTexParameterf(GLenum target, GLenum pname, GLfloat param);
void pfglTexParameteri(GLenum target, GLenum pname, GLint param);
void pfglTexParameterfv(GLenum target, GLenum pname, const GLfloat *params);
void pfglTexParameteriv(GLenum target, GLenum pname, const GLint *params);
void pfglGetTexParameterfv(GLenum target, GLenum pname, GLfloat *params);
void pfglGetTexParameteriv(GLenum target, GLenum pname, GLint *params);
void pfglTexEnvf(GLenum target, GLenum pname, GLfloat param);
void pfglTexEnvi(GLenum target, GLenum pname, GLint param);
void pfglTexEnvfv(GLenum target, GLenum pname, const GLfloat *params);
void pfglTexEnviv(GLenum target, GLenum pname, const GLint *params);
void pfglGetTexEnvfv(GLenum target, GLenum pname, GLfloat *params);
void pfglGetTexEnviv(GLenum target, GLenum pname, GLint *params);
void pfglTexGeni(GLenum coord, GLenum pname, GLint param);
void pfglTexGenf(GLenum coord, GLenum pname, GLfloat param);
void pfglTexGend(GLenum coord, GLenum pname, GLdouble param);
void pfglTexGeniv(GLenum coord, GLenum pname, const GLint *params);
void pfglTexGenfv(GLenum coord, GLenum pname, const GLfloat *params);
void pfglTexGendv(GLenum coord, GLenum pname, const GLdouble *params);
void pfglGetTexGeniv(GLenum coord, GLenum pname, GLint *params);
void pfglGetTexGenfv(GLenum coord, GLenum pname, GLfloat *params);
void pfglGetTexGendv(GLenum coord, GLenum pname, GLdouble *params);

/* Matrices (stacks: modelview 32 deep, projection and texture 4; NULL matrices are ignored) */
void pfglMatrixMode(GLenum mode);
void pfglLoadIdentity(void);
void pfglLoadMatrixf(const GLfloat *m);
void pfglLoadMatrixd(const GLdouble *m);
void pfglMultMatrixf(const GLfloat *m);
void pfglMultMatrixd(const GLdouble *m);
void pfglTranslatef(GLfloat x, GLfloat y, GLfloat z);
void pfglTranslated(GLdouble x, GLdouble y, GLdouble z);
void pfglRotatef(GLfloat angle, GLfloat x, GLfloat y, GLfloat z);
void pfglRotated(GLdouble angle, GLdouble x, GLdouble y, GLdouble z);
void pfglScalef(GLfloat x, GLfloat y, GLfloat z);
void pfglScaled(GLdouble x, GLdouble y, GLdouble z);
void pfglOrtho(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top, GLdouble zNear,
               GLdouble zFar);
void pfglFrustum(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top, GLdouble zNear,
                 GLdouble zFar);
void pfglPushMatrix(void);
void pfglPopMatrix(void);

/* Immediate mode. Every glBegin mode (GL_POINTS ... GL_POLYGON) is a primitive of
 * primitives/<name>.pfl. The vertex attributes in every type GL 1.x has (integer colours and
 * normals normalised as GL 1.5 table 2.9 says); glRect draws a GL_POLYGON. The vector forms
 * ignore a NULL pointer. */
void pfglBegin(GLenum mode);
void pfglEnd(void);
void pfglVertex2f(GLfloat x, GLfloat y);
void pfglVertex3f(GLfloat x, GLfloat y, GLfloat z);
void pfglVertex4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w);
void pfglVertex2fv(const GLfloat *v);
void pfglVertex3fv(const GLfloat *v);
void pfglVertex4fv(const GLfloat *v);
void pfglVertex2d(GLdouble x, GLdouble y);
void pfglVertex3d(GLdouble x, GLdouble y, GLdouble z);
void pfglVertex4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w);
void pfglVertex2dv(const GLdouble *v);
void pfglVertex3dv(const GLdouble *v);
void pfglVertex4dv(const GLdouble *v);
void pfglVertex2i(GLint x, GLint y);
void pfglVertex3i(GLint x, GLint y, GLint z);
void pfglVertex4i(GLint x, GLint y, GLint z, GLint w);
void pfglVertex2iv(const GLint *v);
void pfglVertex3iv(const GLint *v);
void pfglVertex4iv(const GLint *v);
void pfglVertex2s(GLshort x, GLshort y);
void pfglVertex3s(GLshort x, GLshort y, GLshort z);
void pfglVertex4s(GLshort x, GLshort y, GLshort z, GLshort w);
void pfglVertex2sv(const GLshort *v);
void pfglVertex3sv(const GLshort *v);
void pfglVertex4sv(const GLshort *v);
void pfglColor3b(GLbyte red, GLbyte green, GLbyte blue);
void pfglColor4b(GLbyte red, GLbyte green, GLbyte blue, GLbyte alpha);
void pfglColor3bv(const GLbyte *v);
void pfglColor4bv(const GLbyte *v);
void pfglColor3ub(GLubyte red, GLubyte green, GLubyte blue);
void pfglColor4ub(GLubyte red, GLubyte green, GLubyte blue, GLubyte alpha);
void pfglColor3ubv(const GLubyte *v);
void pfglColor4ubv(const GLubyte *v);
void pfglColor3s(GLshort red, GLshort green, GLshort blue);
void pfglColor4s(GLshort red, GLshort green, GLshort blue, GLshort alpha);
void pfglColor3sv(const GLshort *v);
void pfglColor4sv(const GLshort *v);
void pfglColor3us(GLushort red, GLushort green, GLushort blue);
void pfglColor4us(GLushort red, GLushort green, GLushort blue, GLushort alpha);
void pfglColor3usv(const GLushort *v);
void pfglColor4usv(const GLushort *v);
void pfglColor3i(GLint red, GLint green, GLint blue);
void pfglColor4i(GLint red, GLint green, GLint blue, GLint alpha);
void pfglColor3iv(const GLint *v);
void pfglColor4iv(const GLint *v);
void pfglColor3ui(GLuint red, GLuint green, GLuint blue);
void pfglColor4ui(GLuint red, GLuint green, GLuint blue, GLuint alpha);
void pfglColor3uiv(const GLuint *v);
void pfglColor4uiv(const GLuint *v);
void pfglColor3f(GLfloat red, GLfloat green, GLfloat blue);
void pfglColor4f(GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha);
void pfglColor3fv(const GLfloat *v);
void pfglColor4fv(const GLfloat *v);
void pfglColor3d(GLdouble red, GLdouble green, GLdouble blue);
void pfglColor4d(GLdouble red, GLdouble green, GLdouble blue, GLdouble alpha);
void pfglColor3dv(const GLdouble *v);
void pfglColor4dv(const GLdouble *v);
void pfglNormal3b(GLbyte nx, GLbyte ny, GLbyte nz);
void pfglNormal3bv(const GLbyte *v);
void pfglNormal3s(GLshort nx, GLshort ny, GLshort nz);
void pfglNormal3sv(const GLshort *v);
void pfglNormal3i(GLint nx, GLint ny, GLint nz);
void pfglNormal3iv(const GLint *v);
void pfglNormal3f(GLfloat nx, GLfloat ny, GLfloat nz);
void pfglNormal3fv(const GLfloat *v);
void pfglNormal3d(GLdouble nx, GLdouble ny, GLdouble nz);
void pfglNormal3dv(const GLdouble *v);
/* The edge flag (GL 1.5 section 2.6.2): which edges of GL_TRIANGLES, GL_QUADS and GL_POLYGON
 * drawn GL_LINE or GL_POINT are boundary edges (docs/api.md, "Polygon modes and offset"). */
void pfglEdgeFlag(GLboolean flag);
void pfglEdgeFlagv(const GLboolean *flag);
void pfglTexCoord1s(GLshort s);
void pfglTexCoord2s(GLshort s, GLshort t);
void pfglTexCoord3s(GLshort s, GLshort t, GLshort r);
void pfglTexCoord4s(GLshort s, GLshort t, GLshort r, GLshort q);
void pfglTexCoord1sv(const GLshort *v);
void pfglTexCoord2sv(const GLshort *v);
void pfglTexCoord3sv(const GLshort *v);
void pfglTexCoord4sv(const GLshort *v);
void pfglTexCoord1i(GLint s);
void pfglTexCoord2i(GLint s, GLint t);
void pfglTexCoord3i(GLint s, GLint t, GLint r);
void pfglTexCoord4i(GLint s, GLint t, GLint r, GLint q);
void pfglTexCoord1iv(const GLint *v);
void pfglTexCoord2iv(const GLint *v);
void pfglTexCoord3iv(const GLint *v);
void pfglTexCoord4iv(const GLint *v);
void pfglTexCoord1f(GLfloat s);
void pfglTexCoord2f(GLfloat s, GLfloat t);
void pfglTexCoord3f(GLfloat s, GLfloat t, GLfloat r);
void pfglTexCoord4f(GLfloat s, GLfloat t, GLfloat r, GLfloat q);
void pfglTexCoord1fv(const GLfloat *v);
void pfglTexCoord2fv(const GLfloat *v);
void pfglTexCoord3fv(const GLfloat *v);
void pfglTexCoord4fv(const GLfloat *v);
void pfglTexCoord1d(GLdouble s);
void pfglTexCoord2d(GLdouble s, GLdouble t);
void pfglTexCoord3d(GLdouble s, GLdouble t, GLdouble r);
void pfglTexCoord4d(GLdouble s, GLdouble t, GLdouble r, GLdouble q);
void pfglTexCoord1dv(const GLdouble *v);
void pfglTexCoord2dv(const GLdouble *v);
void pfglTexCoord3dv(const GLdouble *v);
void pfglTexCoord4dv(const GLdouble *v);
void pfglRects(GLshort x1, GLshort y1, GLshort x2, GLshort y2);
void pfglRectsv(const GLshort *v1, const GLshort *v2);
void pfglRecti(GLint x1, GLint y1, GLint x2, GLint y2);
void pfglRectiv(const GLint *v1, const GLint *v2);
void pfglRectf(GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2);
void pfglRectfv(const GLfloat *v1, const GLfloat *v2);
void pfglRectd(GLdouble x1, GLdouble y1, GLdouble x2, GLdouble y2);
void pfglRectdv(const GLdouble *v1, const GLdouble *v2);

/* Display lists (GL 1.5 section 5.4): every command above that GL compiles is recorded, and the
 * extension's pfglRastParam*EXT, pfglSequencePointEXT and pfglMaterialInterpEXT too; queries,
 * glFinish / glFlush, glReadPixels, glPixelStore, client state (glPushClientAttrib too), array
 * pointers and glInterleavedArrays execute at once (glArrayElement, glDrawArrays, glDrawElements
 * record what they draw). Nesting up to GL_MAX_LIST_NESTING (64). docs/api.md, "Display lists". */
GLuint pfglGenLists(GLsizei range);
void pfglNewList(GLuint list, GLenum mode);
void pfglEndList(void);
void pfglCallList(GLuint list);
void pfglCallLists(GLsizei n, GLenum type, const GLvoid *lists);
void pfglListBase(GLuint base);
void pfglDeleteLists(GLuint list, GLsizei range);
GLboolean pfglIsList(GLuint list);

/* ---- PixelFlow extensions (tokens in primflow's own range, 0x31000-0x3FFFF) ---------------- */
#define GL_TOO_MANY_ITERATIONS_EXT 0x31001 /* error: a primitive program hit the iteration cap */
#define GL_PERSPECTIVE_LINEAR_INTERPOLATOR_EXT 0x31010 /* pfglMaterialInterpEXT interpolators */
#define GL_LINEAR_INTERPOLATOR_EXT 0x31011
/* glEnable capability: vertex primitives (triangles, quads, ...) lit per pixel from their
 * interpolated eye-space position and normal instead of per vertex (off initially). */
#define GL_PER_PIXEL_LIGHTING_EXT 0x31020
#define GL_FIRST_INTERPOLATOR_EXT 0x31400  /* pfglGetInterpolatorEXT's ids start here */
#define GL_FIRST_PRIMITIVE_MODE_EXT 0x31800 /* glBegin modes of compiled primitives start here */
#define GL_FIRST_PARAM_NAME_EXT 0x38000     /* pfglGetParamNameEXT's ids start here */

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
/* The id of a compiled shared interpolator by name (paper section 3.4), for
 * pfglMaterialInterpEXT; 0 and GL_INVALID_VALUE if there is none. */
GLenum pfglGetInterpolatorEXT(const GLchar *name);

/* Named parameters (paper section 3.1). pfglGetParamNameEXT interns a parameter name and
 * returns its id (never 0; NULL or "": GL_INVALID_VALUE, 0). "vertex", "normal" and
 * "texcoord" are the names glVertex, glNormal and glTexCoord set. pfglRastParam*EXT set a
 * parameter's current value (allowed inside glBegin / glEnd; unknown id: GL_INVALID_VALUE;
 * the vector forms take 1 to 16 values). pfglSequencePointEXT binds the current values of
 * the parameters the glBegin's primitive declares, as glVertex does after setting "vertex"
 * (outside glBegin / glEnd: GL_INVALID_OPERATION). Per-sequence-point parameters (arrays)
 * take each sequence point's value, per-primitive ones the value at the first sequence point
 * of their instance; point parameters are transformed to clip coordinates by the matrices
 * current at glBegin. A glBegin / glEnd whose values do not fit the declaration (a parameter
 * never set, a wrong number of values, or -- for a primitive of the extension -- sequence
 * points that do not make whole instances) draws nothing, sets GL_INVALID_OPERATION at
 * glEnd and says why on stderr. */
GLuint pfglGetParamNameEXT(const GLchar *name);
/* How instances of glBegin mode `primitive` interpolate the per-vertex shading parameter
 * `param` (a name id; "color" is GL's colour): GL_PERSPECTIVE_LINEAR_INTERPOLATOR_EXT (the
 * default of "color"), GL_LINEAR_INTERPOLATOR_EXT (linear in window space), or a shared
 * interpolator (pfglGetInterpolatorEXT), which computes the value per pixel from the surface
 * point P and its own parameters (their values at the instance's first sequence point). Each
 * bound parameter takes 4 channels; its per-vertex value is its current value at each
 * sequence point (missing components (0, 0, 0, 1)), set with pfglRastParam*EXT or glMaterial
 * with the name id. Unknown ids or modes: GL_INVALID_VALUE; other interpolators:
 * GL_INVALID_ENUM. */
void pfglMaterialInterpEXT(GLuint param, GLenum primitive, GLenum interpolator);
void pfglRastParamfEXT(GLuint name, GLfloat value);
void pfglRastParamiEXT(GLuint name, GLint value);
void pfglRastParam3fEXT(GLuint name, GLfloat x, GLfloat y, GLfloat z);
void pfglRastParam4fEXT(GLuint name, GLfloat x, GLfloat y, GLfloat z, GLfloat w);
void pfglRastParamfvEXT(GLuint name, GLsizei count, const GLfloat *values);
void pfglRastParamivEXT(GLuint name, GLsizei count, const GLint *values);
void pfglSequencePointEXT(void);

/* Implicit surfaces (docs/api.md, "Fields"). A field is f(x, y, z) with f >= 0 inside (HyperFun's
 * convention). pfglCompileFieldEXT compiles one from `source` in `format` and returns its id
 * (> 0), which the built-in "implicit" primitive's `field` parameter takes; 0 if the source does
 * not compile (pfglGetFieldLogEXT(0, ...) then holds the diagnostics, file:line:col with a caret,
 * `name` standing for the file). `lipschitz` declares a bound on |grad f| for sphere tracing
 * (0: none; negative or not finite: GL_INVALID_VALUE). Formats:
 *   GL_FIELD_FIDGET_EXT -- Fidget's SSA text (.vm files); Fidget's sign (negative inside) is
 *     flipped on reading.
 *   GL_FIELD_HYPERFUN_EXT -- a HyperFun model (.hf, docs/hyperfun.md); the object named
 *     "my_model", else the file's first.
 *   GL_FIELD_LANGUAGE_EXT -- a `field` unit of the primitive language (.pfl, docs/language.md,
 *     "Fields"; HyperFun's library is in it, docs/field_library.md): the unit named `name`
 *     (a path's directories and extension left out), or the source's only field unit.
 * An unknown format: GL_INVALID_ENUM; NULL source or name: GL_INVALID_VALUE; inside glBegin /
 * glEnd: GL_INVALID_OPERATION. Fields live as long as the context. */
#define GL_FIELD_FIDGET_EXT 0x31030
#define GL_FIELD_HYPERFUN_EXT 0x31031
#define GL_FIELD_LANGUAGE_EXT 0x31032
/* The `method` parameter of the implicit primitive: how it finds the surface along a ray. */
#define GL_FIELD_METHOD_AUTO_EXT 0     /* analytic if polynomial (degree <= 4) or a small CSG tree of such leaves, sphere if Lipschitz, else interval */
#define GL_FIELD_METHOD_ANALYTIC_EXT 1 /* the ray polynomial's first root, or the first hit among a CSG tree's leaf roots */
#define GL_FIELD_METHOD_INTERVAL_EXT 2 /* interval subdivision, block culling, tape simplification */
#define GL_FIELD_METHOD_MARCH_EXT 3    /* `steps` uniform steps, then bisection */
#define GL_FIELD_METHOD_SPHERE_EXT 4   /* sphere tracing with the declared bound (or `steps` as the bound) */
#define GL_FIELD_METHOD_NEWTON_EXT 5   /* `steps` uniform steps, then 4 Newton steps (seed 000's approximate search) */
#define GL_FIELD_METHOD_REGULA_FALSI_EXT 6 /* `steps` uniform steps, then 6 regula falsi steps (seed 000) */
GLuint pfglCompileFieldEXT(GLenum format, const GLchar *name, const GLchar *source, GLfloat lipschitz);
/* pfglCompileFieldEXT with the model's parameters: for GL_FIELD_HYPERFUN_EXT, `time` is x[4] and
 * params[0 .. count-1] are a[1 .. count] (the rest of a[] is 0; more than a[] holds: the
 * compilation fails, with the message in the log). For GL_FIELD_LANGUAGE_EXT, params are the
 * values of the field's parameters after its point, in order (exactly as many as it declares,
 * else the compilation fails, with the message in the log); time must be 0. Fidget models have
 * neither: time must be 0 and count 0 (else GL_INVALID_VALUE). count < 0, or count > 0 with NULL params: GL_INVALID_VALUE. */
GLuint pfglCompileFieldParamsEXT(GLenum format, const GLchar *name, const GLchar *source, GLfloat lipschitz,
                                 GLdouble time, GLsizei count, const GLdouble *params);
/* As pfglGetCompileLogEXT, for fields: field 0 is the last failed compilation. */
void pfglGetFieldLogEXT(GLuint field, GLsizei bufSize, GLsizei *length, GLchar *log);
/* The id of the field last compiled under `name`; 0 and GL_INVALID_VALUE if there is none. */
GLuint pfglGetFieldEXT(const GLchar *name);
/* A sampled field (a voxel array, seed 000 section 3; docs/models.md, "Sampled fields"):
 * nx * ny * nz samples, x fastest, then y, then z -- the field's values (f >= 0 inside) at the
 * points of a regular grid spanning box = {x0, y0, z0, x1, y1, z1}, sample (0, 0, 0) at the first
 * corner -- interpolated trilinearly (GL_FIELD_TRILINEAR_EXT) or by the uniform cubic B-spline
 * whose control points are the samples (GL_FIELD_TRICUBIC_EXT); outside the box, the value at its
 * nearest point. Returns its id, usable wherever a field's is (the implicit primitive, every
 * method); its Lipschitz bound comes from the samples, so `auto` sphere-traces it. Fewer than 2
 * samples along an axis, a box not finite with min < max on each axis, a NaN or infinite sample,
 * NULL name, box or samples: 0 and GL_INVALID_VALUE; more than 2^24 samples: GL_OUT_OF_MEMORY;
 * another interpolation: GL_INVALID_ENUM; inside glBegin / glEnd: GL_INVALID_OPERATION. After
 * a failure pfglGetFieldLogEXT(0, ...) says what was wrong. */
#define GL_FIELD_TRILINEAR_EXT 0x31033
#define GL_FIELD_TRICUBIC_EXT 0x31034
GLuint pfglSampledFieldEXT(const GLchar *name, GLsizei nx, GLsizei ny, GLsizei nz, const GLdouble *box,
                           GLenum interpolation, const GLfloat *samples);

#ifdef __cplusplus
}
#endif

#endif
