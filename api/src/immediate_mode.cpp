// glBegin / glEnd and what goes between them: the paper's sequence points (section 3.1).
//
// Every parameter has a current value, set by pfglRastParam*EXT (and by glVertex, glNormal,
// glTexCoord for "vertex", "normal", "texcoord"); the current colour is the per-vertex shading
// parameter. pfglSequencePointEXT binds the current values of the parameters the glBegin's
// primitive declares into a row, as glVertex does after setting "vertex". glEnd makes instances
// of the rows: per-sequence-point parameters from each row, per-primitive ones from the first
// row of their instance. Nothing here knows what a triangle is: the primitive's declaration
// says how many sequence points an instance takes and which parameters it wants.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <new>

#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/context_state.h"
#include "api/src/shading_channels.h"
#include "raster/limits.h"

using pf::currentContext;

namespace {

// How a glBegin's parameters are transformed (seed 003 section 2.1: a primitive only declares
// which values are points, vectors and normals; the system transforms them).
struct ParamTransforms {
  const glm::mat4& point;   // to clip coordinates (a shared interpolator's: to eye coordinates)
  const glm::mat4& modelview;
  const glm::mat3& normal;  // the inverse transpose of the modelview's 3x3, rescaled as GL asks
  bool normalize;           // GL_NORMALIZE
};

// Converts the current value `v` to parameter `p`'s type (one sequence point's element):
// false, with `why`, if it does not fit. Points take 2 to 4 values (z = 0, w = 1 by default)
// and are transformed to clip coordinates, as glVertex's; vectors go to eye coordinates by the
// modelview's upper 3x3 and normals by its inverse transpose, normalised under GL_NORMALIZE, as
// glNormal's are for lighting; colours take 3 or 4 values (alpha 1).
bool convertValue(const pf::ParamInfo& p, const pf::ParamValue& v, const ParamTransforms& transform, uint32_t* out,
                  std::string& why) {
  using pf::BaseType;
  const int want = p.components;
  const bool element_is_base = p.type.dims.size() <= (p.per_sequence_point ? 1u : 0u);
  auto bad = [&](const std::string& expected) {
    why = "parameter '" + p.name + "' (" + pf::typeName(p.type) + ") needs " + expected + ", its current value has " +
          std::to_string(v.count) + (v.count == 1 ? " value" : " values");
    return false;
  };
  if (v.count == 0) {
    why = "parameter '" + p.name + "' has no value (set it with pfglRastParam*EXT before the sequence point)";
    return false;
  }
  if (element_is_base && p.type.base == BaseType::Point) {
    if (v.count < 2 || v.count > 4) return bad("2 to 4 values");
    glm::vec4 q(static_cast<float>(v.v[0]), static_cast<float>(v.v[1]), v.count > 2 ? static_cast<float>(v.v[2]) : 0.0f,
                v.count > 3 ? static_cast<float>(v.v[3]) : 1.0f);
    q = transform.point * q;
    for (int c = 0; c < 4; ++c) out[c] = std::bit_cast<uint32_t>(q[c]);
    return true;
  }
  if (element_is_base && (p.type.base == BaseType::Vector || p.type.base == BaseType::Normal)) {
    if (v.count != 3) return bad("3 values");
    glm::vec3 d(static_cast<float>(v.v[0]), static_cast<float>(v.v[1]), static_cast<float>(v.v[2]));
    if (p.type.base == BaseType::Vector) {
      d = glm::mat3(transform.modelview) * d;
    } else {
      d = transform.normal * d;
      if (transform.normalize && glm::length(d) > 0.0f) d = glm::normalize(d);
    }
    for (int c = 0; c < 3; ++c) out[c] = std::bit_cast<uint32_t>(d[c]);
    return true;
  }
  if (element_is_base && p.type.base == BaseType::Color) {
    if (v.count < 3 || v.count > 4) return bad("3 or 4 values");
    for (int c = 0; c < 4; ++c) out[c] = std::bit_cast<uint32_t>(c < v.count ? static_cast<float>(v.v[c]) : 1.0f);
    return true;
  }
  if (v.count != want) return bad(std::to_string(want) + (want == 1 ? " value" : " values"));
  for (int c = 0; c < want; ++c) {
    if (p.type.base == BaseType::Int) {
      double r = std::nearbyint(v.v[c]);
      if (!(std::fabs(r) < 2147483648.0)) return bad("int values in range");
      out[c] = static_cast<uint32_t>(static_cast<int32_t>(r));
    } else if (p.type.base == BaseType::Bool) {
      out[c] = v.v[c] != 0.0 ? 1u : 0u;
    } else {
      out[c] = std::bit_cast<uint32_t>(static_cast<float>(v.v[c]));
    }
  }
  return true;
}

// The parameters glBegin's primitive wants, except the count of a parameter-sized one (the
// API supplies it), then those of the shared interpolators its shading channels use.
void planFeed(PFcontextRec& ctx, const pf::CompiledPrimitive& prim) {
  ctx.feed.clear();
  ctx.row_floats = 0;
  for (const pf::ParamInfo& p : prim.params) {
    if (prim.sequence_points == 0 && !p.per_sequence_point && p.offset == prim.count_slot) continue;
    ctx.feed.push_back({&p, ctx.paramId(p.name), ctx.row_floats});
    ctx.row_floats += p.components;
  }
  const auto& shared = ctx.begin_layout.shared;
  for (size_t k = 0; k < shared.size(); ++k)
    for (const pf::ParamInfo& p : shared[k].program->params) {
      ctx.feed.push_back({&p, ctx.paramId(p.name), ctx.row_floats, static_cast<int>(k)});
      ctx.row_floats += p.components;
    }
}

// Binds the current values as one sequence point of the open glBegin.
void recordSequencePoint(PFcontextRec& ctx);

// One sequence point of the glBegin in progress, recorded as a row (a failed allocation drops
// the glBegin: GL_OUT_OF_MEMORY).
void bindSequencePoint(PFcontextRec& ctx) {
  if (ctx.begin_out_of_memory) return;  // this glBegin was dropped: nothing more to record
  try {
    recordSequencePoint(ctx);
  } catch (const std::bad_alloc&) {
    ctx.outOfMemory("a sequence point");
  }
}

void recordSequencePoint(PFcontextRec& ctx) {
  const size_t row = ctx.rows_count++;
  ctx.rows.resize(ctx.rows_count * static_cast<size_t>(ctx.row_floats));
  uint32_t* out = ctx.rows.data() + row * static_cast<size_t>(ctx.row_floats);
  for (const pf::FeedEntry& f : ctx.feed) {
    std::string why;
    // A primitive's points go to clip coordinates; a shared interpolator's to eye coordinates,
    // the space of the P it reads.
    const ParamTransforms to{f.shared >= 0 ? ctx.begin_modelview : ctx.begin_mvp, ctx.begin_modelview,
                             ctx.begin_normal_matrix, ctx.lighting.normalize};
    if (!convertValue(*f.info, ctx.param(f.name), to, out + f.row_offset, why) &&
        ctx.reject_reason.empty())
      ctx.reject_reason = "sequence point " + std::to_string(row) + ": " + why;
  }
  pf::rowChannels(ctx);
}

// Instances handed to the renderer together (a multiple of its setup batch): enough batches
// for the renderer to set them up across its threads, each hand-over waking the pool once
// (at 1,024 instances a chunk, the wake-ups of 200k triangles cost more than two threads saved).
constexpr size_t kInstancesPerChunk = 1024 * pf::kSetupBatchLanes;

// Hands the rows to the renderer: for a primitive with a fixed count, one instance per
// `sequence_points` rows; for one with parameter-sized arrays, one instance holding them all.
void submitInstances(PFcontextRec& ctx) {
  // Textured or fogged and flat: colours flattened here, texture and fog coordinates interpolated
  // (flat_texturing.cpp).
  const bool flattened = ctx.shade_model == GL_FLAT && pf::flattenForTexturing(ctx);
  const pf::CompiledPrimitive& prim = *ctx.begin_primitive;
  const size_t total = ctx.rows_count;
  const bool sized = prim.sequence_points == 0;
  const size_t per = sized ? total : static_cast<size_t>(prim.sequence_points);
  if (per == 0) return;
  const int count = static_cast<int>(per);
  // The shading channels planned at glBegin; the colour in them, or (no per-vertex parameters)
  // the current colour for the whole instance.
  const int nch = ctx.row_channels;
  const pf::ChannelLayout& layout = ctx.begin_layout;
  pf::ShadeState shade;
  if (prim.has_interp_data) {
    shade.color_slot = ctx.color_channel;
    shade.back_color_slot = ctx.back_color_channel;
    if (ctx.begin_texture) {
      shade.texture = ctx.begin_texture;
      shade.texcoord_slot = layout.gbuffer_slot[static_cast<size_t>(ctx.texcoord_channel)];
    }
    if (ctx.fog_channel >= 0) {
      shade.fog_slot = layout.gbuffer_slot[static_cast<size_t>(ctx.fog_channel)];
      shade.fog = pf::fogParams(ctx.fog);
    } else if (ctx.begin_fog_surface) {
      shade.fog_slot = layout.surface_slot + 2;  // P.z
      shade.fog = pf::fogParams(ctx.fog);
    }
  } else {
    for (int k = 0; k < 4; ++k) shade.constant_color[k] = ctx.current_color[k];
  }
  pf::RasterState state = ctx.rasterState();
  if (flattened) state.flat_shading = false;
  // Instances go to the renderer a chunk at a time (sized primitives: the one instance), so
  // that it can run their setup across instances; it keeps their order.
  const size_t instances = total / per;
  // (Buffers for the instances there are, up to a chunk: a glBegin of one triangle does not
  // clear a thousand instances' worth.)
  const size_t chunk = sized ? 1 : std::min(kInstancesPerChunk, std::max<size_t>(instances, 1));
  const size_t pwords = static_cast<size_t>(prim.paramFloats(count));
  const size_t vfloats = per * static_cast<size_t>(layout.count);
  ctx.param_block.assign(chunk * pwords, 0u);
  if (sized) ctx.param_block[static_cast<size_t>(prim.count_slot)] = static_cast<uint32_t>(count);
  ctx.vertex_channels.assign(chunk * vfloats, 0.0f);
  const size_t stride = static_cast<size_t>(ctx.row_floats);
  const size_t nshared = layout.shared.size();
  ctx.shared_blocks.resize(chunk * nshared);
  ctx.shared_block_ptrs.resize(chunk * nshared);
  for (size_t k = 0; k < chunk * nshared; ++k) {
    ctx.shared_blocks[k].assign(static_cast<size_t>(layout.shared[k % nshared].program->param_floats), 0u);
    ctx.shared_block_ptrs[k] = ctx.shared_blocks[k].data();
  }
  for (size_t chunk_first = 0; chunk_first < instances; chunk_first += chunk) {
    const size_t in_chunk = std::min(chunk, instances - chunk_first);
    for (size_t j = 0; j < in_chunk; ++j) {
      const size_t first = (chunk_first + j) * per;
      uint32_t* params = ctx.param_block.data() + j * pwords;
      for (const pf::FeedEntry& f : ctx.feed) {
        const pf::ParamInfo& p = *f.info;
        if (f.shared >= 0) {  // a shared interpolator's: per primitive
          const uint32_t* v = ctx.rows.data() + first * stride + f.row_offset;
          std::copy(v, v + p.components,
                    ctx.shared_blocks[j * nshared + static_cast<size_t>(f.shared)].begin() + p.offset);
          continue;
        }
        if (!p.per_sequence_point) {
          const uint32_t* v = ctx.rows.data() + first * stride + f.row_offset;
          std::copy(v, v + p.components, params + p.offset);
          continue;
        }
        for (size_t i = 0; i < per; ++i) {
          const uint32_t* v = ctx.rows.data() + (first + i) * stride + f.row_offset;
          std::copy(v, v + p.components, params + prim.paramOffset(p, count, static_cast<int>(i)));
        }
      }
      float* channels = ctx.vertex_channels.data() + j * vfloats;
      for (size_t i = 0; i < per; ++i)
        for (int c = 0; c < layout.count; ++c) channels[i * layout.count + c] = ctx.row_shading[(first + i) * nch + c];
    }
    ctx.renderer.submitInstances(prim, static_cast<int>(in_chunk), ctx.param_block.data(), pwords,
                                 ctx.vertex_channels.data(), vfloats, layout, state, shade, count,
                                 nshared ? ctx.shared_block_ptrs.data() : nullptr,
                                 ctx.begin_lit_per_pixel ? &ctx.lighting : nullptr);
  }
}

// The GL modes keep GL's rule for a trailing incomplete group (dropped); a primitive of the
// extension takes exactly whole instances or nothing.
bool isGlMode(GLenum mode) { return mode <= GL_POLYGON; }

void setParam(PFcontextRec& ctx, GLuint name, int count, const double* v) {
  if (!ctx.isParam(name)) {
    ctx.setError(GL_INVALID_VALUE);
    return;
  }
  ctx.setParamValue(name, count, v);
}

// The vector forms of pfglRastParam*EXT: 1 to 16 values (count 0: a NULL pointer).
template <class T, int N>
void setParamVector(PFcontextRec& ctx, GLuint name, const pf::Values<T, N>& v) {
  if (v.count < 1 || v.count > 16) {
    ctx.setError(GL_INVALID_VALUE);
    return;
  }
  double d[16];
  for (int i = 0; i < v.count; ++i) d[i] = v.v[i];
  setParam(ctx, name, v.count, d);
}

void setVertex(PFcontextRec& ctx, double x, double y, double z, double w, int count) {
  if (!ctx.in_begin) return;  // outside Begin/End a vertex has no effect (GL: undefined)
  const double v[4] = {x, y, z, w};
  pf::ParamValue& p = ctx.param(ctx.vertex_param);
  p.count = count;
  for (int i = 0; i < 4; ++i) p.v[i] = v[i];
  bindSequencePoint(ctx);
}

}  // namespace

