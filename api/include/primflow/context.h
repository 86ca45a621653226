/* primflow/context.h: rendering contexts, shaped like OSMesa's so that its users can switch by
 * renaming (OSMesaCreateContext -> pfCreateContext, ...). A context owns the GL state and the
 * renderer; the colour buffer belongs to the caller and is written at glFinish / glFlush. */
#ifndef PRIMFLOW_CONTEXT_H
#define PRIMFLOW_CONTEXT_H

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct PFcontextRec *PFcontext;

/* Attributes for pfCreateContextAttribs: a zero-terminated list of (name, value) pairs. */
#define PF_FORMAT      0x31100 /* colour format: GL_RGBA (the only one so far)            */
#define PF_DEPTH_BITS  0x31101 /* 0 (no depth buffer) or any positive size: float depth    */
#define PF_THREADS     0x31102 /* rasterizer threads; 0 = PF_NUM_THREADS env var, else all cores */
#define PF_ITERATION_CAP 0x31103 /* iterations one loop of a primitive may run per pixel (and per
                                    instance in setup); 0 = the default, 65536 */
#define PF_JIT         0x31104 /* 1: pixel programs as native code where it can (the default, unless
                                  the PF_JIT env var is 0); 0: all on the interpreter. Images are
                                  identical either way. */
#define PF_STENCIL_BITS 0x31105 /* 0 (no stencil buffer, the default) or any positive size: an 8-bit
                                   stencil buffer */
#define PF_ACCUM_BITS  0x31106 /* 0 (no accumulation buffer, the default) or any positive size: an
                                  accumulation buffer of 16 signed bits per channel, as OSMesa's */

/* A context rendering GL_RGBA with a depth buffer when depthBits > 0; NULL on a bad format. */
PFcontext pfCreateContext(GLenum format, GLint depthBits);
PFcontext pfCreateContextAttribs(const int *attribList);

/* Binds ctx to the calling thread and to the caller's buffer (width x height pixels of RGBA,
 * type GL_UNSIGNED_BYTE, row 0 at the bottom as in OSMesa). Returns GL_FALSE on bad arguments
 * (NULL buffer, non-positive or over-8192 sizes, a type other than GL_UNSIGNED_BYTE). Passing
 * ctx = NULL releases the current context. */
GLboolean pfMakeCurrent(PFcontext ctx, void *buffer, GLenum type, GLsizei width, GLsizei height);

PFcontext pfGetCurrentContext(void);

/* The depth buffer: width x height floats (bytesPerValue = 4), window-space depth in [0, 1]
 * after glDepthRange, row 0 at the bottom. Pending drawing is finished first. GL_FALSE when the
 * context has no depth buffer or is not bound to a buffer. */
GLboolean pfGetDepthBuffer(PFcontext ctx, GLint *width, GLint *height, GLint *bytesPerValue,
                           void **buffer);

/* The colour buffer, as OSMesaGetColorBuffer: the caller's buffer bound by pfMakeCurrent
 * (width x height RGBA bytes, format GL_RGBA, row 0 at the bottom). Pending drawing is finished
 * first. GL_FALSE when the context is not bound to a buffer. */
GLboolean pfGetColorBuffer(PFcontext ctx, GLint *width, GLint *height, GLint *format, void **buffer);

/* The rasterizer thread count the context uses. */
GLint pfGetThreadCount(PFcontext ctx);

void pfDestroyContext(PFcontext ctx);

#ifdef __cplusplus
}
#endif

#endif
