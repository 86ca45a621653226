// The GL cases drawn by OSMesa (Mesa's llvmpipe), the reference: cases.inc's gl* calls go to
// libOSMesa here. This translation unit must not see primflow's GL names.
// (GL_GLEXT_PROTOTYPES: the GL 1.4 entry points the cases call, glBlendFuncSeparate, are
// declared by <GL/glext.h> only with it; libOSMesa exports them.)
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <cmath>
#include <cstring>
#include <utility>
#include <string>
#include <vector>

#include "conformance.h"

#include "cases.inc"
#include "read_back.inc"

namespace pfconf {

Rendering renderOsmesa(const std::string& name, int width, int height) {
  Rendering r;
  const GlCase* c = findCase(name);
  if (!c) return r;
  std::vector<uint8_t> buffer(static_cast<size_t>(width) * height * 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, nullptr);  // (the stencil and accumulation cases need them)
  if (!ctx) return r;
  if (OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, width, height)) drawAndRead(*c, width, height, r);
  OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  OSMesaDestroyContext(ctx);
  return r;
}

}  // namespace pfconf
