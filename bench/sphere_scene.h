// pfspheres' scenes -- N lit spheres in a perspective frustum -- and what a renderer hands back
// for one of them: the time per frame, the lit colour and depth, and which sphere each pixel shows.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pfspheres {

struct Sphere {
  float center[3];  // object (world) coordinates, under SphereScene::modelview
  float radius;
  float color[3];   // the material's ambient and diffuse colour (GL_COLOR_MATERIAL)
};

// Everything both GLs and the exact reference draw with. The matrices and values are floats, as
// the GLs receive them; the reference reads the same floats in double.
struct SphereScene {
  int width = 1024, height = 1024;
  std::vector<Sphere> spheres;
  float projection[16];  // column-major (glLoadMatrixf): a glFrustum
  float modelview[16];   // column-major: a rotation and a translation (rigid, so spheres stay spheres)
  float light_direction[4] = {0.3f, 0.5f, 0.8f, 0.0f};  // GL_LIGHT0, directional, eye coordinates
  float specular[4] = {0.5f, 0.5f, 0.5f, 1.0f};          // material specular; GL_LIGHT0's is (1,1,1,1)
  float shininess = 32.0f;
  uint8_t clear_rgb[3] = {51, 51, 64};                   // the background, exact in 8 bits
};

// `count` spheres, placed by a fixed-seed RNG so that they overlap and intersect (radii shrink as
// count^(-1/3): together they fill about the same share of the frustum), all in front of the near
// plane; `size` x `size` pixels.
SphereScene makeSphereScene(int count, int size);

// What one renderer produced: times of the timed frames, then one lit frame's colour and depth and
// one ID frame (lighting off, sphere i drawn in the flat colour encoding i + 1) read back.
struct Rendering {
  std::vector<double> frame_ms;
  std::vector<uint8_t> rgb;    // lit frame, 3 bytes a pixel, row 0 at the bottom
  std::vector<float> depth;    // lit frame, window depth in [0, 1]
  std::vector<uint32_t> id;    // ID frame: 0 = background, i + 1 = sphere i
  std::string error;           // non-empty: the renderer failed
};

struct Timing {
  int warmup = 1, frames = 5;
};

// The sphere an ID frame's RGB pixel shows: 0 = none, i + 1 = sphere i (see sphere_frame.inc).
inline uint32_t idOfColor(const uint8_t* rgb) { return rgb[0] | (rgb[1] << 8) | (uint32_t(rgb[2]) << 16); }

// OSMesa (llvmpipe) drawing every sphere with gluSphere(quadric, r, slices, slices), GLU_SMOOTH
// normals, lit per vertex. LP_NUM_THREADS must be set before the first call.
Rendering renderWithGluSpheres(const SphereScene& s, int slices, const Timing& t);
// primflow drawing every sphere with its `sphere` primitive, one glBegin/glEnd, lit per pixel.
Rendering renderWithPrimflowSpheres(const SphereScene& s, int threads, const Timing& t);

}  // namespace pfspheres
