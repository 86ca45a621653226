// libprimflow-osmesa: OSMesa's entry points over a primflow context, with Mesa 22.3's OSMesa
// semantics (measured by calling it; docs/api.md, "Porting from OSMesa", lists what differs).
// As OSMesa does, primflow draws into a frame of its own (RGBA, 8 bits a channel) and the
// caller's buffer is written, in the caller's format, at glFinish / glFlush and when the
// context is released or another one is made current -- if anything was drawn since it was
// last written. Where OSMesa would crash on bad input
// (NULL context, no current context, NULL attribute list), these return GL_FALSE / NULL / 0.
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <vector>

#include <primflow/gl.h>
#include <primflow/osmesa.h>

#include "api/osmesa/entry_points.h"
#include "api/osmesa/pixel_formats.h"
#include "api/src/frame_hook.h"
#include "raster/limits.h"

struct osmesa_context {
  PFcontext pf = nullptr;
  GLenum format = GL_RGBA;
  int depth_bits = 0;  // what OSMesa gives for the bits asked: 0, 16 or 24
  // The drawable: the caller's buffer and primflow's frame (width x height RGBA8).
  bool bound = false;
  GLenum type = 0;
  void* buffer = nullptr;
  int width = 0, height = 0;
  std::vector<uint8_t> frame;
  GLint row_length = 0;  // OSMESA_ROW_LENGTH: pixels from row to row, 0: width
  GLboolean y_up = GL_TRUE;
  // OSMesaGetDepthBuffer's copy in OSMesa's layout: made at its first call, refreshed with the
  // colour buffer from then on.
  std::vector<uint8_t> depth_copy;
  bool depth_requested = false;
};

namespace {

thread_local osmesa_context* g_current = nullptr;

// The caller's buffer from primflow's frame (and the depth copy, once asked for).
void writeFrame(void* user) {
  auto* c = static_cast<osmesa_context*>(user);
  if (!c->bound) return;
  // A negative OSMESA_ROW_LENGTH is kept (OSMesaGetIntegerv returns it) but packs rows as 0 does:
  // OSMesa would write before the buffer.
  const int row_pixels = c->row_length > 0 ? c->row_length : c->width;
  pf::osmesa::writeColor(c->frame.data(), c->width, c->height, c->format, c->type, c->buffer, row_pixels,
                         c->y_up != GL_FALSE);
  if (c->depth_requested && !c->depth_copy.empty()) {
    void* depth = nullptr;
    if (pfGetDepthBuffer(c->pf, nullptr, nullptr, nullptr, &depth))
      pf::osmesa::writeDepth(static_cast<const float*>(depth), c->width, c->height, c->depth_bits,
                             c->depth_copy.data());
  }
}

// OSMesa's depth buffer for the bits asked (Mesa 22.3): depth and stencil together are 24-bit
// depth with 8-bit stencil; stencil alone, no depth; otherwise 24 bits from 24 up, 16 from 16 up.
int depthBitsFor(int depth, int stencil) {
  if (depth > 0 && stencil > 0) return 24;
  if (stencil > 0) return 0;
  return depth >= 24 ? 24 : depth >= 16 ? 16 : 0;
}

bool validFormat(int format) {
  switch (format) {
    case OSMESA_COLOR_INDEX:
    case OSMESA_RGBA:
    case OSMESA_BGRA:
    case OSMESA_ARGB:
    case OSMESA_RGB:
    case OSMESA_BGR:
    case OSMESA_RGB_565: return true;
    default: return false;
  }
}

}  // namespace

