// The pixel executor's implicit-surface instructions: FieldHit runs the field ray caster over
// the block (raster/field/ray_caster.h), FieldGradient the gradient form, FieldColor the float
// form of the field's attribute tapes (seed 000's procedural colour at the hit point). The rays are the
// pixels' own, rebuilt in double from the state the language's object_ray_near()/_far() read.
#include <algorithm>
#include <cmath>
#include <limits>

#include "raster/field/float_evaluator.h"
#include "raster/lane_count.h"
#include "raster/pixel_executor.h"

namespace pf {
namespace {

using Mat4 = std::array<double, 16>;  // column-major

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row) {
      double s = 0.0;
      for (int k = 0; k < 4; ++k) s += a[k * 4 + row] * b[c * 4 + k];
      r[c * 4 + row] = s;
    }
  return r;
}

Mat4 fromFloats(const float* m) {
  Mat4 r;
  for (int i = 0; i < 16; ++i) r[i] = m[i];
  return r;
}

// Window coordinates to object coordinates: the inverse viewport and depth range, then the
// inverse projection and the inverse modelview (as unscreen(), eye() and object() compose).
field::FieldRays raysOf(const RasterState& s, const float box[6]) {
  Mat4 ndc{};
  ndc[0] = 1.0 / s.vp_scale_x;
  ndc[12] = -static_cast<double>(s.vp_offset_x) / s.vp_scale_x;
  ndc[5] = 1.0 / s.vp_scale_y;
  ndc[13] = -static_cast<double>(s.vp_offset_y) / s.vp_scale_y;
  ndc[10] = 1.0 / s.depth_scale;
  ndc[14] = -static_cast<double>(s.depth_offset) / s.depth_scale;
  ndc[15] = 1.0;
  field::FieldRays rays;
  rays.window_to_object = multiply(fromFloats(s.inv_modelview), multiply(fromFloats(s.inv_projection), ndc));
  rays.depth_near = s.depth_near;
  rays.depth_far = s.depth_far;
  for (int k = 0; k < 3; ++k) {
    rays.box_min[k] = std::min(box[k], box[3 + k]);
    rays.box_max[k] = std::max(box[k], box[3 + k]);
  }
  return rays;
}

}  // namespace

const field::ImplicitField* fieldById(const RasterState& state, float id) {
  const double index = static_cast<double>(id) - 1.0;
  if (!state.fields || !(index >= 0.0) || index >= static_cast<double>(state.fields->size()) || index != std::floor(index))
    return nullptr;
  return (*state.fields)[static_cast<size_t>(index)].get();
}

field::CastRequest fieldCastRequest(const RasterState& state, const field::ImplicitField* f, const float box[6],
                                    float method, float param) {
  field::CastRequest req;
  req.field = f;
  req.rays = raysOf(state, box);
  // (Range-checked before the conversion: a float out of int's range does not convert.)
  const bool valid = method >= 0.0f && method < static_cast<float>(field::kRootMethodCount) && method == std::floor(method);
  req.method = valid ? static_cast<field::RootMethod>(static_cast<int>(method)) : field::RootMethod::Auto;
  req.param = std::isfinite(param) ? param : 0.0f;
  req.iteration_cap = state.iteration_cap;
  return req;
}

float fieldGradientAt(field::GradientEvaluator& ge, const float q[3], int axis, bool by_differences) {
  if (!by_differences) {
    const field::FieldGradient g = ge.evaluate(q[0], q[1], q[2]);
    return axis == 0 ? g.dx : axis == 1 ? g.dy : g.dz;
  }
  // Central differences in double around the float point, with a step of 2^-12 of the point's
  // magnitude (at least 2^-12): for comparison with the derived gradient.
  const double h = std::ldexp(std::max(1.0, static_cast<double>(std::fabs(q[axis]))), -12);
  float a[3] = {q[0], q[1], q[2]}, b[3] = {q[0], q[1], q[2]};
  a[axis] = static_cast<float>(q[axis] + h);
  b[axis] = static_cast<float>(q[axis] - h);
  const double fa = ge.evaluate(a[0], a[1], a[2]).value, fb = ge.evaluate(b[0], b[1], b[2]).value;
  return static_cast<float>((fa - fb) / (static_cast<double>(a[axis]) - b[axis]));
}

const field::ImplicitField* PixelExecutor::lookUpField(const RasterState& state, float id, uint64_t exec) {
  const field::ImplicitField* f = fieldById(state, id);
  if (!f) counters.unknown_field_lanes += static_cast<uint64_t>(laneCount(exec));
  return f;
}

void PixelExecutor::fieldHit(const RasterState& state, int bx, int by, uint64_t exec, float field_id, float method,
                             float param, float* t) {
  std::fill_n(t, kLanes, std::numeric_limits<float>::infinity());
  const field::ImplicitField* f = lookUpField(state, field_id, exec);
  if (!f || !exec) return;
  const field::CastRequest req = fieldCastRequest(state, f, field_box_, method, param);
  const uint64_t capped_before = counters.field.iteration_cap_lanes;
  for (auto& tape : hit_tapes_.tape) tape.reset();
  caster_.castBlock(req, bx, by, exec, t, counters.field, &hit_tapes_);
  hit_serial_ = run_serial_;
  hit_field_ = f;
  hit_lanes_ = exec;
  // Lanes stopped by the iteration cap are reported like a runaway loop's.
  counters.iteration_cap_lanes += counters.field.iteration_cap_lanes - capped_before;
}

