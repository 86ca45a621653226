// pfspheres' exact side: primflow drawing every sphere with its `sphere` primitive
// (primitives/sphere.pfl) -- one glBegin / glEnd, one sequence point a sphere -- ray-cast and lit
// per pixel. Compiled against <primflow/gl_mangle.h>, so the shared frame state is the same source
// as OSMesa's.
#include <primflow/gl_mangle.h>

#include <chrono>
#include <vector>

#include "bench/sphere_scene.h"

#include "bench/sphere_frame.inc"

namespace pfspheres {

namespace {

struct SpherePrimitive {
  GLenum primitive;
  GLuint center, radius;
};

// One frame: all spheres in one glBegin(sphere) ... glEnd, ending in glFinish.
void drawPrimitiveFrame(const SphereScene& s, const SpherePrimitive& p, Pass pass) {
  beginSphereFrame(s, pass);
  glBegin(p.primitive);
  for (size_t i = 0; i < s.spheres.size(); ++i) {
    const Sphere& sp = s.spheres[i];
    setSphereColor(s, i, pass);
    pfglRastParamfEXT(p.radius, sp.radius);
    pfglRastParam3fEXT(p.center, sp.center[0], sp.center[1], sp.center[2]);
    pfglSequencePointEXT();
  }
  glEnd();
  glFinish();
}

}  // namespace

Rendering renderWithPrimflowSpheres(const SphereScene& s, int threads, const Timing& t) {
  Rendering out;
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, threads, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  if (!ctx) {
    out.error = "pfCreateContextAttribs failed";
    return out;
  }
  std::vector<unsigned char> buffer(static_cast<size_t>(s.width) * s.height * 4);
  if (!pfMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, s.width, s.height)) {
    out.error = "pfMakeCurrent failed";
  } else {
    const SpherePrimitive p{pfglGetPrimitiveEXT("sphere"), pfglGetParamNameEXT("center"),
                            pfglGetParamNameEXT("radius")};
    if (p.primitive == 0) out.error = "no built-in `sphere` primitive";
    for (int i = 0; i < t.warmup + t.frames && out.error.empty(); ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      drawPrimitiveFrame(s, p, Pass::Lit);
      const auto t1 = std::chrono::steady_clock::now();
      if (i >= t.warmup) out.frame_ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    }
    if (out.error.empty()) {
      readSphereFrame(s, Pass::Lit, &out);
      drawPrimitiveFrame(s, p, Pass::Id);
      readSphereFrame(s, Pass::Id, &out);
    }
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  }
  pfDestroyContext(ctx);
  return out;
}

}  // namespace pfspheres