extern "C" {

GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContextAttribs(const int* attribList, OSMesaContext sharelist) {
  GLenum format = GL_RGBA;
  int depth = 0, stencil = 0, accum = 0;
  int profile = OSMESA_COMPAT_PROFILE, major = 1, minor = 0;
  for (const int* a = attribList; a && a[0] != 0; a += 2) {
    const int value = a[1];
    switch (a[0]) {
      case OSMESA_FORMAT:
        if (!validFormat(value)) return nullptr;
        format = static_cast<GLenum>(value);
        break;
      case OSMESA_DEPTH_BITS: depth = value; break;
      case OSMESA_STENCIL_BITS: stencil = value; break;
      case OSMESA_ACCUM_BITS: accum = value; break;
      case OSMESA_PROFILE:
        if (value != OSMESA_CORE_PROFILE && value != OSMESA_COMPAT_PROFILE) return nullptr;
        profile = value;
        break;
      case OSMESA_CONTEXT_MAJOR_VERSION: major = value; break;
      case OSMESA_CONTEXT_MINOR_VERSION: minor = value; break;
      default:
        std::fprintf(stderr, "Bad attribute in OSMesaCreateContextAttribs()\n");
        return nullptr;
    }
    if (depth < 0 || stencil < 0 || accum < 0 || major < 1 || minor < 0) return nullptr;
  }
  // The versions Mesa 22.3 creates (up to 4.5, either profile); primflow draws GL 1.x whatever
  // was asked.
  (void)profile;
  if (static_cast<long>(major) * 10 + minor > 45) return nullptr;
  auto* c = new (std::nothrow) osmesa_context;
  if (!c) return nullptr;
  c->format = format;
  c->depth_bits = depthBitsFor(depth, stencil);
  const int attribs[] = {PF_FORMAT,       GL_RGBA, PF_DEPTH_BITS, c->depth_bits, PF_STENCIL_BITS,
                         stencil,         PF_ACCUM_BITS, accum, 0};
  // (An 8-bit stencil buffer for any stencil bits, a 16-bit accumulation buffer for any accum
  // bits, as OSMesa.)
  c->pf = pfCreateContextAttribs(attribs);
  if (!c->pf) {
    delete c;
    return nullptr;
  }
  pf::setFrameHook(c->pf, writeFrame, c);
  if (sharelist) pf::shareDisplayLists(c->pf, sharelist->pf);  // as OSMesa: display lists
  return c;
}

GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContextExt(GLenum format, GLint depthBits, GLint stencilBits,
                                                      GLint accumBits, OSMesaContext sharelist) {
  const int attribs[] = {OSMESA_FORMAT,       static_cast<int>(format), OSMESA_DEPTH_BITS, depthBits,
                         OSMESA_STENCIL_BITS, stencilBits,              OSMESA_ACCUM_BITS, accumBits,
                         0};
  return OSMesaCreateContextAttribs(attribs, sharelist);
}

GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContext(GLenum format, OSMesaContext sharelist) {
  return OSMesaCreateContextExt(format, 24, 8, 0, sharelist);
}

GLAPI void GLAPIENTRY OSMesaDestroyContext(OSMesaContext c) {
  if (!c) return;
  if (g_current == c) g_current = nullptr;
  pfDestroyContext(c->pf);  // releases it too if it is current
  delete c;
}

GLAPI GLboolean GLAPIENTRY OSMesaMakeCurrent(OSMesaContext c, void* buffer, GLenum type, GLsizei width,
                                             GLsizei height) {
  // Releasing the current context, or making another one current, writes its frame into its
  // buffer first, as OSMesa's flush on release does.
  osmesa_context* previous = g_current;
  if (!c && !buffer) {
    if (previous) pfglFlush();
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
    g_current = nullptr;
    return GL_TRUE;
  }
  if (!c || !buffer || width < 1 || height < 1) return GL_FALSE;
  if (pf::osmesa::colorPixelBytes(c->format, type) == 0) {
    std::fprintf(stderr, "OSMesaMakeCurrent(unsupported format/type)\n");
    return GL_FALSE;
  }
  // primflow's limit (OSMESA_MAX_WIDTH / OSMESA_MAX_HEIGHT); OSMesa accepts any size here.
  if (width > pf::kMaxFramebufferSize || height > pf::kMaxFramebufferSize) return GL_FALSE;
  if (previous && previous != c) pfglFlush();
  // The frame is kept while the size is (OSMesa keeps its colour buffer); a new one is bound
  // before the old one is freed (binding executes pending drawing into the old one).
  const size_t bytes = static_cast<size_t>(width) * height * 4;
  std::vector<uint8_t> frame;
  const bool resize = c->frame.size() != bytes || c->width != width || c->height != height;
  try {
    if (resize) frame.assign(bytes, 0);
  } catch (const std::bad_alloc&) {
    return GL_FALSE;
  }
  uint8_t* target = resize ? frame.data() : c->frame.data();
  if (!pfMakeCurrent(c->pf, target, GL_UNSIGNED_BYTE, width, height)) return GL_FALSE;
  if (resize) {
    c->frame.swap(frame);
    if (c->depth_requested) {
      try {
        c->depth_copy.assign(static_cast<size_t>(width) * height * pf::osmesa::depthValueBytes(c->depth_bits), 0);
      } catch (const std::bad_alloc&) {
        c->depth_copy.clear();
        c->depth_requested = false;
      }
    }
  }
  c->bound = true;
  c->buffer = buffer;
  c->type = type;
  c->width = width;
  c->height = height;
  g_current = c;
  return GL_TRUE;
}

GLAPI OSMesaContext GLAPIENTRY OSMesaGetCurrentContext(void) { return g_current; }

GLAPI void GLAPIENTRY OSMesaPixelStore(GLint pname, GLint value) {
  osmesa_context* c = g_current;
  switch (pname) {
    case OSMESA_ROW_LENGTH:
      if (c) c->row_length = value;
      return;
    case OSMESA_Y_UP:
      if (c) c->y_up = value ? GL_TRUE : GL_FALSE;
      return;
    default: std::fprintf(stderr, "Invalid pname in OSMesaPixelStore()\n"); return;
  }
}

GLAPI void GLAPIENTRY OSMesaGetIntegerv(GLint pname, GLint* value) {
  const osmesa_context* c = g_current;
  const bool bound = c && c->bound;
  GLint v = 0;
  switch (pname) {
    case OSMESA_WIDTH: v = bound ? c->width : 0; break;
    case OSMESA_HEIGHT: v = bound ? c->height : 0; break;
    case OSMESA_FORMAT: v = c ? static_cast<GLint>(c->format) : 0; break;
    case OSMESA_TYPE: v = c ? static_cast<GLint>(c->type) : 0; break;
    case OSMESA_ROW_LENGTH: v = c ? c->row_length : 0; break;
    case OSMESA_Y_UP: v = c ? c->y_up : 0; break;
    case OSMESA_MAX_WIDTH:
    case OSMESA_MAX_HEIGHT: v = pf::kMaxFramebufferSize; break;
    default: std::fprintf(stderr, "Invalid pname in OSMesaGetIntegerv()\n"); return;
  }
  if (value) *value = v;
}

GLAPI GLboolean GLAPIENTRY OSMesaGetDepthBuffer(OSMesaContext c, GLint* width, GLint* height,
                                                GLint* bytesPerValue, void** buffer) {
  GLint w = 0, h = 0, bytes = 0;
  void* out = nullptr;
  GLboolean ok = GL_FALSE;
  if (c && c->bound && c->depth_bits > 0) {
    if (!c->depth_requested) {
      // The first call takes a copy of the depth as it is; glFinish / glFlush refresh it.
      try {
        c->depth_copy.assign(static_cast<size_t>(c->width) * c->height * pf::osmesa::depthValueBytes(c->depth_bits), 0);
        void* depth = nullptr;
        if (pfGetDepthBuffer(c->pf, nullptr, nullptr, nullptr, &depth)) {
          pf::osmesa::writeDepth(static_cast<const float*>(depth), c->width, c->height, c->depth_bits,
                                 c->depth_copy.data());
          c->depth_requested = true;
        }
      } catch (const std::bad_alloc&) {
        c->depth_copy.clear();
      }
    }
    if (c->depth_requested) {
      w = c->width;
      h = c->height;
      bytes = pf::osmesa::depthValueBytes(c->depth_bits);
      out = c->depth_copy.data();
      ok = GL_TRUE;
    }
  }
  if (width) *width = w;
  if (height) *height = h;
  if (bytesPerValue) *bytesPerValue = bytes;
  if (buffer) *buffer = out;
  return ok;
}

GLAPI GLboolean GLAPIENTRY OSMesaGetColorBuffer(OSMesaContext c, GLint* width, GLint* height, GLint* format,
                                                void** buffer) {
  const bool bound = c && c->bound;
  if (width) *width = bound ? c->width : 0;
  if (height) *height = bound ? c->height : 0;
  if (format) *format = bound ? static_cast<GLint>(c->format) : 0;
  if (buffer) *buffer = bound ? c->buffer : nullptr;
  return bound ? GL_TRUE : GL_FALSE;
}

GLAPI void GLAPIENTRY OSMesaColorClamp(GLboolean enable) {
  (void)enable;  // primflow's colours are always in [0, 1]
}

GLAPI void GLAPIENTRY OSMesaPostprocess(OSMesaContext osmesa, const char* filter, unsigned enable_value) {
  (void)osmesa;  // no post-processing filters: as OSMesa with an unknown filter name
  (void)filter;
  (void)enable_value;
}

GLAPI OSMESAproc GLAPIENTRY OSMesaGetProcAddress(const char* funcName) {
  if (!funcName) return nullptr;
  static const struct {
    const char* name;
    OSMESAproc function;
  } kOSMesa[] = {
      {"OSMesaCreateContext", reinterpret_cast<OSMESAproc>(OSMesaCreateContext)},
      {"OSMesaCreateContextExt", reinterpret_cast<OSMESAproc>(OSMesaCreateContextExt)},
      {"OSMesaCreateContextAttribs", reinterpret_cast<OSMESAproc>(OSMesaCreateContextAttribs)},
      {"OSMesaDestroyContext", reinterpret_cast<OSMESAproc>(OSMesaDestroyContext)},
      {"OSMesaMakeCurrent", reinterpret_cast<OSMESAproc>(OSMesaMakeCurrent)},
      {"OSMesaGetCurrentContext", reinterpret_cast<OSMESAproc>(OSMesaGetCurrentContext)},
      {"OSMesaPixelStore", reinterpret_cast<OSMESAproc>(OSMesaPixelStore)},
      {"OSMesaGetIntegerv", reinterpret_cast<OSMESAproc>(OSMesaGetIntegerv)},
      {"OSMesaGetDepthBuffer", reinterpret_cast<OSMESAproc>(OSMesaGetDepthBuffer)},
      {"OSMesaGetColorBuffer", reinterpret_cast<OSMESAproc>(OSMesaGetColorBuffer)},
      {"OSMesaGetProcAddress", reinterpret_cast<OSMESAproc>(OSMesaGetProcAddress)},
      {"OSMesaColorClamp", reinterpret_cast<OSMESAproc>(OSMesaColorClamp)},
      {"OSMesaPostprocess", reinterpret_cast<OSMESAproc>(OSMesaPostprocess)},
  };
  for (const auto& f : kOSMesa)
    if (std::strcmp(f.name, funcName) == 0) return f.function;
  // GL by its name, or by primflow's (pfglBegin is glBegin).
  const char* gl_name = std::strncmp(funcName, "pfgl", 4) == 0 ? funcName + 2 : funcName;
  if (OSMESAproc f = pf_osmesa_gl_entry_point(gl_name)) return f;
  // OSMesa hands out a no-op for any other gl* name; primflow's records GL_INVALID_OPERATION.
  if (std::strncmp(funcName, "gl", 2) == 0) return pf_osmesa_unknown_entry_point;
  return nullptr;
}

}  // extern "C"

extern "C" void pf_osmesa_unsupported(const char* name) { pf::unsupportedEntryPoint(name); }

extern "C" void pf_osmesa_unknown_entry_point(void) {
  pf::unsupportedEntryPoint("a gl function OSMesaGetProcAddress does not know");
}
