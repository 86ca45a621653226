// The values of the GL state that programs read (compiler/isa.h: LoadState's StateValue), and
// what a channel layout binds.
#include "raster/raster_state.h"

#include "compiler/compiler.h"
#include "compiler/isa.h"

namespace pf {

float stateValue(const RasterState& s, uint16_t which) {
  const int first = static_cast<int>(StateValue::InvProjection);
  if (which >= first && which < first + 16) return s.inv_projection[which - first];
  if (which >= first + 16 && which < first + 32) return s.projection[which - first - 16];
  if (which >= first + 32 && which < first + 48) return s.inv_modelview[which - first - 32];
  if (which >= first + 48 && which < first + 64) return s.modelview[which - first - 48];
  switch (static_cast<StateValue>(which)) {
    case StateValue::ViewportScaleX: return s.vp_scale_x;
    case StateValue::ViewportOffsetX: return s.vp_offset_x;
    case StateValue::ViewportScaleY: return s.vp_scale_y;
    case StateValue::ViewportOffsetY: return s.vp_offset_y;
    case StateValue::DepthScale: return s.depth_scale;
    case StateValue::DepthOffset: return s.depth_offset;
    case StateValue::DepthNear: return s.depth_near;
    case StateValue::DepthFar: return s.depth_far;
    case StateValue::CullFront: return s.cull_front ? 1.0f : 0.0f;
    case StateValue::CullBack: return s.cull_back ? 1.0f : 0.0f;
    case StateValue::FrontFaceCCW: return s.front_ccw ? 1.0f : 0.0f;
    case StateValue::FlatShading: return s.flat_shading ? 1.0f : 0.0f;
    case StateValue::LineWidth: return s.line_width;
    case StateValue::PointSize: return s.point_size;
    case StateValue::LineStipplePattern: return s.line_stipple_pattern;
    case StateValue::LineStippleFactor: return s.line_stipple_factor;
    case StateValue::LineStippleOn: return s.line_stipple ? 1.0f : 0.0f;
    case StateValue::PolygonModeFront: return s.polygon_mode_front;
    case StateValue::PolygonModeBack: return s.polygon_mode_back;
    case StateValue::OffsetFactor: return s.offset_factor;
    case StateValue::OffsetUnits: return s.offset_units;
    case StateValue::OffsetFill: return s.offset_fill ? 1.0f : 0.0f;
    case StateValue::OffsetLine: return s.offset_line ? 1.0f : 0.0f;
    case StateValue::OffsetPoint: return s.offset_point ? 1.0f : 0.0f;
    case StateValue::PolygonStippleOn: return s.polygon_stipple ? 1.0f : 0.0f;
    default: return 0.0f;
  }
}

bool ChannelLayout::bindsInterpolator(const std::string& name) const {
  for (const SharedInterpolator& s : shared)
    if (s.program->name == name) return true;
  return false;
}

}  // namespace pf
