// The built-in showcase: a depth-tested mesh of Gouraud triangles seen in perspective -- a
// rippled surface and a tilted checkered plane cutting through it, so the Z-buffer has real
// intersections to resolve. Written in plain GL-1.x calls, as an application would.
#include "showcase.h"

#include <primflow/gl_mangle.h>

#include <cmath>

namespace pf {
namespace {

constexpr float kPi = 3.14159265358979f;

float ripple(float x, float z) {
  float r = std::sqrt(x * x + z * z);
  return 0.45f * std::cos(2.2f * r) * std::exp(-0.25f * r);
}

// Colour of the ripple at (x, z): a height ramp, darkened by a fixed light on the slope
// (lighting baked into the vertex colours; GL lighting comes with the [raster] work).
void rippleColor(float x, float z) {
  const float e = 0.01f;
  float h = ripple(x, z);
  float dx = (ripple(x + e, z) - ripple(x - e, z)) / (2 * e);
  float dz = (ripple(x, z + e) - ripple(x, z - e)) / (2 * e);
  float nx = -dx, ny = 1.0f, nz = -dz;
  float len = std::sqrt(nx * nx + ny * ny + nz * nz);
  float diffuse = std::fmax(0.0f, (nx * -0.4f + ny * 0.8f + nz * 0.45f) / len);
  float t = (h + 0.45f) / 0.9f;
  float lit = 0.25f + 0.75f * diffuse;
  glColor3f(lit * (0.15f + 0.85f * t), lit * (0.35f + 0.45f * std::sin(kPi * t)), lit * (0.95f - 0.7f * t));
}

}  // namespace

void drawShowcase(int width, int height) {
  glViewport(0, 0, width, height);
  glClearColor(0.06f, 0.07f, 0.10f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  float aspect = static_cast<float>(width) / static_cast<float>(height);
  glFrustum(-0.6 * aspect, 0.6 * aspect, -0.6, 0.6, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  // Camera: looking down at the surface from above and in front (world -> eye by hand: the
  // spine's matrix subset is identity, ortho and frustum).
  const float cam_y = 3.4f, cam_z = 6.6f, pitch = 0.5f;
  const float cp = std::cos(pitch), sp = std::sin(pitch);
  auto vertex = [&](float x, float y, float z) {
    float yy = y - cam_y, zz = z - cam_z;
    glVertex3f(x, cp * yy - sp * zz, sp * yy + cp * zz);
  };

  // The rippled surface: a 96 x 96 grid, two triangles per cell.
  const int n = 96;
  const float extent = 4.0f;
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      float x0 = -extent + 2 * extent * i / n, x1 = -extent + 2 * extent * (i + 1) / n;
      float z0 = -extent + 2 * extent * j / n, z1 = -extent + 2 * extent * (j + 1) / n;
      auto v = [&](float x, float z) {
        rippleColor(x, z);
        vertex(x, ripple(x, z), z);
      };
      v(x0, z0); v(x1, z0); v(x1, z1);
      v(x0, z0); v(x1, z1); v(x0, z1);
    }
  }
  glEnd();

  // A tilted checkered plane cutting through the ripples.
  const int m = 12;
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < m; ++j) {
      float u0 = -2.6f + 5.2f * i / m, u1 = -2.6f + 5.2f * (i + 1) / m;
      float w0 = -2.6f + 5.2f * j / m, w1 = -2.6f + 5.2f * (j + 1) / m;
      bool dark = (i + j) % 2 == 0;
      auto v = [&](float u, float w, float shade) {
        float s = dark ? 0.55f : 0.95f;
        glColor4f(s * (0.95f - 0.1f * shade), s * (0.55f + 0.2f * shade), s * 0.25f, 1.0f);
        vertex(u, 0.1f + 0.32f * u - 0.12f * w, w);
      };
      float s0 = (w0 + 2.6f) / 5.2f, s1 = (w1 + 2.6f) / 5.2f;
      v(u0, w0, s0); v(u1, w0, s0); v(u1, w1, s1);
      v(u0, w0, s0); v(u1, w1, s1); v(u0, w1, s1);
    }
  }
  glEnd();
  glFinish();
}

}  // namespace pf
