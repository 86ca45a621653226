// The state behind a PFcontext: the GL state machine of the spine subset, the registry of
// compiled primitives (built-in ones compiled from primitives/*.pfl at creation, exactly as a
// user's would be), immediate-mode sequence points, and the renderer.
#pragma once

#include <glm/glm.hpp>
#include <map>
#include <memory>
#include <string>
#include <optional>
#include <vector>

#include <primflow/context.h>
#include <primflow/gl.h>

#include "api/src/display_lists.h"
#include "api/src/fog_clip.h"
#include "api/src/pixel_rectangles.h"
#include "api/src/raster_position.h"
#include "api/src/raster_modes.h"
#include "api/src/textures.h"
#include "api/src/vertex_lighting.h"
#include "raster/lighting.h"
#include "compiler/compiler.h"
#include "raster/renderer.h"

namespace pf {

// The current value of a named parameter (paper section 3.1): set by pfglRastParam*EXT, and
// by glVertex, glNormal and glTexCoord for the names "vertex", "normal" and "texcoord".
struct ParamValue {
  double v[16] = {};
  int count = 0;  // values given; 0: never set
};

// How the primitive of a glBegin takes one of its parameters: the current value it reads, and
// where the value goes in the snapshot each sequence point takes (its row).
struct FeedEntry {
  const ParamInfo* info;
  GLuint name;      // parameter name id
  int row_offset;   // floats from the start of a row
  int shared = -1;  // a parameter of shared interpolator `shared` (ChannelLayout::shared), or
                    // -1: of the primitive
};

// A GL matrix stack (GL 1.5 section 2.11.2): the top is the current matrix; its depth limit
// is what glGetIntegerv(GL_MAX_*_STACK_DEPTH) reports.
struct MatrixStack {
  explicit MatrixStack(size_t max_depth) : max_depth(max_depth) {}
  std::vector<glm::mat4> below;  // the pushed matrices
  glm::mat4 top{1.0f};
  size_t max_depth;
  size_t depth() const { return below.size() + 1; }
};

// One per-vertex shading parameter of the instances of a glBegin: 4 channels from `first`.
constexpr GLuint kEyePositionChannel = 0xfffffff0u;  // (x, y, z, 1) in eye coordinates
constexpr GLuint kEyeNormalChannel = 0xfffffff1u;    // the eye-space normal (x, y, z, 0)
constexpr GLuint kFogCoordChannel = 0xfffffff2u;     // fog: (|z| in eye coordinates, 0, 0, 0)

struct ShadingChannel {
  // Name id; the colour's: its front (`back` false) or back (`back` true) lit colour. Or one of
  // the two internal groups of per-pixel lit vertices (kEyePositionChannel, kEyeNormalChannel),
  // or the fog coordinate (kFogCoordChannel).
  GLuint param;
  bool back = false;
  InterpKind kind;
  int first;
  const CompiledPrimitive* shared = nullptr;  // the shared interpolator computing it, if any
};

// One client-side vertex array (glVertexPointer and its siblings).
struct ClientArray {
  bool enabled = false;
  GLint size = 4;
  GLenum type = GL_FLOAT;
  GLsizei stride = 0;
  const void* pointer = nullptr;
};

// The per-fragment operations' state (GL 1.5 section 4.1; fragment_commands.cpp): what
// rasterState() snapshots into raster/fragment_ops.h's FragmentOps for each draw.
struct FragmentState {
  bool scissor_test = false;
  int scissor[4] = {0, 0, 0, 0};  // x, y, width, height (the first drawable's size at first bind)
  bool alpha_test = false;
  GLenum alpha_func = GL_ALWAYS;
  float alpha_ref = 0.0f;         // clamped to [0, 1]
  bool blend = false;
  GLenum blend_src_rgb = GL_ONE, blend_dst_rgb = GL_ZERO, blend_src_alpha = GL_ONE, blend_dst_alpha = GL_ZERO;
  GLenum blend_equation = GL_FUNC_ADD;
  float blend_color[4] = {0, 0, 0, 0};  // clamped to [0, 1]
  bool logic_op = false;
  GLenum logic_mode = GL_COPY;
  bool dither = true;             // kept and read back; nothing is dithered (as in llvmpipe)
  bool stencil_test = false;
  GLenum stencil_func = GL_ALWAYS;
  GLint stencil_ref = 0;          // as given; clamped to [0, 255] where used and read back
  GLuint stencil_value_mask = 0xff, stencil_write_mask = 0xff;  // (Mesa's initial values)
  GLenum stencil_fail = GL_KEEP, stencil_depth_fail = GL_KEEP, stencil_depth_pass = GL_KEEP;
  GLint stencil_clear = 0;
};

// The snapshot of them a draw takes (fragment_commands.cpp); `has_stencil`: the framebuffer has
// a stencil buffer (without one the stencil test is off, as GL says).
FragmentOps fragmentOps(const FragmentState& f, bool has_stencil);

// glHint's targets (hintIndex gives a target's place; -1: not a target).
constexpr int kHintCount = 7;
int hintIndex(GLenum target);

// What glPushAttrib saves of the groups primflow has (GL 1.5 table 6.x's attribute column),
// restored by glPopAttrib for the groups in `mask`. The state of groups it lacks (pixel maps,
// evaluators, ...) is constant: nothing to save.
struct AttribState {
  GLbitfield mask;
  glm::vec4 current_color;                           // GL_CURRENT_BIT
  ParamValue normal, texcoord, edge_flag;
  bool depth_test, depth_write;                      // GL_DEPTH_BUFFER_BIT (and enables)
  GLenum depth_func;
  float clear_depth;
  bool cull;                                         // GL_POLYGON_BIT (and enables)
  GLenum cull_face, front_face;
  LightingState lighting;                            // GL_LIGHTING_BIT, GL_ENABLE_BIT, GL_TRANSFORM_BIT
  GLenum shade_model;
  GLenum matrix_mode;                                // GL_TRANSFORM_BIT
  int viewport[4];                                   // GL_VIEWPORT_BIT
  float depth_range[2];
  float clear_color[4];                              // GL_COLOR_BUFFER_BIT
  uint8_t color_mask;
  GLenum hints[kHintCount];                          // GL_HINT_BIT
  GLuint list_base;                                  // GL_LIST_BIT
  FragmentState fragment;                            // GL_SCISSOR_BIT, GL_COLOR_BUFFER_BIT, GL_ENABLE_BIT,
                                                     // GL_STENCIL_BUFFER_BIT
  TextureAttribs texture;                            // GL_TEXTURE_BIT (the enables: GL_ENABLE_BIT too)
  FogState fog;                                      // GL_FOG_BIT (the enable: GL_ENABLE_BIT too)
  ClipPlaneState clip;                               // GL_TRANSFORM_BIT (the enables: GL_ENABLE_BIT too)
  float accum_clear[4];                              // GL_ACCUM_BUFFER_BIT
  RasterPosState raster;                             // GL_CURRENT_BIT
  PixelModeState pixel_mode;                         // GL_PIXEL_MODE_BIT
  RasterModes raster_modes;  // GL_POINT_BIT, GL_LINE_BIT, GL_POLYGON_STIPPLE_BIT (raster_modes.h)
};

// glPixelStore's modes for one direction (GL 1.5 table 3.1): pack (glReadPixels writes by
// them) or unpack (kept and read back: nothing in primflow reads client images yet).
struct PixelStore {
  bool swap_bytes = false, lsb_first = false;
  int row_length = 0, skip_rows = 0, skip_pixels = 0, alignment = 4, image_height = 0, skip_images = 0;
};

// What glPushClientAttrib saves: the pixel store modes and the vertex arrays.
struct ClientAttribState {
  GLbitfield mask;
  PixelStore pack, unpack;
  ClientArray vertex_array, color_array, normal_array, texcoord_array, edge_flag_array;
};

// GL_MAX_ATTRIB_STACK_DEPTH and GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, Mesa's 16.
constexpr size_t kMaxAttribStackDepth = 16;

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

