// Drawing pixel rectangles as instances of pixel_rectangle (pixel_rectangles.h).
#include "api/src/pixel_rectangles.h"

#include <algorithm>

#include "api/src/commands.h"
#include "api/src/context_state.h"

namespace pf {

PixelRectangles::PixelRectangles(PFcontextRec& ctx, float z) : ctx_(ctx), z_(z) {
  auto mode = ctx.primitives.mode_of.find("pixel_rectangle");
  if (!ctx.color || mode == ctx.primitives.mode_of.end() || ctx.in_begin) return;
  const RasterPosState& r = ctx.raster;
  fragment_.texcoord = r.texcoord;
  fragment_.fog = r.distance;
  // The whole window, not the viewport; no clip planes (the raster position was clipped);
  // smooth (each rectangle's colour is its one sequence point's anyway).
  std::copy(std::begin(ctx.viewport), std::end(ctx.viewport), viewport_);
  std::copy(std::begin(ctx.clip.enabled), std::end(ctx.clip.enabled), clip_enabled_);
  shade_model_ = ctx.shade_model;
  changed_ = true;
  ctx.viewport[0] = ctx.viewport[1] = 0;
  ctx.viewport[2] = ctx.width;
  ctx.viewport[3] = ctx.height;
  std::fill(std::begin(ctx.clip.enabled), std::end(ctx.clip.enabled), false);
  ctx.shade_model = GL_SMOOTH;
  try {
    rect_param_ = ctx.paramId("rect");
  } catch (const std::bad_alloc&) {
    ctx.outOfMemory("a pixel rectangle");
  }
  if (rect_param_ != 0) {
    const ParamValue& saved = ctx.param(rect_param_);
    std::copy(std::begin(saved.v), std::end(saved.v), saved_rect_);
    saved_rect_count_ = saved.count;
    ctx.pixel_fragment = &fragment_;
    cmd::begin(ctx, mode->second);
  }
  drawing_ = ctx.in_begin;
}

void PixelRectangles::add(float x0, float y0, float x1, float y1, const glm::vec4& color, float z) {
  if (!drawing_) return;
  const double rect[5] = {x0, y0, x1, y1, z};
  ctx_.setParamValue(rect_param_, 5, rect);
  for (int k = 0; k < 4; ++k) fragment_.color[k] = std::clamp(color[k], 0.0f, 1.0f);
  cmd::sequencePoint(ctx_);
}

PixelRectangles::~PixelRectangles() {
  if (ctx_.in_begin && drawing_) cmd::end(ctx_);
  if (!changed_) return;
  ctx_.pixel_fragment = nullptr;
  if (rect_param_ != 0) {
    ParamValue& p = ctx_.param(rect_param_);
    std::copy(std::begin(saved_rect_), std::end(saved_rect_), p.v);
    p.count = saved_rect_count_;
  }
  std::copy(std::begin(viewport_), std::end(viewport_), ctx_.viewport);
  std::copy(std::begin(clip_enabled_), std::end(clip_enabled_), ctx_.clip.enabled);
  ctx_.shade_model = shade_model_;
}

}  // namespace pf
