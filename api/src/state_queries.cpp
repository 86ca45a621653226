// Reading state back: glGet{Boolean,Integer,Float,Double}v (GL 1.5 section 6.1). (glPixelStore
// and glReadPixels: pixels.cpp.)
#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/type_ptr.hpp>

#include <primflow/gl.h>

#include "api/src/context_state.h"
#include "api/src/query.h"
#include "raster/limits.h"

namespace {

using pf::Query;

// A client array's size, type and stride (GL_*_ARRAY_SIZE / _TYPE / _STRIDE); `size` 0: none.
bool arrayQuery(const pf::ClientArray& a, GLenum pname, GLenum size, GLenum type, GLenum stride, Query& q) {
  if (pname == size && size != 0) q.set({double(a.size)});
  else if (pname == type) q.set({double(a.type)});
  else if (pname == stride) q.set({double(a.stride)});
  else return false;
  return true;
}

// The per-fragment operations' state (fragment_commands.cpp).
bool fragmentQuery(const pf::FragmentState& f, GLenum pname, Query& q) {
  switch (pname) {
    case GL_SCISSOR_TEST: q.set({f.scissor_test ? 1.0 : 0.0}); return true;
    case GL_ALPHA_TEST: q.set({f.alpha_test ? 1.0 : 0.0}); return true;
    case GL_ALPHA_TEST_FUNC: q.set({double(f.alpha_func)}); return true;
    case GL_ALPHA_TEST_REF: q.set({f.alpha_ref}, true); return true;
    case GL_BLEND: q.set({f.blend ? 1.0 : 0.0}); return true;
    case GL_BLEND_SRC: case GL_BLEND_SRC_RGB: q.set({double(f.blend_src_rgb)}); return true;
    case GL_BLEND_DST: case GL_BLEND_DST_RGB: q.set({double(f.blend_dst_rgb)}); return true;
    case GL_BLEND_SRC_ALPHA: q.set({double(f.blend_src_alpha)}); return true;
    case GL_BLEND_DST_ALPHA: q.set({double(f.blend_dst_alpha)}); return true;
    case GL_BLEND_EQUATION: case GL_BLEND_EQUATION_ALPHA: q.set({double(f.blend_equation)}); return true;
    case GL_BLEND_COLOR: {
      const float* c = f.blend_color;
      q.set({c[0], c[1], c[2], c[3]}, true);
      return true;
    }
    case GL_COLOR_LOGIC_OP: q.set({f.logic_op ? 1.0 : 0.0}); return true;
    case GL_LOGIC_OP_MODE: q.set({double(f.logic_mode)}); return true;
    case GL_DITHER: q.set({f.dither ? 1.0 : 0.0}); return true;
    case GL_STENCIL_TEST: q.set({f.stencil_test ? 1.0 : 0.0}); return true;
    case GL_STENCIL_FUNC: q.set({double(f.stencil_func)}); return true;
    case GL_STENCIL_VALUE_MASK: q.set({double(f.stencil_value_mask)}); return true;
    case GL_STENCIL_FAIL: q.set({double(f.stencil_fail)}); return true;
    case GL_STENCIL_PASS_DEPTH_FAIL: q.set({double(f.stencil_depth_fail)}); return true;
    case GL_STENCIL_PASS_DEPTH_PASS: q.set({double(f.stencil_depth_pass)}); return true;
    case GL_STENCIL_WRITEMASK: q.set({double(f.stencil_write_mask)}); return true;
    case GL_STENCIL_CLEAR_VALUE: q.set({double(f.stencil_clear)}); return true;
    default: return false;
  }
}

bool query(const PFcontextRec& ctx, GLenum pname, Query& q) {
  auto set = [&](std::initializer_list<double> values, bool normalized = false) { q.set(values, normalized); };
  auto matrix = [&](const glm::mat4& m, bool transpose = false) {
    const float* p = glm::value_ptr(m);
    q.count = 16;
    for (int i = 0; i < 16; ++i) q.v[i] = p[transpose ? (i % 4) * 4 + i / 4 : i];
    q.normalized = false;
  };
  const auto& cc = ctx.clear_color;
  const auto& col = ctx.current_color;
  switch (pname) {
    case GL_VIEWPORT: set({double(ctx.viewport[0]), double(ctx.viewport[1]), double(ctx.viewport[2]), double(ctx.viewport[3])}); return true;
    case GL_MAX_VIEWPORT_DIMS: set({double(pf::kMaxFramebufferSize), double(pf::kMaxFramebufferSize)}); return true;
    case GL_DEPTH_RANGE: set({ctx.depth_range[0], ctx.depth_range[1]}, true); return true;
    case GL_COLOR_CLEAR_VALUE: set({cc[0], cc[1], cc[2], cc[3]}, true); return true;
    case GL_DEPTH_CLEAR_VALUE: set({ctx.clear_depth}, true); return true;
    case GL_DEPTH_FUNC: set({double(ctx.depth_func)}); return true;
    case GL_DEPTH_WRITEMASK: set({ctx.depth_write ? 1.0 : 0.0}); return true;
    case GL_DEPTH_TEST: set({ctx.depth_test ? 1.0 : 0.0}); return true;
    case GL_CULL_FACE: set({ctx.cull ? 1.0 : 0.0}); return true;
    case GL_CULL_FACE_MODE: set({double(ctx.cull_face)}); return true;
    case GL_FRONT_FACE: set({double(ctx.front_face)}); return true;
    case GL_SHADE_MODEL: set({double(ctx.shade_model)}); return true;
    case GL_COLOR_WRITEMASK:
      set({double(ctx.color_mask & 1), double((ctx.color_mask >> 1) & 1), double((ctx.color_mask >> 2) & 1),
           double((ctx.color_mask >> 3) & 1)});
      return true;
    case GL_MATRIX_MODE: set({double(ctx.matrix_mode)}); return true;
    case GL_LIGHTING: set({ctx.lighting.enabled ? 1.0 : 0.0}); return true;
    case GL_COLOR_MATERIAL: set({ctx.lighting.color_material ? 1.0 : 0.0}); return true;
    case GL_COLOR_MATERIAL_FACE: set({double(ctx.lighting.color_material_face)}); return true;
    case GL_COLOR_MATERIAL_PARAMETER: set({double(ctx.lighting.color_material_mode)}); return true;
    case GL_NORMALIZE: set({ctx.lighting.normalize ? 1.0 : 0.0}); return true;
    case GL_PER_PIXEL_LIGHTING_EXT: set({ctx.lighting.per_pixel_vertices ? 1.0 : 0.0}); return true;
    case GL_RESCALE_NORMAL: set({ctx.lighting.rescale_normal ? 1.0 : 0.0}); return true;
    case GL_MAX_LIGHTS: set({double(pf::kMaxLights)}); return true;
    case GL_LIGHT_MODEL_AMBIENT: {
      const glm::vec4& a = ctx.lighting.model_ambient;
      set({a[0], a[1], a[2], a[3]}, true);
      return true;
    }
    case GL_LIGHT_MODEL_LOCAL_VIEWER: set({ctx.lighting.local_viewer ? 1.0 : 0.0}); return true;
    case GL_LIGHT_MODEL_TWO_SIDE: set({ctx.lighting.two_side ? 1.0 : 0.0}); return true;
    case GL_VERTEX_ARRAY: set({ctx.vertex_array.enabled ? 1.0 : 0.0}); return true;
    case GL_COLOR_ARRAY: set({ctx.color_array.enabled ? 1.0 : 0.0}); return true;
    case GL_NORMAL_ARRAY: set({ctx.normal_array.enabled ? 1.0 : 0.0}); return true;
    case GL_TEXTURE_COORD_ARRAY: set({ctx.texcoord_array.enabled ? 1.0 : 0.0}); return true;
    case GL_EDGE_FLAG_ARRAY: set({ctx.edge_flag_array.enabled ? 1.0 : 0.0}); return true;
    case GL_EDGE_FLAG_ARRAY_STRIDE: set({double(ctx.edge_flag_array.stride)}); return true;
    case GL_EDGE_FLAG: set({ctx.param(ctx.edge_flag_param).v[0] == 1.0 ? 1.0 : 0.0}); return true;  // (Mesa's test)
    case GL_MODELVIEW_MATRIX: matrix(ctx.modelview.top); return true;
    case GL_PROJECTION_MATRIX: matrix(ctx.projection.top); return true;
    case GL_TEXTURE_MATRIX: matrix(ctx.texture.top); return true;
    case GL_TRANSPOSE_MODELVIEW_MATRIX: matrix(ctx.modelview.top, true); return true;
    case GL_TRANSPOSE_PROJECTION_MATRIX: matrix(ctx.projection.top, true); return true;
    case GL_TRANSPOSE_TEXTURE_MATRIX: matrix(ctx.texture.top, true); return true;
    case GL_MODELVIEW_STACK_DEPTH: set({double(ctx.modelview.depth())}); return true;
    case GL_PROJECTION_STACK_DEPTH: set({double(ctx.projection.depth())}); return true;
    case GL_TEXTURE_STACK_DEPTH: set({double(ctx.texture.depth())}); return true;
    case GL_MAX_MODELVIEW_STACK_DEPTH: set({double(ctx.modelview.max_depth)}); return true;
    case GL_MAX_PROJECTION_STACK_DEPTH: set({double(ctx.projection.max_depth)}); return true;
    case GL_MAX_TEXTURE_STACK_DEPTH: set({double(ctx.texture.max_depth)}); return true;
    case GL_CURRENT_COLOR: set({col[0], col[1], col[2], col[3]}, true); return true;
    case GL_CURRENT_NORMAL: {
      const pf::ParamValue& n = ctx.param(ctx.normal_param);
      set({n.v[0], n.v[1], n.v[2]}, true);
      return true;
    }
    case GL_CURRENT_TEXTURE_COORDS: {
      const pf::ParamValue& t = ctx.param(ctx.texcoord_param);
      set({t.v[0], t.v[1], t.v[2], t.v[3]});
      return true;
    }
    case GL_PACK_SWAP_BYTES: set({double(ctx.pack.swap_bytes)}); return true;
    case GL_PACK_LSB_FIRST: set({double(ctx.pack.lsb_first)}); return true;
    case GL_PACK_ROW_LENGTH: set({double(ctx.pack.row_length)}); return true;
    case GL_PACK_SKIP_ROWS: set({double(ctx.pack.skip_rows)}); return true;
    case GL_PACK_SKIP_PIXELS: set({double(ctx.pack.skip_pixels)}); return true;
    case GL_PACK_ALIGNMENT: set({double(ctx.pack.alignment)}); return true;
    case GL_PACK_IMAGE_HEIGHT: set({double(ctx.pack.image_height)}); return true;
    case GL_PACK_SKIP_IMAGES: set({double(ctx.pack.skip_images)}); return true;
    case GL_UNPACK_SWAP_BYTES: set({double(ctx.unpack.swap_bytes)}); return true;
    case GL_UNPACK_LSB_FIRST: set({double(ctx.unpack.lsb_first)}); return true;
    case GL_UNPACK_ROW_LENGTH: set({double(ctx.unpack.row_length)}); return true;
    case GL_UNPACK_SKIP_ROWS: set({double(ctx.unpack.skip_rows)}); return true;
    case GL_UNPACK_SKIP_PIXELS: set({double(ctx.unpack.skip_pixels)}); return true;
    case GL_UNPACK_ALIGNMENT: set({double(ctx.unpack.alignment)}); return true;
    case GL_UNPACK_IMAGE_HEIGHT: set({double(ctx.unpack.image_height)}); return true;
    case GL_UNPACK_SKIP_IMAGES: set({double(ctx.unpack.skip_images)}); return true;
    case GL_RED_BITS: case GL_GREEN_BITS: case GL_BLUE_BITS: case GL_ALPHA_BITS: set({8}); return true;
    case GL_DEPTH_BITS: set({double(ctx.depth_bits > 0 ? 24 : 0)}); return true;
    case GL_STENCIL_BITS: set({double(ctx.stencil_bits)}); return true;
    case GL_ACCUM_RED_BITS: case GL_ACCUM_GREEN_BITS: case GL_ACCUM_BLUE_BITS: case GL_ACCUM_ALPHA_BITS:
      set({double(ctx.accum_bits)});
      return true;
    case GL_ACCUM_CLEAR_VALUE: {
      const auto& ac = ctx.accum_clear;
      set({ac[0], ac[1], ac[2], ac[3]}, true);
      return true;
    }
    // The reference as the test uses it: clamped to the buffer's values (0 without one), as Mesa.
    case GL_STENCIL_REF: set({double(std::clamp(ctx.fragment.stencil_ref, 0, (1 << ctx.stencil_bits) - 1))}); return true;
    // Display lists: the list being compiled and its mode (0 when none is), the base; names as
    // GLint, as Mesa keeps them (glListBase(-5) reads back -5).
    case GL_LIST_INDEX: set({double(static_cast<GLint>(ctx.lists.compiling ? ctx.lists.name : 0))}); return true;
    case GL_LIST_MODE:
      set({double(!ctx.lists.compiling ? 0 : ctx.lists.execute ? GL_COMPILE_AND_EXECUTE : GL_COMPILE)});
      return true;
    case GL_LIST_BASE: set({double(static_cast<GLint>(ctx.lists.base))}); return true;
    case GL_MAX_LIST_NESTING: set({double(pf::kMaxListNesting)}); return true;
    case GL_ATTRIB_STACK_DEPTH: set({double(ctx.attrib_stack.size())}); return true;
    case GL_CLIENT_ATTRIB_STACK_DEPTH: set({double(ctx.client_attrib_stack.size())}); return true;
    case GL_MAX_ATTRIB_STACK_DEPTH: case GL_MAX_CLIENT_ATTRIB_STACK_DEPTH: set({double(pf::kMaxAttribStackDepth)}); return true;
    case GL_SUBPIXEL_BITS: set({8}); return true;  // window coordinates snap to 1/256 pixel
    case GL_TEXTURE_1D: set({ctx.textures.a.enabled_1d ? 1.0 : 0.0}); return true;
    case GL_TEXTURE_2D: set({ctx.textures.a.enabled_2d ? 1.0 : 0.0}); return true;
    case GL_TEXTURE_GEN_S: case GL_TEXTURE_GEN_T: case GL_TEXTURE_GEN_R: case GL_TEXTURE_GEN_Q:
      set({ctx.textures.a.gen[pname - GL_TEXTURE_GEN_S].enabled ? 1.0 : 0.0});
      return true;
    case GL_TEXTURE_BINDING_1D: set({double(ctx.textures.a.binding_1d)}); return true;
    case GL_TEXTURE_BINDING_2D: set({double(ctx.textures.a.binding_2d)}); return true;
    case GL_MAX_TEXTURE_SIZE: set({double(pf::kMaxTextureSize)}); return true;
    case GL_SCISSOR_BOX: {
      const int* b = ctx.fragment.scissor;
      set({double(b[0]), double(b[1]), double(b[2]), double(b[3])});
      return true;
    }
    default:
      if (fragmentQuery(ctx.fragment, pname, q) || pf::fogClipQuery(ctx, pname, q) ||
          pf::rasterPosQuery(ctx, pname, q) || pf::rasterModeQuery(ctx.raster_modes, pname, q) ||
          pf::pixelTransferQuery(ctx, pname, q))
        return true;
      if (pname >= GL_LIGHT0 && pname < GL_LIGHT0 + pf::kMaxLights) {
        set({ctx.lighting.lights[pname - GL_LIGHT0].enabled ? 1.0 : 0.0});
        return true;
      }
      if (int hint = pf::hintIndex(pname); hint >= 0) {
        set({double(ctx.hints[hint])});
        return true;
      }
      return arrayQuery(ctx.vertex_array, pname, GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE, GL_VERTEX_ARRAY_STRIDE, q) ||
             arrayQuery(ctx.color_array, pname, GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE, GL_COLOR_ARRAY_STRIDE, q) ||
             arrayQuery(ctx.normal_array, pname, 0, GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY_STRIDE, q) ||
             arrayQuery(ctx.texcoord_array, pname, GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_TYPE,
                        GL_TEXTURE_COORD_ARRAY_STRIDE, q) ||
             pf::constantQuery(pname, q);
  }
}

// The query, or GL_INVALID_ENUM; not between glBegin and glEnd.
const Query* lookup(GLenum pname, Query& q) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return nullptr;
  if (!query(*ctx, pname, q)) {
    ctx->setError(GL_INVALID_ENUM);
    return nullptr;
  }
  return &q;
}