  // Shared interpolators: by id (GL_FIRST_INTERPOLATOR_EXT + index); a recompiled name keeps
  // its id and gets the new program (the old one stays alive in `replaced`).
  static constexpr size_t kMaxInterpolators = GL_FIRST_PRIMITIVE_MODE_EXT - GL_FIRST_INTERPOLATOR_EXT;
  std::map<std::string, GLuint> interpolator_ids;
  std::vector<std::shared_ptr<const CompiledPrimitive>> interpolators;
  void addInterpolator(std::shared_ptr<const CompiledPrimitive> p);
  const CompiledPrimitive* interpolator(GLenum id) const {
    return id >= GL_FIRST_INTERPOLATOR_EXT && id - GL_FIRST_INTERPOLATOR_EXT < interpolators.size()
               ? interpolators[id - GL_FIRST_INTERPOLATOR_EXT].get() : nullptr;
  }

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
  int stencil_bits = 0;  // 8 or 0
  uint8_t* color = nullptr;
  int width = 0, height = 0;
  std::vector<float> depth;
  std::vector<uint8_t> stencil;  // cleared to 0 by every pfMakeCurrent
  // The accumulation buffer (accumulation.cpp): 16 signed bits per channel, RGBA per pixel, as
  // Mesa's; allocated by pfMakeCurrent (cleared to 0) when accum_bits is 16, else empty.
  int accum_bits = 0;  // 16 or 0
  std::vector<int16_t> accum;
  float accum_clear[4] = {0, 0, 0, 0};  // glClearAccum's, clamped to [-1, 1]
  bool ever_bound = false;
  unsigned iteration_cap = 65536;
  // Called by glFinish / glFlush after the drawing has executed, if any drawing has since the
  // last call (api/src/frame_hook.h).
  void (*frame_hook)(void* user) = nullptr;
  void* frame_hook_user = nullptr;
  bool frame_changed = false;

