/* The client suite's context (tests/clients): what a client without GLU does around its
 * drawing -- create a context with depth (and stencil) bits, OSMesa's or, through
 * gl_mangle.h (PF_CLIENT_MANGLE), primflow's; bind it to a buffer of its own; print
 * GL_RENDERER; and at the end write the image and the depth (client_output.h) and say whether
 * GL reported an error. Include it after the GL header. */
#ifndef CLIENT_CONTEXT_H
#define CLIENT_CONTEXT_H

#include <stdio.h>
#include <stdlib.h>

#include "client_output.h"

/* Accumulation bits of the context: a client that needs the buffer defines this before the include. */
#ifndef CLIENT_ACCUM_BITS
#define CLIENT_ACCUM_BITS 0
#endif

typedef struct {
#ifdef PF_CLIENT_MANGLE
  PFcontext ctx;
#else
  OSMesaContext ctx;
#endif
  GLubyte *buffer;
  int width, height;
} client_context;

/* Creates and binds the context; 0 on failure. `argc` / `argv`: the client's, which must name
 * the output image (usage: NAME OUT.pam [DEPTH]). */
static int client_begin(client_context *c, int argc, char *argv[], int width, int height, int depth_bits,
                        int stencil_bits) {
  int ok;
  if (argc < 2) {
    fprintf(stderr, "usage: %s OUT.pam [DEPTH]\n", argv[0]);
    return 0;
  }
#ifdef PF_CLIENT_MANGLE
  {
    const int attribs[] = {PF_FORMAT,       GL_RGBA,      PF_DEPTH_BITS,     depth_bits, PF_STENCIL_BITS,
                           stencil_bits,    PF_ACCUM_BITS, CLIENT_ACCUM_BITS, 0};
    c->ctx = pfCreateContextAttribs(attribs);
  }
#else
  c->ctx = OSMesaCreateContextExt(OSMESA_RGBA, depth_bits, stencil_bits, CLIENT_ACCUM_BITS, NULL);
#endif
  c->width = width;
  c->height = height;
  c->buffer = (GLubyte *)malloc((size_t)width * height * 4);
  if (!c->ctx || !c->buffer) return 0;
#ifdef PF_CLIENT_MANGLE
  ok = pfMakeCurrent(c->ctx, c->buffer, GL_UNSIGNED_BYTE, width, height);
#else
  ok = OSMesaMakeCurrent(c->ctx, c->buffer, GL_UNSIGNED_BYTE, width, height);
#endif
  if (ok) printf("%s\n", (const char *)glGetString(GL_RENDERER));
  return ok;
}

/* After glFinish: writes the image to argv[1] (and the depth to argv[2], if given), frees the
 * context; returns the client's exit code (1: no output, 3: a GL error, 0: fine). */
static int client_end(client_context *c, int argc, char *argv[]) {
  GLint w = 0, h = 0, bytes = 0;
  void *depth = NULL;
  float *z = NULL;
  int ok;
  if (!client_write_pam(argv[1], c->width, c->height, c->buffer)) return 1;
#ifdef PF_CLIENT_MANGLE
  if (pfGetDepthBuffer(c->ctx, &w, &h, &bytes, &depth)) z = client_depth_to_float(depth, w, h, bytes, 1);
#else
  if (OSMesaGetDepthBuffer(c->ctx, &w, &h, &bytes, &depth)) z = client_depth_to_float(depth, w, h, bytes, 0);
#endif
  if (argc > 2 && (!z || !client_write_depth(argv[2], w, h, z))) return 1;
  ok = glGetError() == GL_NO_ERROR;
  free(z);
  free(c->buffer);
#ifdef PF_CLIENT_MANGLE
  pfDestroyContext(c->ctx);
#else
  OSMesaDestroyContext(c->ctx);
#endif
  return ok ? 0 : 3;
}

#endif
