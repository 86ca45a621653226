// Benchmark scenes: geometry generated deterministically (a fixed seed), shared by both sides.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pfbench {

struct SceneData {
  std::string name;
  int width = 1024, height = 1024;
  std::vector<float> vertices;  // x, y, z per vertex, window coordinates (glOrtho onto pixels)
  std::vector<float> colors;    // r, g, b per vertex
  std::vector<float> normals;   // x, y, z per vertex; empty: unlit
  std::vector<float> texcoords; // s, t per vertex; empty: untextured
  float alpha = 1.0f;           // every vertex's alpha; below 1: blended (GL_SRC_ALPHA, 1 - GL_SRC_ALPHA)
  int texture_size = 0;         // textured: a texture_size^2 RGB image, texels below
  std::vector<unsigned char> texels;
};

// "small": 200k small Gouraud triangles (about 3 pixels across), depth-tested.
// "large": 2k large overlapping triangles (fill rate), depth-tested.
// "fill":  64 triangles covering the frame 32 times (the per-pixel cost of the triangle program).
// "lit":   "small" with one directional light, lit per vertex (GL_COLOR_MATERIAL: the colours
//          are the material).
// "textured": "large"'s triangles with texture coordinates, a 256x256 RGB texture, bilinear
//          (GL_LINEAR both ways, no mipmaps), GL_REPEAT, GL_MODULATE; each frame uploads the
//          image (glTexImage2D) and draws.
// "blended": "large"'s triangles at alpha 0.5, blended over each other in submission order
//          (glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)), depth test off.
SceneData makeScene(const std::string& name);

// Renders `frames` frames after `warmup` ones; returns each frame's milliseconds. `image`, if
// given, receives the last frame (RGBA, row 0 at the bottom, read back with glReadPixels).
std::vector<double> timeOsmesa(const SceneData& s, int warmup, int frames, std::vector<unsigned char>* image = nullptr);
// The work primflow counted for one frame.
struct FrameWork {
  uint64_t pixels_run = 0;          // pixel-program runs (lanes started)
  uint64_t pixels_shaded = 0;
  uint64_t setup_instructions = 0;  // executed by setup programs
  uint64_t pixel_instructions = 0;  // executed by interpreted pixel programs, once per 8x8 block
  uint64_t blocks_run = 0, blocks_native = 0, blocks_rejected = 0, blocks_accepted = 0, blocks_packed = 0;
};

std::vector<double> timePrimflow(const SceneData& s, int warmup, int frames, int threads, FrameWork* work,
                                 std::vector<unsigned char>* image = nullptr);

}  // namespace pfbench