  pf::PrimitiveRegistry primitives;
  // Fields for implicit surfaces (pfglCompileFieldEXT): by id - 1, with each compilation's log;
  // the last failed compilation's log is field_failed_log.
  pf::field::FieldTable fields;
  std::vector<std::string> field_logs;
  std::string field_failed_log;
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
  bool cull = false;
  GLenum cull_face = GL_BACK;
  GLenum front_face = GL_CCW;
  GLenum shade_model = GL_SMOOTH;
  uint8_t color_mask = 0xf;  // bit k: RGBA channel k written
  pf::FragmentState fragment;
  pf::PixelStore pack, unpack;
  GLenum matrix_mode = GL_MODELVIEW;
  pf::MatrixStack modelview{32}, projection{4}, texture{4};
  glm::vec4 current_color{1.0f, 1.0f, 1.0f, 1.0f};

  pf::ClientArray vertex_array, color_array, normal_array, texcoord_array;
  pf::ClientArray edge_flag_array{false, 1, GL_UNSIGNED_BYTE, 0, nullptr};  // glEdgeFlagPointer's GLbooleans
  pf::LightingState lighting;
  pf::TextureState textures;
  pf::FogState fog;
  pf::ClipPlaneState clip;
  pf::RasterPosState raster;
  pf::PixelModeState pixel_mode;
  pf::PixelMaps pixel_maps;  // glPixelMap's tables (pixel_maps.h): fixed, 10 KiB
  pf::RasterModes raster_modes;
  pf::DisplayLists lists;
  GLenum hints[pf::kHintCount] = {GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE,
                                  GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE};
  std::vector<pf::AttribState> attrib_stack;
  std::vector<pf::ClientAttribState> client_attrib_stack;

