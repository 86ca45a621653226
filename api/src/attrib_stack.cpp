// glPushAttrib / glPopAttrib (recorded in display lists) and glPushClientAttrib /
// glPopClientAttrib (executed at once), GL 1.5 section 6.1.14, for the attribute groups
// primflow has: what each group holds is AttribState's (context_state.h). Stacks 16 deep, as
// Mesa's; overflow GL_STACK_OVERFLOW, underflow GL_STACK_UNDERFLOW; bits of other groups are
// accepted and save nothing (their state is constant).
#include <algorithm>
#include <new>

#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/context_state.h"

namespace pf::cmd {

void pushAttrib(PFcontextRec& ctx, GLbitfield mask) {
  if (!outsideBegin(ctx)) return;
  if (ctx.attrib_stack.size() >= kMaxAttribStackDepth) return ctx.setError(GL_STACK_OVERFLOW);
  AttribState s;
  s.mask = mask;
  s.current_color = ctx.current_color;
  s.normal = ctx.param(ctx.normal_param);
  s.texcoord = ctx.param(ctx.texcoord_param);
  s.edge_flag = ctx.param(ctx.edge_flag_param);
  s.depth_test = ctx.depth_test;
  s.depth_write = ctx.depth_write;
  s.depth_func = ctx.depth_func;
  s.clear_depth = ctx.clear_depth;
  s.cull = ctx.cull;
  s.cull_face = ctx.cull_face;
  s.front_face = ctx.front_face;
  s.lighting = ctx.lighting;
  s.shade_model = ctx.shade_model;
  s.matrix_mode = ctx.matrix_mode;
  std::copy(std::begin(ctx.viewport), std::end(ctx.viewport), s.viewport);
  std::copy(std::begin(ctx.depth_range), std::end(ctx.depth_range), s.depth_range);
  std::copy(std::begin(ctx.clear_color), std::end(ctx.clear_color), s.clear_color);
  s.color_mask = ctx.color_mask;
  std::copy(std::begin(ctx.hints), std::end(ctx.hints), s.hints);
  s.list_base = ctx.lists.base;
  s.fragment = ctx.fragment;
  s.texture = ctx.textures.a;
  s.fog = ctx.fog;
  s.clip = ctx.clip;
  std::copy(std::begin(ctx.accum_clear), std::end(ctx.accum_clear), s.accum_clear);
  s.raster = ctx.raster;
  s.pixel_mode = ctx.pixel_mode;
  s.raster_modes = ctx.raster_modes;
  try {
    ctx.attrib_stack.push_back(s);
  } catch (const std::bad_alloc&) {
    ctx.setError(GL_OUT_OF_MEMORY);
  }
}

void popAttrib(PFcontextRec& ctx) {
  if (!outsideBegin(ctx)) return;
  if (ctx.attrib_stack.empty()) return ctx.setError(GL_STACK_UNDERFLOW);
  const AttribState s = ctx.attrib_stack.back();
  ctx.attrib_stack.pop_back();
  const GLbitfield m = s.mask;
  LightingState& l = ctx.lighting;
  if (m & GL_CURRENT_BIT) {  // (a colour restored is not tracked by GL_COLOR_MATERIAL, as in Mesa)
    ctx.current_color = s.current_color;
    ParamValue& color = ctx.param(ctx.color_param);
    color.count = 4;
    for (int k = 0; k < 4; ++k) color.v[k] = s.current_color[k];
    ctx.param(ctx.normal_param) = s.normal;
    ctx.param(ctx.texcoord_param) = s.texcoord;
    ctx.param(ctx.edge_flag_param) = s.edge_flag;
    ctx.raster = s.raster;
  }
  if (m & GL_LIGHTING_BIT) {  // all of the lighting state but the enables of other groups
    const bool normalize = l.normalize, rescale = l.rescale_normal, per_pixel = l.per_pixel_vertices;
    l = s.lighting;
    l.normalize = normalize;
    l.rescale_normal = rescale;
    l.per_pixel_vertices = per_pixel;
    ctx.shade_model = s.shade_model;
  }
  FragmentState& f = ctx.fragment;
  const FragmentState& saved = s.fragment;
  if (m & GL_ENABLE_BIT) {
    f.scissor_test = saved.scissor_test;
    f.alpha_test = saved.alpha_test;
    f.blend = saved.blend;
    f.logic_op = saved.logic_op;
    f.dither = saved.dither;
    f.stencil_test = saved.stencil_test;
    ctx.depth_test = s.depth_test;
    ctx.cull = s.cull;
    l.enabled = s.lighting.enabled;
    for (int k = 0; k < kMaxLights; ++k) l.lights[k].enabled = s.lighting.lights[k].enabled;
    l.color_material = s.lighting.color_material;
    l.normalize = s.lighting.normalize;
    l.rescale_normal = s.lighting.rescale_normal;
    l.per_pixel_vertices = s.lighting.per_pixel_vertices;
    TextureAttribs& t = ctx.textures.a;
    t.enabled_1d = s.texture.enabled_1d;
    t.enabled_2d = s.texture.enabled_2d;
    for (int k = 0; k < 4; ++k) t.gen[k].enabled = s.texture.gen[k].enabled;
    ctx.textures.dirty = true;
    ctx.fog.enabled = s.fog.enabled;
    ctx.raster_modes.line_stipple = s.raster_modes.line_stipple;
    ctx.raster_modes.offset_fill = s.raster_modes.offset_fill;
    ctx.raster_modes.offset_line = s.raster_modes.offset_line;
    ctx.raster_modes.offset_point = s.raster_modes.offset_point;
    ctx.raster_modes.polygon_stipple = s.raster_modes.polygon_stipple;
    std::copy(std::begin(s.clip.enabled), std::end(s.clip.enabled), ctx.clip.enabled);
  }
  if (m & GL_FOG_BIT) ctx.fog = s.fog;  // (the enable included)
  if (m & GL_ACCUM_BUFFER_BIT) std::copy(std::begin(s.accum_clear), std::end(s.accum_clear), ctx.accum_clear);
  if (m & GL_PIXEL_MODE_BIT) ctx.pixel_mode = s.pixel_mode;  // (the zoom and glPixelTransfer's modes, not the maps)
  if (m & GL_POINT_BIT) ctx.raster_modes.point_size = s.raster_modes.point_size;
  if (m & GL_LINE_BIT) {  // the width, the stipple and its enable
    ctx.raster_modes.line_width = s.raster_modes.line_width;
    ctx.raster_modes.line_stipple = s.raster_modes.line_stipple;
    ctx.raster_modes.stipple_factor = s.raster_modes.stipple_factor;
    ctx.raster_modes.stipple_pattern = s.raster_modes.stipple_pattern;
  }
  if (m & GL_TEXTURE_BIT) {  // the bindings, the environment, the generation (enables included)
    ctx.textures.a = s.texture;
    // (A binding to a texture deleted since is the default texture's.)
    if (ctx.textures.a.binding_1d && !ctx.textures.object(ctx.textures.a.binding_1d)) ctx.textures.a.binding_1d = 0;
    if (ctx.textures.a.binding_2d && !ctx.textures.object(ctx.textures.a.binding_2d)) ctx.textures.a.binding_2d = 0;
    ctx.textures.dirty = true;
  }
  if (m & GL_DEPTH_BUFFER_BIT) {
    ctx.depth_test = s.depth_test;
    ctx.depth_write = s.depth_write;
    ctx.depth_func = s.depth_func;
    ctx.clear_depth = s.clear_depth;
  }
  if (m & GL_POLYGON_BIT) {  // culling, the polygon modes, the offset, its enables and the stipple's
    ctx.cull = s.cull;
    ctx.cull_face = s.cull_face;
    ctx.front_face = s.front_face;
    RasterModes& r = ctx.raster_modes;
    const RasterModes& saved_r = s.raster_modes;
    std::copy(std::begin(saved_r.polygon_mode), std::end(saved_r.polygon_mode), r.polygon_mode);
    r.offset_factor = saved_r.offset_factor;
    r.offset_units = saved_r.offset_units;
    r.offset_fill = saved_r.offset_fill;
    r.offset_line = saved_r.offset_line;
    r.offset_point = saved_r.offset_point;
    r.polygon_stipple = saved_r.polygon_stipple;
  }
  if (m & GL_POLYGON_STIPPLE_BIT)  // the pattern (its enable: GL_ENABLE_BIT, GL_POLYGON_BIT)
    std::copy(std::begin(s.raster_modes.stipple_rows), std::end(s.raster_modes.stipple_rows), ctx.raster_modes.stipple_rows);
  if (m & GL_TRANSFORM_BIT) {  // the matrix mode, the clip planes and their enables, normalising
    ctx.matrix_mode = s.matrix_mode;
    ctx.clip = s.clip;
    l.normalize = s.lighting.normalize;
    l.rescale_normal = s.lighting.rescale_normal;
  }
  if (m & GL_VIEWPORT_BIT) {
    std::copy(std::begin(s.viewport), std::end(s.viewport), ctx.viewport);
    std::copy(std::begin(s.depth_range), std::end(s.depth_range), ctx.depth_range);
  }
  if (m & GL_COLOR_BUFFER_BIT) {  // the alpha test, blending, the logic op, dithering
    std::copy(std::begin(s.clear_color), std::end(s.clear_color), ctx.clear_color);
    ctx.color_mask = s.color_mask;
    f.alpha_test = saved.alpha_test, f.alpha_func = saved.alpha_func, f.alpha_ref = saved.alpha_ref;
    f.blend = saved.blend;
    f.blend_src_rgb = saved.blend_src_rgb, f.blend_dst_rgb = saved.blend_dst_rgb;
    f.blend_src_alpha = saved.blend_src_alpha, f.blend_dst_alpha = saved.blend_dst_alpha;
    f.blend_equation = saved.blend_equation;
    std::copy(std::begin(saved.blend_color), std::end(saved.blend_color), f.blend_color);
    f.logic_op = saved.logic_op, f.logic_mode = saved.logic_mode;
    f.dither = saved.dither;
  }
  if (m & GL_STENCIL_BUFFER_BIT) {
    f.stencil_test = saved.stencil_test;
    f.stencil_func = saved.stencil_func, f.stencil_ref = saved.stencil_ref;
    f.stencil_value_mask = saved.stencil_value_mask, f.stencil_write_mask = saved.stencil_write_mask;
    f.stencil_fail = saved.stencil_fail, f.stencil_depth_fail = saved.stencil_depth_fail;
    f.stencil_depth_pass = saved.stencil_depth_pass;
    f.stencil_clear = saved.stencil_clear;
  }
  if (m & GL_SCISSOR_BIT) {
    f.scissor_test = saved.scissor_test;
    std::copy(std::begin(saved.scissor), std::end(saved.scissor), f.scissor);
  }
  if (m & GL_HINT_BIT) std::copy(std::begin(s.hints), std::end(s.hints), ctx.hints);
  if (m & GL_LIST_BIT) ctx.lists.base = s.list_base;
}

}  // namespace pf::cmd

