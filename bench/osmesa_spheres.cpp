// pfspheres' tessellated side: OSMesa (llvmpipe) drawing each sphere with gluSphere, GLU_SMOOTH
// normals, lit per vertex by GL's fixed function and Gouraud-shaded.
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>

#include <chrono>
#include <vector>

#include "bench/sphere_scene.h"

#include "bench/sphere_frame.inc"

namespace pfspheres {

namespace {

// One frame: every sphere translated to its centre and tessellated by GLU into slices x slices
// quads (the polar caps are triangle fans), ending in glFinish.
void drawGluFrame(const SphereScene& s, GLUquadric* quadric, int slices, Pass pass) {
  beginSphereFrame(s, pass);
  for (size_t i = 0; i < s.spheres.size(); ++i) {
    const Sphere& sp = s.spheres[i];
    setSphereColor(s, i, pass);
    glPushMatrix();
    glTranslatef(sp.center[0], sp.center[1], sp.center[2]);
    gluSphere(quadric, sp.radius, slices, slices);
    glPopMatrix();
  }
  glFinish();
}

}  // namespace

Rendering renderWithGluSpheres(const SphereScene& s, int slices, const Timing& t) {
  Rendering out;
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!ctx) {
    out.error = "OSMesaCreateContextExt failed";
    return out;
  }
  std::vector<unsigned char> buffer(static_cast<size_t>(s.width) * s.height * 4);
  GLUquadric* quadric = gluNewQuadric();
  if (!OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, s.width, s.height) || !quadric) {
    out.error = "OSMesaMakeCurrent or gluNewQuadric failed";
  } else {
    glDisable(GL_DITHER);  // primflow does not dither; neither should the reference
    gluQuadricNormals(quadric, GLU_SMOOTH);
    gluQuadricDrawStyle(quadric, GLU_FILL);
    for (int i = 0; i < t.warmup + t.frames; ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      drawGluFrame(s, quadric, slices, Pass::Lit);
      const auto t1 = std::chrono::steady_clock::now();
      if (i >= t.warmup) out.frame_ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    }
    readSphereFrame(s, Pass::Lit, &out);
    drawGluFrame(s, quadric, slices, Pass::Id);
    readSphereFrame(s, Pass::Id, &out);
  }
  if (quadric) gluDeleteQuadric(quadric);
  OSMesaDestroyContext(ctx);
  return out;
}

}  // namespace pfspheres