void PFcontextRec::setParamValue(GLuint id, int count, const double* v) {
  pf::ParamValue& p = param(id);
  p.count = count;
  for (int i = 0; i < count; ++i) p.v[i] = v[i];
  if (id == color_param) {  // GL's current colour, missing components (0, 0, 0, 1)
    for (int k = 0; k < 4; ++k) current_color[k] = k < count ? static_cast<float>(v[k]) : (k == 3 ? 1.0f : 0.0f);
    lighting.trackColor(current_color);
  }
}

GLuint PFcontextRec::paramId(const std::string& name) {
  auto it = param_ids.find(name);
  if (it != param_ids.end()) return it->second;
  if (param_names.size() >= kMaxParamNames) throw std::bad_alloc();
  param_names.push_back(name);
  current_params.emplace_back();
  GLuint id = kParamNameBase + static_cast<GLuint>(param_names.size()) - 1;
  param_ids[name] = id;
  return id;
}

// glBegin's planning, once the mode is known: transforms, lighting, the rows' layout.
static void startBegin(PFcontextRec& context, GLenum mode, const pf::CompiledPrimitive* primitive) {
  PFcontextRec* ctx = &context;
  ctx->begin_mode = mode;
  ctx->begin_primitive = primitive;
  ctx->begin_mvp = ctx->projection.top * ctx->modelview.top;
  // GL lights vertices: a primitive with a `vertex` parameter is lit per sequence point -- or,
  // under GL_PER_PIXEL_LIGHTING_EXT, per pixel from its interpolated position and normal.
  const bool vertices = ctx->lighting.enabled && ctx->begin_primitive->findParam("vertex") != nullptr;
  ctx->begin_vertices_per_pixel = vertices && ctx->lighting.per_pixel_vertices;
  ctx->begin_lit = vertices && !ctx->begin_vertices_per_pixel;
  if (ctx->begin_lit) ctx->begin_equation.emplace(ctx->lighting);
  ctx->begin_modelview = ctx->modelview.top;
  {
    // Normals -- glNormal's for lighting and every `normal` parameter -- go by the inverse
    // transpose of the modelview's upper 3x3; GL_RESCALE_NORMAL divides by the length of the
    // inverse's third row (GL 1.5 section 2.11.3).
    glm::mat3 inverse = glm::inverse(glm::mat3(ctx->modelview.top));
    ctx->begin_normal_matrix = glm::transpose(inverse);
    if (ctx->lighting.rescale_normal && !ctx->lighting.normalize) {
      float len = std::sqrt(inverse[0][2] * inverse[0][2] + inverse[1][2] * inverse[1][2] + inverse[2][2] * inverse[2][2]);
      if (len > 0.0f) ctx->begin_normal_matrix /= len;
    }
  }
  // Texturing: the bound texture's snapshot when it is enabled and complete, for primitives
  // that carry shading parameters (the others have no texture coordinates to sample by).
  ctx->begin_texture = ctx->begin_primitive->has_interp_data ? ctx->textures.current() : nullptr;
  pf::planShading(*ctx, mode, *ctx->begin_primitive);
  // A primitive that sets its normal and has no vertices to light is lit per pixel: its P and N
  // follow its channels in the G-buffer.
  ctx->begin_lit_per_pixel = ctx->lighting.enabled && !ctx->begin_lit && ctx->begin_primitive->writes_normal;
  if (ctx->begin_lit_per_pixel) {
    ctx->begin_layout.surface_slot = ctx->row_channels;
    ctx->begin_layout.surface_eye = pf::lightReadsEye(ctx->lighting);
  }
  // Fog on a primitive that commits its surface point: measured from each pixel's P (fog.h), which
  // the G-buffer then carries whether or not lighting reads it.
  ctx->begin_fog_surface = ctx->fog.enabled && ctx->begin_primitive->writes_normal &&
                           ctx->begin_primitive->has_interp_data && !ctx->begin_layout.surface_interpolated;
  if (ctx->begin_fog_surface) {
    ctx->begin_layout.surface_slot = ctx->row_channels;
    ctx->begin_layout.surface_eye = true;
  }
  // (Vertices lit per pixel have their surface slots already, among their channels.)
  if (ctx->begin_vertices_per_pixel && ctx->begin_layout.surface_interpolated) ctx->begin_lit_per_pixel = true;
  planFeed(*ctx, *ctx->begin_primitive);
  ctx->rows_count = 0;
  ctx->rows.clear();
  ctx->row_shading.clear();
  ctx->vertex_lighting.clear();
  ctx->reject_reason.clear();
  if (ctx->row_channels > pf::kMaxChannels)
    ctx->reject_reason = std::to_string(ctx->row_channels / 4) + " shading parameters bound to this mode need " +
                         std::to_string(ctx->row_channels) + " channels; at most " + std::to_string(pf::kMaxChannels) +
                         " fit";
}

