/* primflow/osmesa.h: OSMesa's interface, for programs linking libprimflow-osmesa (-lprimflow-osmesa).
 * Source-compatible with Mesa's <GL/osmesa.h> (same constants, version macros, types and
 * functions; the same include guard, so either header may be included, or both). What differs
 * from Mesa 22.3's OSMesa is listed in docs/api.md, "Porting from OSMesa". */
#ifndef OSMESA_H
#define OSMESA_H

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The OSMesa interface version this header describes (Mesa's osmesa.h of Mesa 11.2 and later). */
#define OSMESA_MAJOR_VERSION 11
#define OSMESA_MINOR_VERSION 2
#define OSMESA_PATCH_VERSION 0

/* Colour formats: OSMesaCreateContext*'s format. */
#define OSMESA_COLOR_INDEX GL_COLOR_INDEX
#define OSMESA_RGBA GL_RGBA
#define OSMESA_BGRA 0x1
#define OSMESA_ARGB 0x2
#define OSMESA_RGB GL_RGB
#define OSMESA_BGR 0x4
#define OSMESA_RGB_565 0x5

/* OSMesaPixelStore parameters */
#define OSMESA_ROW_LENGTH 0x10
#define OSMESA_Y_UP 0x11

/* OSMesaGetIntegerv parameters */
#define OSMESA_WIDTH 0x20
#define OSMESA_HEIGHT 0x21
#define OSMESA_FORMAT 0x22
#define OSMESA_TYPE 0x23
#define OSMESA_MAX_WIDTH 0x24
#define OSMESA_MAX_HEIGHT 0x25

/* OSMesaCreateContextAttribs attributes (OSMESA_FORMAT above is one too) */
#define OSMESA_DEPTH_BITS 0x30
#define OSMESA_STENCIL_BITS 0x31
#define OSMESA_ACCUM_BITS 0x32
#define OSMESA_PROFILE 0x33
#define OSMESA_CORE_PROFILE 0x34
#define OSMESA_COMPAT_PROFILE 0x35
#define OSMESA_CONTEXT_MAJOR_VERSION 0x36
#define OSMESA_CONTEXT_MINOR_VERSION 0x37

typedef struct osmesa_context *OSMesaContext;
typedef void (*OSMESAproc)();

/* OSMesaCreateContextExt(format, 24, 8, 0, sharelist) */
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContext(GLenum format, OSMesaContext sharelist);
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContextExt(GLenum format, GLint depthBits, GLint stencilBits,
                                                      GLint accumBits, OSMesaContext sharelist);
/* A zero-terminated list of (attribute, value) pairs. */
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContextAttribs(const int *attribList, OSMesaContext sharelist);
GLAPI void GLAPIENTRY OSMesaDestroyContext(OSMesaContext ctx);
/* type: GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT or GL_FLOAT (GL_UNSIGNED_SHORT_5_6_5 for
 * OSMESA_RGB_565). ctx = NULL and buffer = NULL release the current context. */
GLAPI GLboolean GLAPIENTRY OSMesaMakeCurrent(OSMesaContext ctx, void *buffer, GLenum type, GLsizei width,
                                             GLsizei height);
GLAPI OSMesaContext GLAPIENTRY OSMesaGetCurrentContext(void);
GLAPI void GLAPIENTRY OSMesaPixelStore(GLint pname, GLint value);
GLAPI void GLAPIENTRY OSMesaGetIntegerv(GLint pname, GLint *value);
GLAPI GLboolean GLAPIENTRY OSMesaGetDepthBuffer(OSMesaContext c, GLint *width, GLint *height,
                                                GLint *bytesPerValue, void **buffer);
GLAPI GLboolean GLAPIENTRY OSMesaGetColorBuffer(OSMesaContext c, GLint *width, GLint *height, GLint *format,
                                                void **buffer);
GLAPI OSMESAproc GLAPIENTRY OSMesaGetProcAddress(const char *funcName);
GLAPI void GLAPIENTRY OSMesaColorClamp(GLboolean enable);
GLAPI void GLAPIENTRY OSMesaPostprocess(OSMesaContext osmesa, const char *filter, unsigned enable_value);

#ifdef __cplusplus
}
#endif

#endif