void PixelExecutor::fieldGradient(const RasterState& state, uint64_t exec, float field_id, int axis,
                                  bool by_differences, const float* const p[3], const bool p_wide[3], float* out) {
  std::fill_n(out, kLanes, 0.0f);
  const field::ImplicitField* f = lookUpField(state, field_id, exec);
  if (!f) return;
  GradientCache& gc = gradient_cache_;
  // The three components of one field_gradient() come one after the other: the second and
  // third read what the first computed, where the field, the mode and the points are the same.
  bool reuse = axis != 0 && gc.field == f && gc.by_differences == by_differences && (gc.lanes & exec) == exec;
  for (uint64_t m = exec; m && reuse; m &= m - 1) {
    const int i = __builtin_ctzll(m);
    for (int k = 0; k < 3 && reuse; ++k) reuse = gc.q[k][i] == (p_wide[k] ? p[k][i] : p[k][0]);
  }
  if (!reuse) {
    std::unique_ptr<field::GradientEvaluator>& full = gradients_[f];
    if (!full) full = std::make_unique<field::GradientEvaluator>(f->tape);
    // A lane whose point lies in the box of the short tape that found its hit runs that tape:
    // it equals the field there, gradient included (the same side of every min and max).
    const bool hits_usable = hit_serial_ == run_serial_ && hit_field_ == f && !by_differences;
    // Lanes grouped by the tape they run (nullptr: the whole field), each group one batch.
    std::vector<std::pair<const field::FieldTape*, uint64_t>>& groups = gc.groups;
    groups.clear();
    for (uint64_t m = exec; m; m &= m - 1) {
      const int i = __builtin_ctzll(m);
      float q[3];
      for (int k = 0; k < 3; ++k) gc.q[k][i] = q[k] = p_wide[k] ? p[k][i] : p[k][0];
      const field::FieldTape* tape = nullptr;
      if (hits_usable && (hit_lanes_ >> i & 1) && hit_tapes_.tape[i] && hit_tapes_.box[i].contains(q))
        tape = hit_tapes_.tape[i].get();
      auto g = std::find_if(groups.begin(), groups.end(), [&](const auto& e) { return e.first == tape; });
      if (g == groups.end()) g = groups.insert(groups.end(), {tape, 0});
      g->second |= uint64_t(1) << i;
    }
    for (const auto& [tape, lanes] : groups) {
      // A short tape runs on the executor's scratch evaluator, rebuilt for it in place (no
      // allocation once its storage has grown to the tapes' size): the groups' tapes differ.
      if (tape) short_gradient_.reset(*tape);
      field::GradientEvaluator& ge = tape ? short_gradient_ : *full;
      if (by_differences) {
        for (uint64_t m = lanes; m; m &= m - 1) {
          const int i = __builtin_ctzll(m);
          const float q[3] = {gc.q[0][i], gc.q[1][i], gc.q[2][i]};
          for (int k = 0; k < 3; ++k) gc.g[k][i] = fieldGradientAt(ge, q, k, true);
        }
        continue;
      }
      float xs[kLanes], ys[kLanes], zs[kLanes];
      field::FieldGradient g[kLanes];
      int n = 0;
      for (uint64_t m = lanes; m; m &= m - 1, ++n) {
        const int i = __builtin_ctzll(m);
        xs[n] = gc.q[0][i];
        ys[n] = gc.q[1][i];
        zs[n] = gc.q[2][i];
      }
      ge.evaluate(xs, ys, zs, n, g);
      n = 0;
      for (uint64_t m = lanes; m; m &= m - 1, ++n) {
        const int i = __builtin_ctzll(m);
        gc.g[0][i] = g[n].dx;
        gc.g[1][i] = g[n].dy;
        gc.g[2][i] = g[n].dz;
      }
    }
    gc.field = f;
    gc.by_differences = by_differences;
    gc.lanes = exec;
    counters.field.point_evaluations += static_cast<uint64_t>(laneCount(exec)) * (by_differences ? 6 : 1);
  }
  for (uint64_t m = exec; m; m &= m - 1) {
    const int i = __builtin_ctzll(m);
    out[i] = gc.g[axis][i];
  }
}

void PixelExecutor::fieldColor(const RasterState& state, uint64_t exec, float field_id, int component,
                               const float* const p[3], const bool p_wide[3], float* out) {
  std::fill_n(out, kLanes, 1.0f);
  const field::ImplicitField* f = lookUpField(state, field_id, exec);
  if (!f || static_cast<size_t>(component) >= f->attributes.size() || !exec) return;
  const field::FieldTape& tape = f->attributes[static_cast<size_t>(component)];
  std::unique_ptr<field::FloatEvaluator>& fe = attribute_evaluators_[&tape];
  if (!fe) fe = std::make_unique<field::FloatEvaluator>(tape);
  float xs[kLanes], ys[kLanes], zs[kLanes], values[kLanes];
  int n = 0;
  for (uint64_t m = exec; m; m &= m - 1, ++n) {
    const int i = __builtin_ctzll(m);
    xs[n] = p_wide[0] ? p[0][i] : p[0][0];
    ys[n] = p_wide[1] ? p[1][i] : p[1][0];
    zs[n] = p_wide[2] ? p[2][i] : p[2][0];
  }
  fe->evaluate(xs, ys, zs, n, values);
  n = 0;
  for (uint64_t m = exec; m; m &= m - 1, ++n) out[__builtin_ctzll(m)] = values[n];
  counters.field.point_evaluations += static_cast<uint64_t>(n);
}

}  // namespace pf