  // Named parameters: ids (GL_FIRST_PARAM_NAME_EXT + index) by name, and their current values.
  // "color" is GL's current colour: glColor and pfglRastParam*EXT on "color" set both
  // current_color and its value.
  static constexpr GLuint kParamNameBase = GL_FIRST_PARAM_NAME_EXT;
  std::map<std::string, GLuint> param_ids;
  std::vector<std::string> param_names;
  std::vector<pf::ParamValue> current_params;
  GLuint vertex_param = 0, normal_param = 0, texcoord_param = 0, color_param = 0;
  // glEdgeFlag's current flag (GL 1.5 section 2.6.2), "edge_flag": the GLboolean as given (as
  // Mesa keeps it), initially 1.
  GLuint edge_flag_param = 0;
  // Interns the name. Ids end at 0x3FFFF, primflow's range (docs/api.md): past 32,768 names the
  // table is full and it throws std::bad_alloc (GL_OUT_OF_MEMORY where a command catches it).
  static constexpr size_t kMaxParamNames = 0x40000 - GL_FIRST_PARAM_NAME_EXT;
  GLuint paramId(const std::string& name);
  // Sets a parameter's current value (`count` values; "color" also sets current_color).
  void setParamValue(GLuint id, int count, const double* v);
  bool isParam(GLuint id) const { return id >= kParamNameBase && id - kParamNameBase < current_params.size(); }
  pf::ParamValue& param(GLuint id) { return current_params[id - kParamNameBase]; }
  const pf::ParamValue& param(GLuint id) const { return current_params[id - kParamNameBase]; }

  // How each glBegin mode interpolates shading parameters (pfglMaterialInterpEXT): by mode,
  // the parameter and its interpolator (GL_PERSPECTIVE_LINEAR_INTERPOLATOR_EXT,
  // GL_LINEAR_INTERPOLATOR_EXT or a shared interpolator's id). "color" is perspective-linear
  // unless bound otherwise.
  std::map<GLenum, std::vector<std::pair<GLuint, GLenum>>> shading_bindings;
  std::vector<std::pair<GLuint, GLenum>> planned_bindings;  // scratch of the glBegin in progress

