// The differential tests' scenes, rendered by two GL implementations from one GL-1.x source
// (fan_scene.inc): OSMesa, the reference (osmesa_render.cpp), and primflow through
// <primflow/gl_mangle.h> (primflow_render.cpp).
#pragma once

#include <cstdint>
#include <vector>

namespace pfdiff {

enum class Scene : int {
  FanIds,            // 64 triangles around a pixel centre, each in its own ID colour
  MeshIds,           // a jittered grid of 288 triangles sharing edges, each in its own ID colour
  FanGouraud,        // the fan with a different colour at every vertex
  DepthFarThenNear,  // three overlapping triangles at different depths, drawn far to near
  DepthNearThenFar,  // the same, drawn near to far
  Showcase,          // pfrender's showcase (tools/showcase_scene.inc): perspective, depth, Gouraud
  // The depth scene far to near with depth cleared to 0.5 and each glDepthFunc:
  DepthNever, DepthLess, DepthEqual, DepthLequal, DepthGreater, DepthNotequal, DepthGequal, DepthAlways,
  DepthMaskOff,      // the far triangle with depth writes on, the others with glDepthMask(GL_FALSE)
  DepthRangeNarrow,  // glDepthRange(0.2, 0.6), far to near
  // The other glBegin modes, each vertex its own colour (the colours are no affine function of
  // position, so they show how each mode splits its polygons into triangles):
  StripGouraud,      // GL_TRIANGLE_STRIP: a zig-zag band, both windings
  FanModeGouraud,    // GL_TRIANGLE_FAN: the fan of FanGouraud in one glBegin
  QuadsGouraud,      // GL_QUADS: a row of quadrilaterals of different shapes
  QuadStripGouraud,  // GL_QUAD_STRIP: a curved band
  PolygonGouraud,    // GL_POLYGON: a convex heptagon and a triangle-shaped pentagon
  QuadMeshIds,       // the jittered grid of MeshIds as 144 GL_QUADS, each in its own ID colour
  PointsGouraud,     // GL_POINTS on a grid of quarter-pixel offsets (integers and halves included)
  LinesStar,         // GL_LINES in 48 directions from a centre and short ones at every offset
  LineStripGouraud,  // GL_LINE_STRIP: a spiral
  LineLoopGouraud,   // GL_LINE_LOOP: a star polygon, closed
  // Polygon and framebuffer state:
  CullBack,          // the ID fan (odd triangles clockwise) with back faces culled
  CullFrontCw,       // glFrontFace(GL_CW), glCullFace(GL_FRONT)
  CullBoth,          // GL_FRONT_AND_BACK: nothing but the clear colour
  FlatModes,         // glShadeModel(GL_FLAT) with every polygon and line mode: provoking vertices
  ColorMasks,        // glColorMask on clears and on drawing
  MatrixOps,         // perspective, push / pop, translate, rotate, scale, load and mult matrix
  NearClipCull,      // perspective triangles crossing the near plane, culled by orientation
  VertexArrays,      // the ID mesh through glDrawElements, a strip through glDrawArrays
  // GL lighting on tessellated spheres and an open cylinder (seen inside), one feature each:
  LitDirectional,    // a directional light, specular material
  LitPointLights,    // two positional lights with constant / linear / quadratic attenuation
  LitSpot,           // a spot light: exponent and cutoff
  LitTwoSide,        // two-sided lighting, a back material, the inside of a cylinder
  LitLocalViewer,    // specular with a local viewer
  LitNormalize,      // a scaled modelview with GL_NORMALIZE, and with GL_RESCALE_NORMAL
  LitColorMaterial,  // GL_COLOR_MATERIAL tracking per-vertex glColor, emission, global ambient
};

constexpr int kSize = 256;  // the scenes are drawn at 256 x 256, glOrtho(0, 256, 0, 256, -1, 1)

// The clear colour of every scene, as bytes.
constexpr uint8_t kClear[4] = {16, 32, 48, 255};

// Number of triangles of the ID scenes, and the ID colour of triangle `id`:
// R = (id + 1) & 255, G = (id + 1) >> 8, B = (id * 37) & 255 (for the eye only), A = 255.
constexpr int kFanTriangles = 64;
constexpr int kMeshTriangles = 288;
constexpr int kMeshQuads = 144;
constexpr int kNoId = -1;

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;   // row 0 at the bottom
  std::vector<double> depth;   // window depth in [0, 1], row 0 at the bottom; empty if unread
  bool ok = false;             // false: the context could not be made
};

Image renderOsmesa(Scene scene, int width, int height);
Image renderPrimflow(Scene scene, int width, int height, int threads);

}  // namespace pfdiff

// The fan of ID colours, as pixels (RGBA, row 0 at the bottom).
std::vector<uint8_t> renderFanOsmesa(int w, int h);
std::vector<uint8_t> renderFanPrimflow(int w, int h, int threads);