namespace pf::cmd {

void begin(PFcontextRec& ctx, GLenum mode) {
  if (ctx.in_begin) {
    ctx.setError(GL_INVALID_OPERATION);
    return;
  }
  auto it = ctx.primitives.by_mode.find(mode);
  if (it == ctx.primitives.by_mode.end()) {
    ctx.setError(GL_INVALID_ENUM);
    return;
  }
  // GL_TRIANGLES with a face drawn unfilled (glPolygonMode): triangle_modes, which decides each
  // triangle's face and calls `triangles` or draws its edges (primitives/triangles.pfl), so that
  // `triangles` itself calls nothing.
  const pf::CompiledPrimitive* primitive = it->second.get();
  const pf::RasterModes& rm = ctx.raster_modes;
  if (mode == GL_TRIANGLES && (rm.polygon_mode[0] != GL_FILL || rm.polygon_mode[1] != GL_FILL)) {
    auto unfilled = ctx.primitives.by_name.find("triangle_modes");
    if (unfilled != ctx.primitives.by_name.end()) primitive = unfilled->second.get();
  }
  ctx.in_begin = true;
  ctx.begin_out_of_memory = false;
  try {
    startBegin(ctx, mode, primitive);
  } catch (const std::bad_alloc&) {  // planning the glBegin's rows: the glBegin is dropped
    ctx.outOfMemory("glBegin");
  }
}

void end(PFcontextRec& ctx) {
  if (!ctx.in_begin) {
    ctx.setError(GL_INVALID_OPERATION);
    return;
  }
  ctx.in_begin = false;
  if (ctx.begin_out_of_memory) {  // already reported (GL_OUT_OF_MEMORY): nothing to draw
    ctx.begin_out_of_memory = false;
    ctx.begin_primitive = nullptr;
    ctx.begin_texture.reset();
    return;
  }
  const CompiledPrimitive& prim = *ctx.begin_primitive;
  if (ctx.reject_reason.empty() && !isGlMode(ctx.begin_mode) && prim.sequence_points > 0 &&
      ctx.rows_count % static_cast<size_t>(prim.sequence_points) != 0)
    ctx.reject_reason = std::to_string(ctx.rows_count) + " sequence point(s) do not make whole instances of " +
                        std::to_string(prim.sequence_points);
  if (!ctx.reject_reason.empty()) {
    // Never half-drawn: the whole glBegin / glEnd is dropped.
    ctx.setError(GL_INVALID_OPERATION);
    std::fprintf(stderr, "primflow: glEnd: instances of '%s' rejected, nothing drawn: %s\n", prim.name.c_str(),
                 ctx.reject_reason.c_str());
  } else if (ctx.color) {
    if (!ctx.vertex_lighting.empty()) pf::flushVertexLighting(ctx);
    try {
      submitInstances(ctx);
    } catch (const std::bad_alloc&) {  // instances half binned: the frame so far is dropped
      ctx.outOfMemory("glEnd");
    }
  }
  ctx.begin_primitive = nullptr;
  ctx.begin_texture.reset();  // (the instances hold the snapshot; a level changed next is not copied for it)
}

void vertex2f(PFcontextRec& ctx, GLfloat x, GLfloat y) { setVertex(ctx, x, y, 0, 1, 2); }
void vertex3f(PFcontextRec& ctx, GLfloat x, GLfloat y, GLfloat z) { setVertex(ctx, x, y, z, 1, 3); }
void vertex(PFcontextRec& ctx, GLdouble x, GLdouble y, GLdouble z, GLdouble w, GLint count) {
  setVertex(ctx, x, y, z, w, count);
}

void color(PFcontextRec& ctx, GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  ctx.current_color = glm::vec4(r, g, b, a);
  ctx.lighting.trackColor(ctx.current_color);
  ParamValue& p = ctx.param(ctx.color_param);
  p.count = 4;
  for (int k = 0; k < 4; ++k) p.v[k] = ctx.current_color[k];
}

// Allowed inside glBegin. Kept as given, as Mesa keeps it (a float): an edge is drawn where its
// flag is not 0, GL_EDGE_FLAG reads true where it is 1.
void edgeFlag(PFcontextRec& ctx, GLboolean flag) {
  const double v = flag;
  setParam(ctx, ctx.edge_flag_param, 1, &v);
}

void normal(PFcontextRec& ctx, GLfloat x, GLfloat y, GLfloat z) {
  const double v[3] = {x, y, z};
  setParam(ctx, ctx.normal_param, 3, v);
}

// GL keeps four texture coordinates (s, t, r, q).
void texCoord(PFcontextRec& ctx, GLfloat s, GLfloat t, GLfloat r, GLfloat q) {
  const double v[4] = {s, t, r, q};
  setParam(ctx, ctx.texcoord_param, 4, v);
}

void rastParam1(PFcontextRec& ctx, GLuint name, GLdouble v) { setParam(ctx, name, 1, &v); }
void rastParam3(PFcontextRec& ctx, GLuint name, GLfloat x, GLfloat y, GLfloat z) {
  const double d[3] = {x, y, z};
  setParam(ctx, name, 3, d);
}
void rastParam4(PFcontextRec& ctx, GLuint name, GLfloat x, GLfloat y, GLfloat z, GLfloat w) {
  const double d[4] = {x, y, z, w};
  setParam(ctx, name, 4, d);
}
void rastParamfv(PFcontextRec& ctx, GLuint name, Values16f v) { setParamVector(ctx, name, v); }
void rastParamiv(PFcontextRec& ctx, GLuint name, Values16i v) { setParamVector(ctx, name, v); }

void sequencePoint(PFcontextRec& ctx) {
  if (!ctx.in_begin) {
    ctx.setError(GL_INVALID_OPERATION);
    return;
  }
  bindSequencePoint(ctx);
}

void materialInterp(PFcontextRec& ctx, GLuint param, GLenum primitive, GLenum interpolator) {
  if (!outsideBegin(ctx)) return;
  if (!ctx.isParam(param) || !ctx.primitives.by_mode.count(primitive)) {
    ctx.setError(GL_INVALID_VALUE);
    return;
  }
  if (interpolator != GL_PERSPECTIVE_LINEAR_INTERPOLATOR_EXT && interpolator != GL_LINEAR_INTERPOLATOR_EXT &&
      !ctx.primitives.interpolator(interpolator)) {
    ctx.setError(GL_INVALID_ENUM);
    return;
  }
  auto& bound = ctx.shading_bindings[primitive];
  for (auto& b : bound)
    if (b.first == param) {
      b.second = interpolator;
      return;
    }
  bound.push_back({param, interpolator});
}

}  // namespace pf::cmd

