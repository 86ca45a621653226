// The shading channels of a glBegin (shading_channels.h).
#include "api/src/shading_channels.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "api/src/context_state.h"

namespace pf {
namespace {

// The fog coordinate of the current sequence point: |z| of its position in eye coordinates (the
// modelview's third row times the position, not divided by w: Mesa's fixed-function vertex
// program, GL_EYE_PLANE_ABSOLUTE_NV), 0 for a primitive without a position parameter.
float fogCoordinate(const PFcontextRec& ctx) {
  if (ctx.fog_position_param == 0) return 0.0f;
  const ParamValue& v = ctx.param(ctx.fog_position_param);
  const glm::vec4 p(static_cast<float>(v.v[0]), static_cast<float>(v.v[1]), v.count > 2 ? static_cast<float>(v.v[2]) : 0.0f,
                    v.count > 3 ? static_cast<float>(v.v[3]) : 1.0f);
  return std::fabs((ctx.begin_modelview * p).z);
}

// The parameter whose position fog measures: the primitive's "vertex", else its first point
// parameter given per sequence point (a sphere's centre); 0: none.
GLuint fogPositionParam(PFcontextRec& ctx, const CompiledPrimitive& prim) {
  if (prim.findParam("vertex")) return ctx.vertex_param;
  for (const ParamInfo& p : prim.params)
    if (p.per_sequence_point && p.type.base == BaseType::Point) return ctx.paramId(p.name);
  return 0;
}

}  // namespace

void flushVertexLighting(PFcontextRec& ctx) {
  ctx.vertex_lighting.flush(*ctx.begin_equation, {ctx.row_shading.data(), static_cast<size_t>(ctx.row_channels),
                                                  ctx.color_channel, ctx.back_color_channel});
}

// The shading channels of a sequence point, in the layout planned at glBegin: each bound
// parameter's current value, the colour's being GL's lit colour(s) when lighting applies
// (written when its batch is lit: flushVertexLighting).
void rowChannels(PFcontextRec& ctx) {
  const size_t at = ctx.row_shading.size();
  ctx.row_shading.resize(at + static_cast<size_t>(ctx.row_channels));
  float* out = ctx.row_shading.data() + at;
  glm::vec3 eye(0.0f), n(0.0f);
  glm::vec4 p(0.0f), eye4(0.0f);
  const bool generating = ctx.begin_texture && ctx.textures.generating();
  if (ctx.begin_lit || ctx.begin_vertices_per_pixel || generating) {
    const ParamValue& v = ctx.param(ctx.vertex_param);
    const ParamValue& nv = ctx.param(ctx.normal_param);
    p = glm::vec4(static_cast<float>(v.v[0]), static_cast<float>(v.v[1]), v.count > 2 ? static_cast<float>(v.v[2]) : 0.0f,
                  v.count > 3 ? static_cast<float>(v.v[3]) : 1.0f);
    eye4 = ctx.begin_modelview * p;
    eye = eye4.w != 0.0f ? glm::vec3(eye4) / eye4.w : glm::vec3(eye4);
    n = ctx.begin_normal_matrix *
        glm::vec3(static_cast<float>(nv.v[0]), static_cast<float>(nv.v[1]), static_cast<float>(nv.v[2]));
    if (ctx.lighting.normalize && glm::length(n) > 0.0f) n = glm::normalize(n);
  }
  // Lit vertices' colours come later, a batch at a time (flushVertexLighting); a colour not
  // bound to the mode is not lit at all.
  const bool lit_later = ctx.begin_lit && ctx.color_channel >= 0;
  if (lit_later) {
    const size_t row = at / static_cast<size_t>(ctx.row_channels);
    ctx.vertex_lighting.add(row, eye, n, ctx.lighting.material[0],
                            ctx.back_color_channel >= 0 ? &ctx.lighting.material[1] : nullptr);
  }
  if (const PixelFragment* f = ctx.pixel_fragment) {
    // A pixel rectangle's fragment: its colour, the raster position's texture coordinates as
    // glRasterPos computed them and its distance as the fog coordinate.
    for (const ShadingChannel& s : ctx.shading) {
      float* dst = out + s.first;
      const glm::vec4 v = s.param == kFogCoordChannel    ? glm::vec4(f->fog, 0.0f, 0.0f, 0.0f)
                          : s.param == ctx.color_param    ? f->color
                          : s.param == ctx.texcoord_param ? f->texcoord
                                                          : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
      for (int k = 0; k < 4; ++k) dst[k] = v[k];
    }
    return;
  }
  for (const ShadingChannel& s : ctx.shading) {
    float* dst = out + s.first;
    if (s.param == kFogCoordChannel) {
      dst[0] = fogCoordinate(ctx);
      dst[1] = dst[2] = dst[3] = 0.0f;
      continue;
    }
    if (s.param == kEyePositionChannel || s.param == kEyeNormalChannel) {
      const glm::vec3& v = s.param == kEyePositionChannel ? eye : n;
      for (int k = 0; k < 3; ++k) dst[k] = v[k];
      dst[3] = s.param == kEyePositionChannel ? 1.0f : 0.0f;
      continue;
    }
    if (s.param == ctx.color_param) {
      const glm::vec4 c = lit_later ? glm::vec4(0.0f) : ctx.current_color;  // lit: written by the flush
      for (int k = 0; k < 4; ++k) dst[k] = c[k];
      continue;
    }
    const ParamValue& v = ctx.param(s.param);
    if (s.param == ctx.texcoord_param && ctx.begin_texture) {
      // The texture coordinates a textured draw samples by: generated, then the texture matrix.
      const glm::vec4 current(static_cast<float>(v.v[0]), static_cast<float>(v.v[1]), static_cast<float>(v.v[2]),
                              static_cast<float>(v.v[3]));
      const glm::vec4 c = textureCoordinates(ctx.textures, ctx.texture.top, current, p, eye4, n);
      for (int k = 0; k < 4; ++k) dst[k] = c[k];
      continue;
    }
    for (int k = 0; k < 4; ++k) dst[k] = k < v.count ? static_cast<float>(v.v[k]) : (k == 3 ? 1.0f : 0.0f);
  }
  if (ctx.vertex_lighting.full()) flushVertexLighting(ctx);
}

// Plans the shading channels of a glBegin: the parameters bound for its mode (the colour
// perspective-linear unless bound otherwise; front and back with two-sided lighting), 4
// channels each, ordered by interpolation kind as ChannelLayout wants.
void planShading(PFcontextRec& ctx, GLenum mode, const CompiledPrimitive& prim) {
  ctx.shading.clear();
  ctx.color_channel = ctx.back_color_channel = ctx.texcoord_channel = ctx.fog_channel = -1;
  ctx.fog_position_param = 0;
  // Cleared, not rebuilt: a glBegin per triangle must not allocate (their capacity stays).
  ChannelLayout& layout = ctx.begin_layout;
  layout.count = 0;
  for (int k = 0; k < kInterpKindCount; ++k) layout.kind_begin[k] = layout.kind_end[k] = 0;
  layout.gbuffer_slot.clear();
  layout.shared.clear();
  layout.surface_slot = -1;
  layout.surface_interpolated = false;
  layout.surface_eye = true;
  ctx.row_channels = 0;
  if (!prim.has_interp_data) return;
  std::vector<std::pair<GLuint, GLenum>>& bound = ctx.planned_bindings;
  bound.clear();
  auto it = ctx.shading_bindings.find(mode);
  if (it != ctx.shading_bindings.end()) bound.assign(it->second.begin(), it->second.end());
  bool has_color = false, has_texcoord = false;
  for (const auto& b : bound) {
    has_color = has_color || b.first == ctx.color_param;
    has_texcoord = has_texcoord || b.first == ctx.texcoord_param;
  }
  if (!has_color) bound.insert(bound.begin(), {ctx.color_param, GL_PERSPECTIVE_LINEAR_INTERPOLATOR_EXT});
  // A textured draw carries its texture coordinates, perspective-correct unless bound otherwise.
  if (ctx.begin_texture && !has_texcoord) bound.push_back({ctx.texcoord_param, GL_PERSPECTIVE_LINEAR_INTERPOLATOR_EXT});
  for (int kind = 0; kind < kInterpKindCount; ++kind) {
    layout.kind_begin[kind] = 4 * static_cast<int>(ctx.shading.size());
    if (kind == static_cast<int>(InterpKind::PerspectiveLinear) && ctx.begin_vertices_per_pixel) {
      // Per-pixel lit vertices: the eye-space position and normal, interpolated perspective-
      // correct, are the shading pass's P and N (their x, y, z in six consecutive G-buffer
      // slots, the w's after them; see below).
      for (GLuint internal : {kEyePositionChannel, kEyeNormalChannel})
        ctx.shading.push_back(
            {internal, false, InterpKind::PerspectiveLinear, 4 * static_cast<int>(ctx.shading.size()), nullptr});
    }
    if (kind == static_cast<int>(InterpKind::PerspectiveLinear) && ctx.fog.enabled && !prim.writes_normal) {
      // Fog: the fog coordinate, interpolated perspective-correct (as llvmpipe interpolates it).
      // (A primitive that commits its surface point is fogged by it instead: immediate_mode.cpp.)
      ctx.fog_channel = 4 * static_cast<int>(ctx.shading.size());
      ctx.fog_position_param = fogPositionParam(ctx, prim);
      ctx.shading.push_back({kFogCoordChannel, false, InterpKind::PerspectiveLinear, ctx.fog_channel, nullptr});
    }
    for (const auto& [param, interpolator] : bound) {
      const CompiledPrimitive* shared = ctx.primitives.interpolator(interpolator);
      InterpKind k = shared                                         ? InterpKind::Shared
                         : interpolator == GL_LINEAR_INTERPOLATOR_EXT ? InterpKind::Linear
                                                                      : InterpKind::PerspectiveLinear;
      if (static_cast<int>(k) != kind) continue;
      const bool color = param == ctx.color_param;
      // A shared interpolator computes one value for both faces.
      const int faces = color && !shared && ctx.begin_lit && ctx.lighting.two_side ? 2 : 1;
      for (int face = 0; face < faces; ++face) {
        const int first = 4 * static_cast<int>(ctx.shading.size());
        ctx.shading.push_back({param, face == 1, k, first, shared});
        if (color) (face == 0 ? ctx.color_channel : ctx.back_color_channel) = first;
        if (param == ctx.texcoord_param) ctx.texcoord_channel = first;
        if (shared) {
          uint32_t offset = 0;
          for (const auto& s : layout.shared)
            offset = std::max(offset, s.record_offset + s.program->pixel.num_uniform_slots);
          layout.shared.push_back({shared, first, offset});
        }
      }
    }
    layout.kind_end[kind] = 4 * static_cast<int>(ctx.shading.size());
  }
  if (ctx.texcoord_channel < 0) ctx.begin_texture.reset();  // (no channels: nothing to sample by)
  ctx.row_channels = 4 * static_cast<int>(ctx.shading.size());
  layout.count = ctx.row_channels;
  for (int c = 0; c < ctx.row_channels; ++c) layout.gbuffer_slot.push_back(c);
  for (const ShadingChannel& s : ctx.shading) {
    if (s.param != kEyePositionChannel) continue;
    // Position x, y, z -> slots f, f+1, f+2; normal x, y, z (channels f+4..f+6) -> f+3..f+5;
    // the two w's -> f+6, f+7.
    const int f = s.first;
    const int slot_of[8] = {f, f + 1, f + 2, f + 6, f + 3, f + 4, f + 5, f + 7};
    for (int k = 0; k < 8; ++k) layout.gbuffer_slot[f + k] = slot_of[k];
    layout.surface_slot = f;
    layout.surface_interpolated = true;
  }
}

}  // namespace pf