extern "C" {

void pfglPushAttrib(GLbitfield mask) { pf::dispatch<pf::GlOp::PushAttrib>(mask); }
void pfglPopAttrib(void) { pf::dispatch<pf::GlOp::PopAttrib>(); }

void pfglPushClientAttrib(GLbitfield mask) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return;
  if (ctx->client_attrib_stack.size() >= pf::kMaxAttribStackDepth) return ctx->setError(GL_STACK_OVERFLOW);
  try {
    ctx->client_attrib_stack.push_back(
        {mask, ctx->pack, ctx->unpack, ctx->vertex_array, ctx->color_array, ctx->normal_array, ctx->texcoord_array,
         ctx->edge_flag_array});
  } catch (const std::bad_alloc&) {
    ctx->setError(GL_OUT_OF_MEMORY);
  }
}

void pfglPopClientAttrib(void) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return;
  if (ctx->client_attrib_stack.empty()) return ctx->setError(GL_STACK_UNDERFLOW);
  const pf::ClientAttribState s = ctx->client_attrib_stack.back();
  ctx->client_attrib_stack.pop_back();
  if (s.mask & GL_CLIENT_PIXEL_STORE_BIT) {
    ctx->pack = s.pack;
    ctx->unpack = s.unpack;
  }
  if (s.mask & GL_CLIENT_VERTEX_ARRAY_BIT) {
    ctx->vertex_array = s.vertex_array;
    ctx->color_array = s.color_array;
    ctx->normal_array = s.normal_array;
    ctx->texcoord_array = s.texcoord_array;
    ctx->edge_flag_array = s.edge_flag_array;
  }
}

}  // extern "C"