  // Immediate mode: between glBegin and glEnd, each sequence point appends a row with the
  // values of the primitive's parameters (points already in clip coordinates) and the colour.
  bool in_begin = false;
  GLenum begin_mode = 0;
  const pf::CompiledPrimitive* begin_primitive = nullptr;
  std::vector<pf::FeedEntry> feed;
  int row_floats = 0;
  glm::mat4 begin_mvp{1.0f};  // matrices cannot change inside glBegin / glEnd
  // Per-vertex lighting (a primitive with a `vertex` parameter, GL_LIGHTING on): the
  // modelview, the normal matrix (rescaled as GL_RESCALE_NORMAL asks), and the channels of a
  // row's colour: 4, or 8 with two-sided lighting (front, then back).
  bool begin_lit = false;
  // The lights' equation for begin_lit (lights cannot change inside glBegin / glEnd; the
  // material can, and is read per row).
  std::optional<pf::LightingEquation> begin_equation;
  // begin_lit's vertices waiting to be lit together (vertex_lighting.h): lit when the batch
  // fills and at glEnd, into their rows' colour channels.
  pf::VertexLightingBatch vertex_lighting;
  // Fog measured per pixel from the surface point P a primitive commits (it sets N): its P
  // goes to the G-buffer even unlit, and no fog coordinate channel is planned.
  bool begin_fog_surface = false;
  bool begin_lit_per_pixel = false;  // GL lighting per pixel in the shading pass: a primitive
                                     // that sets N, or vertices under GL_PER_PIXEL_LIGHTING_EXT
  // GL_PER_PIXEL_LIGHTING_EXT on a vertex primitive: each row carries its eye-space position
  // and normal (two channel groups, interpolated perspective-correct) for the shading pass.
  bool begin_vertices_per_pixel = false;
  glm::mat4 begin_modelview{1.0f};
  glm::mat3 begin_normal_matrix{1.0f};
  int row_channels = 4;
  // The shading parameters of the glBegin's instances: where each goes in a row's channels.
  std::vector<pf::ShadingChannel> shading;
  pf::ChannelLayout begin_layout;
  int color_channel = -1, back_color_channel = -1;  // first channel of the colour(s); -1: none
  // Texturing (textures.h): the snapshot the glBegin's instances sample (null: untextured), and
  // the first channel of their texture coordinates.
  std::shared_ptr<const pf::TextureUnit> begin_texture;
  int texcoord_channel = -1;
  // Fog (fog_clip.h): the first channel of the fog coordinate (-1: no fog), and the parameter
  // whose eye-space z it is (the primitive's "vertex", else its first point parameter; 0: none,
  // the coordinate 0).
  int fog_channel = -1;
  GLuint fog_position_param = 0;
  // A pixel rectangle being drawn (pixel_rectangles.h): its sequence points' colour, texture
  // and fog coordinates come from here; null otherwise.
  const pf::PixelFragment* pixel_fragment = nullptr;
  size_t rows_count = 0;
  std::vector<uint32_t> rows;
  std::vector<float> row_shading;  // row_channels floats per sequence point
  std::string reject_reason;  // non-empty: the sequence points do not fit the primitive
  bool begin_out_of_memory = false;  // a failed allocation dropped the glBegin in progress
  // Scratch for building instances (kept to avoid allocation per instance).
  std::vector<uint32_t> param_block;
  std::vector<float> vertex_channels;
  std::vector<std::vector<uint32_t>> shared_blocks;  // the shared interpolators' parameters
  std::vector<const uint32_t*> shared_block_ptrs;

  void setError(GLenum e) {
    if (error == GL_NO_ERROR) error = e;
  }
  pf::MatrixStack& matrixStack() {
    return matrix_mode == GL_PROJECTION ? projection : matrix_mode == GL_TEXTURE ? texture : modelview;
  }
  // Runs all recorded drawing; a failed allocation while drawing: GL_OUT_OF_MEMORY, the frame
  // dropped.
  void flush();
  // flush(), then reports runaway primitives: GL_TOO_MANY_ITERATIONS_EXT and a line on stderr.
  void finish();
  // A failed allocation (std::bad_alloc) in a command: GL_OUT_OF_MEMORY and a line on stderr;
  // what the command was building is dropped whole -- the glBegin in progress (`in_begin`), or
  // everything recorded since the last flush -- so the context goes on in a consistent state
  // (GL 1.5 section 2.5 leaves the state undefined; primflow keeps it usable).
  void outOfMemory(const char* command);
  pf::RasterState rasterState() const;
};

namespace pf {
PFcontextRec* currentContext();
// glGetShaderInfoLog's contract for a compile log: at most bufSize - 1 characters and a NUL into
// `out`, the count into *length; no log (null) or a negative size: GL_INVALID_VALUE.
void copyInfoLog(PFcontextRec& ctx, const std::string* text, GLsizei bufSize, GLsizei* length, GLchar* out);
// The current context, or null if there is none or (GL_INVALID_OPERATION set) it is between
// glBegin and glEnd, where GL allows only the vertex-attribute commands.
PFcontextRec* contextOutsideBegin();
// glClear's GL_ACCUM_BUFFER_BIT (accumulation.cpp): the accumulation buffer, if there is one, set
// to glClearAccum's value within the scissor box.
void clearAccumBuffer(PFcontextRec& ctx);
// The same check on a context: false, with GL_INVALID_OPERATION set, between glBegin and glEnd.
inline bool outsideBegin(PFcontextRec& ctx) {
  if (!ctx.in_begin) return true;
  ctx.setError(GL_INVALID_OPERATION);
  return false;
}
}
