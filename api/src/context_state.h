// The state behind a PFcontext: the GL state machine of the spine subset, the registry of
// compiled primitives (built-in ones compiled from primitives/*.pfl at creation, exactly as a
// user's would be), immediate-mode sequence points, and the renderer.
#pragma once

#include <glm/glm.hpp>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <primflow/context.h>

#include "compiler/compiler.h"
#include "raster/renderer.h"

namespace pf {

// One glSequencePointEXT / glVertex: the current values bound together.
struct SequencePoint {
  glm::vec4 position;  // clip coordinates (point parameters are transformed when bound)
  glm::vec4 color;
};

// Registered primitives: by name, and by the enum glBegin takes.
struct PrimitiveRegistry {
  std::map<std::string, std::shared_ptr<const CompiledPrimitive>> by_name;
  std::map<GLenum, std::shared_ptr<const CompiledPrimitive>> by_mode;
  std::map<std::string, GLenum> mode_of;  // the glBegin mode of each name
  GLenum next_mode = 0x31800;             // GL_FIRST_PRIMITIVE_MODE_EXT
  // Compiled modules: their diagnostics (id - 1), and the last failed compilation's.
  std::vector<std::string> module_logs;
  std::string failed_log;
  // Replaced programs stay alive: instances already recorded point at them.
  std::vector<std::shared_ptr<const CompiledPrimitive>> replaced;

  // Registers a compiled primitive under its name: a new name gets the next mode, a known
  // name keeps its mode (a built-in GL mode, or an earlier one) and gets the new program.
  // `mode`: a GL mode of its own (GL_POINTS is 0, so "none" is kAnyMode).
  static constexpr GLenum kAnyMode = 0xffffffffu;
  void add(std::shared_ptr<const CompiledPrimitive> p, GLenum mode = kAnyMode);
};

}  // namespace pf

struct PFcontextRec {
  explicit PFcontextRec(int threads) : renderer(threads) {}

  // Framebuffer binding.
  GLenum format = GL_RGBA;
  int depth_bits = 0;
  uint8_t* color = nullptr;
  int width = 0, height = 0;
  std::vector<float> depth;
  bool ever_bound = false;
  unsigned iteration_cap = 65536;

  pf::PrimitiveRegistry primitives;
  pf::Renderer renderer;

  // GL state.
  GLenum error = GL_NO_ERROR;
  float clear_color[4] = {0, 0, 0, 0};
  float clear_depth = 1.0f;
  int viewport[4] = {0, 0, 0, 0};
  float depth_range[2] = {0.0f, 1.0f};
  bool depth_test = false;
  bool depth_write = true;
  GLenum depth_func = GL_LESS;
  GLenum matrix_mode = GL_MODELVIEW;
  glm::mat4 modelview{1.0f}, projection{1.0f};
  glm::vec4 current_color{1.0f, 1.0f, 1.0f, 1.0f};

  // Immediate mode.
  bool in_begin = false;
  const pf::CompiledPrimitive* begin_primitive = nullptr;
  std::vector<pf::SequencePoint> sequence_points;
  // Scratch for building instances (kept to avoid allocation per instance).
  std::vector<uint32_t> param_block;
  std::vector<float> vertex_channels;

  void setError(GLenum e) {
    if (error == GL_NO_ERROR) error = e;
  }
  // Runs all recorded drawing, then reports runaway primitives: GL_TOO_MANY_ITERATIONS_EXT and
  // a line on stderr.
  void finish();
  pf::RasterState rasterState() const;
};

namespace pf {
PFcontextRec* currentContext();
}
