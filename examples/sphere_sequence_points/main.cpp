// Example 2: the paper's figure 3. A primitive of our own, compiled at run time, takes a centre
// and a radius bound per sequence point, so one glBegin / glEnd draws many spheres:
//
//   glBegin(my_sphere_primitive);
//   glRastParamfEXT(radius_name, radius_value);
//   glRastParam3fEXT(center_name, cx, cy, cz);
//   glSequencePointEXT();
//   glEnd();
//
// The sphere here is deliberately minimal (its radius is in window pixels, its shading a fixed
// light): the [shapes] primitives bring the real one. Writes sphere_sequence_points.png.
#include <primflow/gl.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "png_image.h"

namespace {

const char* kSphere = R"(
// A sphere seen from far away: a disk of `radius` pixels around the centre's window position,
// shaded as a hemisphere facing the viewer and lit from the upper left, with its depth.
primitive my_sphere(point center[1]; float radius[1]; interpolator_data interp_data[1];
                    varying float X, Y; inout varying float Z)
{
    point c = screen(center[0]);
    if (c.w <= 0) return;
    float cx = c.x / c.w;
    float cy = c.y / c.w;
    float r = radius[0];
    bound(cx - r, cy - r, cx + r, cy + r);
    float dx = (X - cx) / r;
    float dy = (Y - cy) / r;
    float d2 = dx * dx + dy * dy;
    if (d2 >= 1) return;
    float nz = sqrt(1 - d2);
    float z = c.z / c.w - nz * 0.02;
    if (!ztest(z)) return;
    Z = z;
    float light = 0.25 + 0.75 * max(dot(vector(dx, dy, nz), normalize(vector(-0.4, 0.5, 0.77))), 0.0);
    interpolation {
    perspective_linear:
    linear:
        interpolator_return(interp_data[0] * light);
    default:
        interpolator_return;
    }
}
)";

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "sphere_sequence_points.png";
  const int w = 320, h = 240;
  std::vector<uint8_t> pixels(static_cast<size_t>(w) * h * 4);
  PFcontext ctx = pfCreateContext(GL_RGBA, 24);
  if (!ctx || !pfMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, w, h)) return 1;

  if (pfglCompilePrimitivesEXT(kSphere) == 0) {
    char log[2048];
    pfglGetCompileLogEXT(0, sizeof log, nullptr, log);
    std::fprintf(stderr, "%s", log);
    return 1;
  }
  const GLenum my_sphere_primitive = pfglGetPrimitiveEXT("my_sphere");
  const GLuint center_name = pfglGetParamNameEXT("center");
  const GLuint radius_name = pfglGetParamNameEXT("radius");

  pfglClearColor(0.05f, 0.05f, 0.08f, 1.0f);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.4, 0.4, -0.3, 0.3, 1.0, 50.0);
  pfglMatrixMode(GL_MODELVIEW);

  // A spiral of spheres, near to far, in one glBegin / glEnd.
  pfglBegin(my_sphere_primitive);
  for (int i = 0; i < 40; ++i) {
    const float t = 0.45f * static_cast<float>(i);
    const float depth = -3.0f - 0.5f * static_cast<float>(i);
    pfglColor3f(0.5f + 0.5f * std::cos(t), 0.5f + 0.5f * std::sin(t), 0.9f);
    pfglRastParamfEXT(radius_name, 40.0f * 3.0f / -depth);
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
