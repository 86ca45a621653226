// RaySegmentSearch: the interval method's per-ray search inside undecided slabs (ray_search.h).
#include "raster/field/ray_search.h"

#include <bit>
#include <cmath>

#include "raster/field/ray_box.h"
#include "raster/field/ray_caster.h"

namespace pf::field {

// How many sample steps long a segment with an unbounded enclosure is left to the samples.
constexpr double kUnboundedSteps = 16.0;

float RaySegmentSearch::pointAt(const Lane& lane, double t) {
  const Vec3d p = lane.ray->at(t);
  ++counters_.point_evaluations;
  return points_.evaluate(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
}

RaySearchOutcome RaySegmentSearch::clear(const PixelRay& ray, double a, float fa, double b, float fb,
                                         const RaySearchLimits& limits) {
  Lane lane{&ray, &limits, 0, false};
  return clearSegment(lane, a, fa, b, fb);
}

RaySearchOutcome RaySegmentSearch::refine(const PixelRay& ray, double a, float fa, double b,
                                          const RaySearchLimits& limits) {
  Lane lane{&ray, &limits, 0, false};
  return refineBracket(lane, a, fa, b);
}

uint64_t RaySegmentSearch::provenClear(const LaneSegment* segments, uint64_t which) {
  IntervalBatchEvaluator::Boxes boxes;
  int lane_of[IntervalBatchEvaluator::kBoxes];
  int n = 0;
  for (uint64_t p = which; p; p &= p - 1) {
    const int i = std::countr_zero(p);
    const LaneSegment& s = segments[i];
    // clear()'s steps before its first evaluation: segments they settle are left to it.
    if (!(s.b > s.a) || clearByRateBound(s.fa, s.fb, s.b - s.a, s.limits->rate_bound) || s.limits->budget == 0)
      continue;
    const PixelRay* const one[1] = {s.ray};
    const RayBox box = rayBoxOf(one, s.a, s.b, rays_);
    if (box.empty) continue;
    boxes.x_lo[n] = box.x.lo, boxes.x_hi[n] = box.x.hi;
    boxes.y_lo[n] = box.y.lo, boxes.y_hi[n] = box.y.hi;
    boxes.z_lo[n] = box.z.lo, boxes.z_hi[n] = box.z.hi;
    lane_of[n++] = i;
  }
  if (n == 0) return 0;
  Interval f[IntervalBatchEvaluator::kBoxes];
  interval_batch_.evaluate(boxes, n, f, false);
  uint64_t clear = 0;
  for (int j = 0; j < n; ++j)
    if (f[j].allNegative()) {
      clear |= uint64_t(1) << lane_of[j];
      ++counters_.interval_evaluations;
    }
  return clear;
}

uint64_t RaySegmentSearch::provenMonotone(const LaneSegment* segments, uint64_t which) {
  IntervalSlopeBatchEvaluator::Boxes pairs;
  int lane_of[IntervalSlopeBatchEvaluator::kBoxes];
  int n = 0;
  const auto axis = [](double v) { return Interval{roundedDown(v), roundedUp(v)}; };
  for (uint64_t p = which; p; p &= p - 1) {
    const int i = std::countr_zero(p);
    const LaneSegment& s = segments[i];
    // refine()'s steps before its first evaluation: brackets they settle are left to it.
    if (!(s.b - s.a > s.limits->stated_width) || s.limits->budget == 0) continue;
    const PixelRay* const one[1] = {s.ray};
    const RayBox box = rayBoxOf(one, s.a, s.b, rays_);
    if (box.empty) continue;
    pairs.x_lo[n] = box.x.lo, pairs.x_hi[n] = box.x.hi;
    pairs.y_lo[n] = box.y.lo, pairs.y_hi[n] = box.y.hi;
    pairs.z_lo[n] = box.z.lo, pairs.z_hi[n] = box.z.hi;
    const Vec3d& d = s.ray->direction;
    const Interval dx = axis(d[0]), dy = axis(d[1]), dz = axis(d[2]);
    pairs.dx_lo[n] = dx.lo, pairs.dx_hi[n] = dx.hi;
    pairs.dy_lo[n] = dy.lo, pairs.dy_hi[n] = dy.hi;
    pairs.dz_lo[n] = dz.lo, pairs.dz_hi[n] = dz.hi;
    lane_of[n++] = i;
  }
  if (n == 0) return 0;
  IntervalSlope slope[IntervalSlopeBatchEvaluator::kBoxes];
  slope_batch_.evaluate(pairs, n, slope);
  uint64_t monotone = 0;
  for (int j = 0; j < n; ++j)
    if (slope[j].monotone()) {
      monotone |= uint64_t(1) << lane_of[j];
      ++counters_.interval_evaluations;
    }
  return monotone;
}

// f and its rate along the lane's ray over a segment's box.
IntervalSlope RaySegmentSearch::slopeOver(Lane& lane, const RayBox& box) {
  ++lane.spent;
  ++counters_.interval_evaluations;
  const Vec3d& d = lane.ray->direction;
  const auto axis = [](double v) { return Interval{roundedDown(v), roundedUp(v)}; };
  return slopes_.evaluate(box.x, box.y, box.z, axis(d[0]), axis(d[1]), axis(d[2]));
}

// Both ends outside (or NaN) by their points. Depth-first, front half first, so the first
// outcome that is not Nothing is the first surface.
RaySearchOutcome RaySegmentSearch::clearSegment(Lane& lane, double a, float fa, double b, float fb) {
  if (!(b > a) || clearByRateBound(fa, fb, b - a, lane.limits->rate_bound)) return {};
  if (lane.spent >= lane.limits->budget) {
    ++counters_.iteration_cap_lanes;
    return {RaySearchOutcome::Runaway, a, a};
  }
  const PixelRay* const one[1] = {lane.ray};
  const RayBox box = rayBoxOf(one, a, b, rays_);
  if (box.empty) return {};
  // The plain enclosure first (a third of the rate's cost where products abound): most
  // segments it proves clear.
  ++lane.spent;
  ++counters_.interval_evaluations;
  const Interval f = intervals_.evaluate(box.x, box.y, box.z);
  if (f.allNegative()) return {};
  // Proven inside although the point at a was not: the points and the enclosure disagree only
  // by rounding, at a surface -- which is then at a.
  if (f.allNonNegative()) return {RaySearchOutcome::Surface, a, a};
  if (slopeOver(lane, box).monotone()) return {};  // outside at both ends and monotone between
  const double width = b - a;
  // An enclosure with an infinite end (the whole line where f may be NaN; a pole, an overflow)
  // does not shrink with the segment: once the segment is a few sample steps long, the samples
  // decide it (NaN is outside), as the march's would.
  if (!(std::isfinite(f.lo) && std::isfinite(f.hi)) && width <= kUnboundedSteps * lane.limits->sample_step) return {};
  // An enclosure that does not shrink either (a select or a comparison undecided all along a
  // stretch of the ray, where its hull stays wide): past the lane's share of interval work, the
  // samples decide what is left. Counted, as the only other way this search falls short.
  if (lane.spent > lane.limits->soft_budget) {
    if (!lane.left_to_samples) ++counters_.segments_left_to_samples;
    lane.left_to_samples = true;
    return {};
  }
  // Undecided at the stated width with both ends outside: a solid this thin along the ray is
  // below the method's resolution (reporting it as surface would put grazing hits up to the
  // enclosure's overestimate over the slope of f in front of the true one).
  if (width <= lane.limits->stated_width) return {};
  const double m = 0.5 * (a + b);
  const float fm = pointAt(lane, m);
  if (fm >= 0.0f) return refineBracket(lane, a, fa, m);
  const RaySearchOutcome front = clearSegment(lane, a, fa, m, fm);
  if (front.kind != RaySearchOutcome::Nothing) return front;
  return clearSegment(lane, m, fm, b, fb);
}

// f(a) < 0 <= f(b): halve, keeping the half that holds the first crossing -- the front one when
// f(mid) >= 0, else the back one once the front one is proven clear.
RaySearchOutcome RaySegmentSearch::refineBracket(Lane& lane, double a, float fa, double b) {
  while (b - a > lane.limits->stated_width) {
    if (lane.spent >= lane.limits->budget) {
      ++counters_.iteration_cap_lanes;
      return {RaySearchOutcome::Runaway, a, a};
    }
    const PixelRay* const one[1] = {lane.ray};
    const RayBox box = rayBoxOf(one, a, b, rays_);
    if (box.empty || slopeOver(lane, box).monotone()) break;  // one crossing: bisect it
    const double m = 0.5 * (a + b);
    if (!(m > a && m < b)) break;  // double resolution of t reached
    const float fm = pointAt(lane, m);
    if (fm >= 0.0f) {
      b = m;
      continue;
    }
    const RaySearchOutcome front = clearSegment(lane, a, fa, m, fm);
    if (front.kind != RaySearchOutcome::Nothing) return front;
    a = m;
    fa = fm;
  }
  return {RaySearchOutcome::Bracket, a, b};
}

}  // namespace pf::field
