// The GL cases drawn by primflow: cases.inc's gl* calls are renamed to primflow's pfgl* by
// <primflow/gl_mangle.h>. This build's table is the suite's list of GL cases.
#include <primflow/gl_mangle.h>

#include <cmath>
#include <cstring>
#include <utility>
#include <string>
#include <vector>

#include "conformance.h"

#include "cases.inc"
#include "read_back.inc"

namespace pfconf {

const std::vector<GlCase>& glCases() {
  static const std::vector<GlCase> cases(std::begin(kGlCaseTable), std::end(kGlCaseTable));
  return cases;
}

Rendering renderPrimflow(const std::string& name, int width, int height, int threads, int native) {
  Rendering r;
  const GlCase* c = findCase(name);
  if (!c) return r;
  std::vector<uint8_t> buffer(static_cast<size_t>(width) * height * 4);
  const int attribs[] = {PF_FORMAT,  GL_RGBA, PF_DEPTH_BITS, 24, PF_STENCIL_BITS, 8, PF_ACCUM_BITS, 16, PF_THREADS, threads,
                         native >= 0 ? PF_JIT : 0, native, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  if (!ctx) return r;
  if (pfMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, width, height)) drawAndRead(*c, width, height, r);
  pfMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  pfDestroyContext(ctx);
  return r;
}

}  // namespace pfconf
