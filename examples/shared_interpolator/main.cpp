// Example 3: a shared interpolator (paper section 3.4). A user primitive -- a ring, drawn per
// pixel -- and a user interpolator compiled at run time; the colour of the ring is bound to the
// interpolator, which computes it from the surface point P and its own parameter `bands`, so
// the same solid stripes continue across the ring and a GL quad drawn through them.
// Writes shared_interpolator.png.
#include <primflow/gl.h>

#include <cstdio>
#include <string>
#include <vector>

#include "png_image.h"

namespace {

const char* kSource = R"(
// A flat ring in the plane z = depth (eye coordinates, through the vertex's transform), between
// radii r0 and r1 around the centre: a test per pixel in window space, P for its interpolators.
primitive ring(point vertex[1]; float r0; float r1; interpolator_data interp_data[1];
               varying float X, Y; inout varying float Z)
{
    point c = screen(vertex[0]);
    if (c.w <= 0) return;
    float cx = c.x / c.w;
    float cy = c.y / c.w;
    bound(cx - r1, cy - r1, cx + r1, cy + r1);
    float d = sqrt((X - cx) * (X - cx) + (Y - cy) * (Y - cy));
    if (d < r0 || d >= r1) return;
    float z = c.z / c.w;
    if (!ztest(z)) return;
    Z = z;
    interpolation {
    perspective_linear:
    linear:
        interpolator_return(interp_data[0]);
    default:
        // The point of the ring's plane under this pixel, in eye coordinates: where the ray from
        // the eye through the pixel meets the plane z = the centre's z.
        point e = eye(vertex[0]);
        point q = eye(unscreen(point(X, Y, 0.0)));  // a point of that ray (on the near plane)
        float t = (e.z / e.w) / (q.z / q.w);
        P = point(q.x / q.w * t, q.y / q.w * t, e.z / e.w);
        interpolator_return;
    }
}

// Solid stripes along x + y, `bands` of them per unit, blending two colours.
interpolator stripes(float bands)
{
    float s = 0.5 + 0.5 * sin((P.x + P.y) * bands * 3.14159265);
    interpolator_return(mix(color(0.95, 0.55, 0.15, 1.0), color(0.2, 0.3, 0.8, 1.0), s));
}
)";

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "shared_interpolator.png";
  const int w = 320, h = 240;
  std::vector<uint8_t> pixels(static_cast<size_t>(w) * h * 4);
  PFcontext ctx = pfCreateContext(GL_RGBA, 24);
  if (!ctx || !pfMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, w, h)) return 1;
  if (pfglCompilePrimitivesEXT(kSource) == 0) {
    char log[4096];
    pfglGetCompileLogEXT(0, sizeof log, nullptr, log);
    std::fprintf(stderr, "%s", log);
    return 1;
  }
  const GLenum ring = pfglGetPrimitiveEXT("ring");
  const GLenum stripes = pfglGetInterpolatorEXT("stripes");
  const GLuint color = pfglGetParamNameEXT("color");
  // The colour of rings and of GL quads comes from the stripes interpolator.
  pfglMaterialInterpEXT(color, ring, stripes);
  pfglMaterialInterpEXT(color, GL_QUADS, stripes);
  pfglRastParamfEXT(pfglGetParamNameEXT("bands"), 2.0f);

  pfglClearColor(0.05f, 0.05f, 0.07f, 1.0f);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-1.0, 1.0, -0.75, 0.75, 1.0, 10.0);
  pfglMatrixMode(GL_MODELVIEW);

  // A quad at z = -2.5, then a ring in front of it at z = -2.
  pfglBegin(GL_QUADS);
  pfglVertex3f(-1.8f, -1.3f, -2.5f);
  pfglVertex3f(0.0f, -1.3f, -2.5f);
  pfglVertex3f(0.0f, 1.3f, -2.5f);
  pfglVertex3f(-1.8f, 1.3f, -2.5f);
  pfglEnd();
  pfglBegin(ring);
  pfglRastParamfEXT(pfglGetParamNameEXT("r0"), 40.0f);
  pfglRastParamfEXT(pfglGetParamNameEXT("r1"), 90.0f);
  pfglVertex3f(0.6f, 0.0f, -2.0f);
  pfglEnd();
  pfglFinish();

  const GLenum error = pfglGetError();
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
  std::string message;
  if (error != GL_NO_ERROR || !pf::writePngBottomUp(out, pixels.data(), w, h, &message)) {
    std::fprintf(stderr, "shared_interpolator: %s\n", error != GL_NO_ERROR ? "GL error" : message.c_str());
    return 1;
  }
  std::printf("wrote %s\n", out.c_str());
  return 0;
}
