// The stencil test and its operations (GL 1.5 section 4.1.5) on an 8-bit stencil buffer: a
// draw's snapshot of them (StencilOps, part of FragmentOps) and what they do to one pixel's
// stored value. The renderer applies them per fragment after a stencil draw's two runs
// (docs/architecture.md, "Ordered fragments": the first finds the pixels it covers, the second
// which of them pass the depth test).
#pragma once

#include <cstdint>

#include <GL/gl.h>

namespace pf {

// A comparison of GL's glAlphaFunc / glDepthFunc / glStencilFunc (GL_NEVER + value).
enum class CompareFunc : uint8_t { Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always };

// Whether `value` passes `func` against `ref` (value func ref).
inline bool compares(CompareFunc func, float value, float ref) {
  switch (func) {
    case CompareFunc::Never: return false;
    case CompareFunc::Less: return value < ref;
    case CompareFunc::Equal: return value == ref;
    case CompareFunc::LessEqual: return value <= ref;
    case CompareFunc::Greater: return value > ref;
    case CompareFunc::NotEqual: return value != ref;
    case CompareFunc::GreaterEqual: return value >= ref;
    case CompareFunc::Always: return true;
  }
  return true;
}

struct StencilOps {
  bool test = false;  // on, and the framebuffer has a stencil buffer
  CompareFunc func = CompareFunc::Always;
  uint8_t ref = 0;          // clamped to [0, 255]
  uint8_t value_mask = 0xff, write_mask = 0xff;
  // glStencilOp's three: stencil test failed; passed and the depth test failed; both passed.
  GLenum fail = GL_KEEP, depth_fail = GL_KEEP, depth_pass = GL_KEEP;

  // Whether a fragment over the stored value `stored` passes: (ref & mask) func (stored & mask).
  bool passes(uint8_t stored) const {
    return compares(func, static_cast<float>(ref & value_mask), static_cast<float>(stored & value_mask));
  }
  bool operator==(const StencilOps&) const = default;
};

// The stored value after `op` (GL_KEEP ... GL_DECR_WRAP) on `stored`, under the write mask.
inline uint8_t stencilApply(const StencilOps& s, GLenum op, uint8_t stored) {
  int v;
  switch (op) {
    case GL_ZERO: v = 0; break;
    case GL_REPLACE: v = s.ref; break;
    case GL_INCR: v = stored < 255 ? stored + 1 : 255; break;
    case GL_DECR: v = stored > 0 ? stored - 1 : 0; break;
    case GL_INVERT: v = ~stored & 0xff; break;
    case GL_INCR_WRAP: v = (stored + 1) & 0xff; break;
    case GL_DECR_WRAP: v = (stored + 255) & 0xff; break;
    default: return stored;  // GL_KEEP
  }
  return static_cast<uint8_t>((stored & ~s.write_mask) | (v & s.write_mask));
}

}  // namespace pf