// Rounded to nearest, a half away from zero (Mesa's IROUND: a fog start of 2.5 reads 3, -0.5
// reads -1); a normalised value v as v * (2^31 - 1) truncated toward zero, as Mesa does (0.5
// reads 1073741823).
GLint toInt(double v, bool normalized) {
  if (v != v) return 0;  // NaN
  double r = normalized ? std::trunc(v * 2147483647.0) : std::round(v);
  return static_cast<GLint>(std::clamp(r, -2147483648.0, 2147483647.0));
}

}  // namespace

extern "C" {

void pfglGetBooleanv(GLenum pname, GLboolean* params) {
  Query q;
  if (!lookup(pname, q) || !params) return;
  for (int i = 0; i < q.count; ++i) params[i] = q.v[i] != 0.0 ? GL_TRUE : GL_FALSE;
}

void pfglGetIntegerv(GLenum pname, GLint* params) {
  Query q;
  if (!lookup(pname, q) || !params) return;
  for (int i = 0; i < q.count; ++i) params[i] = toInt(q.v[i], q.normalized);
}

void pfglGetFloatv(GLenum pname, GLfloat* params) {
  Query q;
  if (!lookup(pname, q) || !params) return;
  for (int i = 0; i < q.count; ++i) params[i] = static_cast<GLfloat>(q.v[i]);
}

void pfglGetDoublev(GLenum pname, GLdouble* params) {
  Query q;
  if (!lookup(pname, q) || !params) return;
  for (int i = 0; i < q.count; ++i) params[i] = q.v[i];
}

}  // extern "C"
