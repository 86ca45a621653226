// Example 2: the paper's figure 3. The built-in `sphere` primitive takes a centre and a radius
// bound per sequence point, so one glBegin / glEnd draws many spheres:
//
//   glBegin(my_sphere_primitive);
//   glRastParamfEXT(radius_name, radius_value);
//   glRastParam3fEXT(center_name, cx, cy, cz);
//   glSequencePointEXT();
//   glEnd();
//
// Each sphere is exact (ray-cast per pixel, no tessellation) and lit per pixel by GL's lighting.
// Writes sphere_sequence_points.png.
#include <primflow/gl.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "png_image.h"

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "sphere_sequence_points.png";
  const int w = 320, h = 240;
  std::vector<uint8_t> pixels(static_cast<size_t>(w) * h * 4);
  PFcontext ctx = pfCreateContext(GL_RGBA, 24);
  if (!ctx || !pfMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, w, h)) return 1;

  const GLenum my_sphere_primitive = pfglGetPrimitiveEXT("sphere");
  const GLuint center_name = pfglGetParamNameEXT("center");
  const GLuint radius_name = pfglGetParamNameEXT("radius");

  pfglClearColor(0.05f, 0.05f, 0.08f, 1.0f);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  // GL lighting: a key light up left; the colour is the material (GL_COLOR_MATERIAL).
  const GLfloat key[4] = {-1.0f, 1.5f, 2.0f, 0.0f};
  const GLfloat specular[4] = {0.5f, 0.5f, 0.5f, 1.0f};
  pfglLightfv(GL_LIGHT0, GL_POSITION, key);
  pfglEnable(GL_LIGHT0);
  pfglMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  pfglMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
  pfglEnable(GL_COLOR_MATERIAL);
  pfglEnable(GL_LIGHTING);
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.4, 0.4, -0.3, 0.3, 1.0, 50.0);
  pfglMatrixMode(GL_MODELVIEW);

  // A spiral of spheres, near to far, in one glBegin / glEnd.
  pfglBegin(my_sphere_primitive);
  for (int i = 0; i < 40; ++i) {
    const float t = 0.45f * static_cast<float>(i);
    const float depth = -3.0f - 0.5f * static_cast<float>(i);
    pfglColor3f(0.5f + 0.5f * std::cos(t), 0.5f + 0.5f * std::sin(t), 0.9f);
    pfglRastParamfEXT(radius_name, 0.18f);
    pfglRastParam3fEXT(center_name, 1.2f * std::cos(t), 0.9f * std::sin(t), depth);
    pfglSequencePointEXT();
  }
  pfglEnd();
  pfglFinish();

  const GLenum error = pfglGetError();
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
  std::string message;
  if (error != GL_NO_ERROR || !pf::writePngBottomUp(out, pixels.data(), w, h, &message)) {
    std::fprintf(stderr, "sphere_sequence_points: %s\n", error != GL_NO_ERROR ? "GL error" : message.c_str());
    return 1;
  }
  std::printf("wrote %s\n", out.c_str());
  return 0;
}