// (The vertex attributes' entry points, glVertex* and the rest: vertex_attributes.cpp.)

extern "C" {

void pfglBegin(GLenum mode) { pf::dispatch<pf::GlOp::Begin>(mode); }
void pfglEnd(void) { pf::dispatch<pf::GlOp::End>(); }

// ---- the extension: named parameters and sequence points ----

GLuint pfglGetParamNameEXT(const GLchar* name) {
  PFcontextRec* ctx = currentContext();
  if (!ctx) return 0;
  if (!name || !*name) {
    ctx->setError(GL_INVALID_VALUE);
    return 0;
  }
  try {
    return ctx->paramId(name);
  } catch (const std::bad_alloc&) {  // out of memory, or all 32,768 ids taken
    ctx->setError(GL_OUT_OF_MEMORY);
    return 0;
  }
}

void pfglRastParamfEXT(GLuint name, GLfloat v) { pf::dispatch<pf::GlOp::RastParam1>(name, v); }
void pfglRastParamiEXT(GLuint name, GLint v) { pf::dispatch<pf::GlOp::RastParam1>(name, v); }
void pfglRastParam3fEXT(GLuint name, GLfloat x, GLfloat y, GLfloat z) {
  pf::dispatch<pf::GlOp::RastParam3>(name, x, y, z);
}
void pfglRastParam4fEXT(GLuint name, GLfloat x, GLfloat y, GLfloat z, GLfloat w) {
  pf::dispatch<pf::GlOp::RastParam4>(name, x, y, z, w);
}
// (A count outside 1..16 or a NULL pointer copies nothing: GL_INVALID_VALUE when it executes.)
void pfglRastParamfvEXT(GLuint name, GLsizei count, const GLfloat* v) {
  const bool ok = count >= 1 && count <= 16;
  pf::dispatch<pf::GlOp::RastParamfv>(name, pf::valuesOf<GLfloat, 16>(ok ? v : nullptr, count, count));
}
void pfglRastParamivEXT(GLuint name, GLsizei count, const GLint* v) {
  const bool ok = count >= 1 && count <= 16;
  pf::dispatch<pf::GlOp::RastParamiv>(name, pf::valuesOf<GLint, 16>(ok ? v : nullptr, count, count));
}

void pfglMaterialInterpEXT(GLuint param, GLenum primitive, GLenum interpolator) {
  pf::dispatch<pf::GlOp::MaterialInterp>(param, primitive, interpolator);
}

void pfglSequencePointEXT(void) { pf::dispatch<pf::GlOp::SequencePoint>(); }

}  // extern "C"
