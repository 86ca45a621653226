// The GL state a primitive instance is drawn with, snapshotted at submission (binned once per
// change, shared by the instances that follow), and the layout of its shading channels.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "compiler/types.h"
#include "raster/field/implicit_field.h"
#include "raster/fragment_ops.h"

namespace pf {

struct CompiledPrimitive;

// glDepthFunc's comparison (the depth test's and the alpha test's: fragment_ops.h).
using DepthFunc = CompareFunc;

struct RasterState {
  // Viewport and depth-range transform (window = ndc * scale + offset), as screen() uses it.
  float vp_scale_x = 0, vp_offset_x = 0, vp_scale_y = 0, vp_offset_y = 0;
  float depth_scale = 0.5f, depth_offset = 0.5f, depth_near = 0, depth_far = 1;
  int vp_x0 = 0, vp_y0 = 0, vp_x1 = 0, vp_y1 = 0;  // pixel rectangle [x0, x1) x [y0, y1)
  bool depth_test = false;
  bool depth_write = true;
  DepthFunc depth_func = DepthFunc::Less;
  // Polygon state the primitives read (culled(), flat_shading()).
  bool cull_front = false, cull_back = false, front_ccw = true, flat_shading = false;
  // The width of lines and the size of points in whole pixels, as rasterized (line_width(),
  // point_size(); api/src/raster_modes.h rounds and clamps glLineWidth and glPointSize).
  float line_width = 1.0f, point_size = 1.0f;
  // glLineStipple under GL_LINE_STIPPLE (line_stipple()): the 16-bit pattern and the repeat
  // factor, as numbers.
  bool line_stipple = false;
  float line_stipple_pattern = 65535.0f, line_stipple_factor = 1.0f;
  // glPolygonMode per face (polygon_mode(): 0 fill, 1 line, 2 point) and glPolygonOffset
  // (polygon_offset(): the factor, and the units already times the depth resolution r).
  float polygon_mode_front = 0.0f, polygon_mode_back = 0.0f;
  float offset_factor = 0.0f, offset_units = 0.0f;
  bool offset_fill = false, offset_line = false, offset_point = false;
  // Colour channels written (bit k: channel k of RGBA). The renderer keeps one mask per flush,
  // so that the deferred shading pass writes every pixel with the mask its instance had.
  uint8_t color_mask = 0xf;
  // Scissor, alpha test, blending, logic op (fragment_ops.h): a draw with any but the scissor
  // is shaded in submission order, not deferred.
  FragmentOps fragment;
  // Column-major matrices for the space transforms of the language: the inverse projection
  // (clip to eye, eye()), the projection (eye to clip, clip()), and the inverse modelview (eye to
  // object, object(); its transpose takes object normals to eye, eye_normal()).
  float inv_projection[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  float projection[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  float inv_modelview[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  float modelview[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // object to eye
  // Iterations one loop may run per pixel (pixel program) or per instance (setup) before the
  // pixel, or the instance, is stopped and the hit reported.
  uint32_t iteration_cap = 65536;
  // The context's fields (pfglCompileFieldEXT), which field_hit() and field_gradient() name by
  // id (1-based). Owned by the context, which outlives its drawing.
  const field::FieldTable* fields = nullptr;
  // User clip planes (GL 1.5 section 2.11), the enabled ones in window coordinates: a fragment
  // at window (X, Y) and depth z is kept where ((a * X + b * Y) + c * z) + d >= 0 for each of
  // the first clip_plane_count planes (a, b, c, d). ztest() applies them -- a clipped
  // fragment fails it -- so every primitive that tests depth is clipped per pixel
  // (docs/architecture.md, "Fog and clip planes").
  static constexpr int kMaxClipPlanes = 8;
  int clip_plane_count = 0;
  float clip_planes[kMaxClipPlanes][4] = {};
  // The polygon stipple (GL 1.5 section 3.5.2) under GL_POLYGON_STIPPLE, else off with every
  // row 0: polygon_ztest() -- the depth test of the primitives that draw filled polygons --
  // fails the fragment at window (x, y) where bit 31 - (x mod 32) of stipple_rows[y mod 32] is 0
  // (a row's first unpacked byte in bits 31 - 24, its first bit x = 0). ztest() ignores it.
  bool polygon_stipple = false;
  uint32_t stipple_rows[32] = {};

  bool operator==(const RasterState&) const = default;

  // Whether the enabled clip planes keep the fragment at (x, y, z), evaluated as ztest() does.
  bool clipKeeps(float x, float y, float z) const {
    for (int p = 0; p < clip_plane_count; ++p) {
      const float* e = clip_planes[p];
      const float ax = e[0] * x, by = e[1] * y, cz = e[2] * z;
      if (!(((ax + by) + cz) + e[3] >= 0.0f)) return false;
    }
    return true;
  }

  // Whether the polygon stipple keeps the fragment at pixel centre (x, y), as polygon_ztest()
  // and native code decide it: the pixel's integer coordinates (truncated) modulo 32.
  bool stippleKeeps(float x, float y) const {
    const uint32_t row = stipple_rows[static_cast<uint32_t>(static_cast<int32_t>(y)) & 31u];
    return ((row >> (31u - (static_cast<uint32_t>(static_cast<int32_t>(x)) & 31u))) & 1u) != 0;
  }
};

// The state value `which` (compiler/isa.h: StateValue) of `s`, as LoadState reads it.
float stateValue(const RasterState& s, uint16_t which);

// How an instance's per-vertex shading parameters are laid out: `count` channels (floats),
// ordered by interpolation kind (each kind one range), each mapped to a G-buffer slot.
struct ChannelLayout {
  int count = 0;
  int kind_begin[kInterpKindCount] = {0, 0, 0};
  int kind_end[kInterpKindCount] = {0, 0, 0};
  std::vector<int> gbuffer_slot;  // per channel
  // The shared interpolators that fill channels of the Shared kind (4 each, from `first`),
  // and where each one's uniform record sits among the instance's shared records.
  struct SharedInterpolator {
    const CompiledPrimitive* program;
    int first;
    uint32_t record_offset;
    bool operator==(const SharedInterpolator&) const = default;
  };
  std::vector<SharedInterpolator> shared;
  // Per-pixel lighting: the 6 G-buffer slots (P's x, y, z in eye coordinates, then N) from this
  // one, written for primitives that set N; -1: none.
  int surface_slot = -1;
  // Those slots are filled by interpolated channels (vertex primitives lit per pixel), not by
  // the primitive's P and N.
  bool surface_interpolated = false;
  // The lighting reads P (a positional light, a local viewer, two-sided lighting: lightReadsEye):
  // else only N's slots are written, and the shading pass does not read P's. Whoever plans the
  // layout sets it from the lighting the instances are submitted with (the API, at glBegin);
  // false with a lighting that reads P would shade from stale P values.
  bool surface_eye = true;

  // Whether some channels are bound to a shared interpolator called `name`.
  bool bindsInterpolator(const std::string& name) const;

  // Whether some channel is of a kind in `set` (bit 1 << kind).
  bool hasKinds(unsigned set) const {
    for (int k = 0; k < kInterpKindCount; ++k)
      if ((set & (1u << k)) && kind_end[k] > kind_begin[k]) return true;
    return false;
  }

  // `count` channels, all of interpolation kind `kind`, in G-buffer slots 0 .. count - 1.
  static ChannelLayout ofKind(int count, InterpKind kind) {
    ChannelLayout l;
    l.count = count;
    int k = static_cast<int>(kind);
    for (int i = 0; i < kInterpKindCount; ++i) l.kind_begin[i] = l.kind_end[i] = i < k ? 0 : count;
    l.kind_begin[k] = 0;
    for (int i = 0; i < count; ++i) l.gbuffer_slot.push_back(i);
    return l;
  }

  bool operator==(const ChannelLayout&) const = default;
};

}  // namespace pf
