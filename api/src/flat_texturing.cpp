// glShadeModel(GL_FLAT) on a textured or fogged draw of a GL mode. GL flat-shades the colour only
// (GL 1.5 section 2.14.7): texture and fog coordinates are still interpolated. The primitives' flat_shading()
// takes the provoking vertex's value for every channel of a kind, which would flatten the
// texture and fog coordinates too; so for such a draw the API gives every vertex of each triangle, quad
// or line the colour of that part's provoking vertex itself and draws it smooth. Strips, fans,
// quad strips and line strips and loops share vertices between parts, so they are drawn as the
// independent mode (GL_TRIANGLES, GL_QUADS, GL_LINES) with each part's vertices in the order the
// strip's own primitive passes them to `triangles`, `quad` or `lines` (primitives/*.pfl): the
// same parts, the same windings, the same pixels.
#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include <primflow/gl.h>

#include "api/src/context_state.h"

namespace pf {
namespace {

// The parameters the API feeds a primitive (its count parameter aside), in order.
bool sameFeed(const CompiledPrimitive& a, const CompiledPrimitive& b) {
  auto fed = [](const CompiledPrimitive& p) {
    std::vector<std::pair<std::string, int>> out;
    for (const ParamInfo& i : p.params)
      if (!(p.sequence_points == 0 && !i.per_sequence_point && i.offset == p.count_slot))
        out.push_back({i.name, i.components});
    return out;
  };
  return fed(a) == fed(b);
}

}  // namespace

bool flattenForTexturing(PFcontextRec& ctx) {
  if ((!ctx.begin_texture && ctx.fog_channel < 0) || ctx.color_channel < 0) return false;
  // Not while polygons are drawn unfilled or lines stippled: the independent primitive would
  // fill, or restart the stipple at each segment (the primitive's flat shading applies then).
  const pf::RasterModes& m = ctx.raster_modes;
  if (m.line_stipple || m.polygon_mode[0] != GL_FILL || m.polygon_mode[1] != GL_FILL) return false;
  const size_t n = ctx.rows_count;
  // Each output row: the row it copies and the row whose colour it takes.
  std::vector<std::pair<size_t, size_t>> order;
  GLenum independent = ctx.begin_mode;
  auto part = [&](std::initializer_list<size_t> rows, size_t provoking) {
    for (size_t r : rows) order.push_back({r, provoking});
  };
  switch (ctx.begin_mode) {
    case GL_TRIANGLES:
      for (size_t i = 0; i + 2 < n; i += 3) part({i, i + 1, i + 2}, i + 2);
      break;
    case GL_TRIANGLE_STRIP:
      independent = GL_TRIANGLES;
      for (size_t i = 0; i + 2 < n; ++i) {
        if (i % 2 == 1) part({i + 1, i, i + 2}, i + 2);
        else part({i, i + 1, i + 2}, i + 2);
      }
      break;
    case GL_TRIANGLE_FAN:
      independent = GL_TRIANGLES;
      for (size_t i = 0; i + 2 < n; ++i) part({0, i + 1, i + 2}, i + 2);
      break;
    case GL_QUADS:
      for (size_t i = 0; i + 3 < n; i += 4) part({i, i + 1, i + 2, i + 3}, i + 3);
      break;
    case GL_QUAD_STRIP:
      independent = GL_QUADS;
      // (Under the polygon stipple `quads` rotates each quad by one, llvmpipe's split of
      // GL_QUADS then: the quad given rotated back, so that `quad` gets the strip's order.)
      for (size_t i = 0; i + 3 < n; i += 2) {
        if (m.polygon_stipple) part({i + 2, i, i + 1, i + 3}, i + 3);
        else part({i, i + 1, i + 3, i + 2}, i + 3);
      }
      break;
    case GL_POLYGON:  // the first vertex is a polygon's provoking vertex
      for (size_t i = 0; i < n; ++i) order.push_back({i, 0});
      break;
    case GL_LINES:
      for (size_t i = 0; i + 1 < n; i += 2) part({i, i + 1}, i + 1);
      break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
      independent = GL_LINES;
      for (size_t i = 0; i + 1 < n; ++i) part({i, i + 1}, i + 1);
      if (ctx.begin_mode == GL_LINE_LOOP && n > 1) part({n - 1, 0}, 0);
      break;
    default: return false;  // points (one vertex a part) and the extension's primitives
  }
  auto it = ctx.primitives.by_mode.find(independent);
  if (it == ctx.primitives.by_mode.end() || !sameFeed(*ctx.begin_primitive, *it->second)) return false;
  const CompiledPrimitive& prim = *it->second;
  const size_t stride = static_cast<size_t>(ctx.row_floats), channels = static_cast<size_t>(ctx.row_channels);
  std::vector<uint32_t> rows(order.size() * stride);
  std::vector<float> shading(order.size() * channels);
  for (size_t k = 0; k < order.size(); ++k) {
    const auto [row, provoking] = order[k];
    std::copy_n(ctx.rows.begin() + static_cast<std::ptrdiff_t>(row * stride), stride, rows.begin() + static_cast<std::ptrdiff_t>(k * stride));
    std::copy_n(ctx.row_shading.begin() + static_cast<std::ptrdiff_t>(row * channels), channels,
                shading.begin() + static_cast<std::ptrdiff_t>(k * channels));
    for (int face : {ctx.color_channel, ctx.back_color_channel}) {
      if (face < 0) continue;
      for (size_t c = 0; c < 4; ++c)
        shading[k * channels + static_cast<size_t>(face) + c] = ctx.row_shading[provoking * channels + static_cast<size_t>(face) + c];
    }
  }
  // The feed now names the independent primitive's parameters (the same names and sizes).
  for (FeedEntry& f : ctx.feed) {
    if (f.shared >= 0) continue;
    for (const ParamInfo& p : prim.params)
      if (p.name == f.info->name) f.info = &p;
  }
  ctx.rows.swap(rows);
  ctx.row_shading.swap(shading);
  ctx.rows_count = order.size();
  ctx.begin_primitive = &prim;
  ctx.begin_mode = independent;
  return true;
}

}  // namespace pf
