// The sound part of the interval method (issue 28): along one pixel's ray through a slab the
// region culling left undecided, the first surface -- with nothing skipped that the interval
// form cannot rule out.
//
// A segment of the ray is discarded only when the interval form proves f < 0 on it (over the
// outward-rounded box of the segment), or proves f monotone along the ray there with both ends
// outside (interval_slope_evaluator.h). An undecided segment is halved, its midpoint evaluated:
// f(mid) >= 0 brackets a crossing in the front half; else both halves are searched, front first.
// A bracket is narrowed the same way -- its front half is proven empty before the search moves
// behind the midpoint, so a sliver that enters and leaves the solid inside a bracket is found
// first; a bracket over which f is proven monotone holds one crossing and goes to plain
// bisection at once. This goes on down to the stated width (RaySearchLimits): a segment still undecided there
// with both ends outside is taken as clear, a bracket that narrow goes to plain bisection. So a
// surface is missed only where the solid is thinner along the ray than the stated width.
//
// Two kinds of field defeat this. Where the enclosure has an infinite end -- the whole line where
// f may be NaN (sqrt or log of a negative part, a division by an interval holding 0), a pole, an
// overflow -- it does not shrink as the segment does and says nothing; a NaN point is outside
// (NaN >= 0 is false), so such segments, once a few sample steps long, are decided by the
// samples, as the march's would be. And where a select or comparison stays undecided along a
// stretch of the ray, its hull keeps the enclosure wide however short the segment: a lane that
// has spent its share of interval evaluations (soft_budget) leaves what is still undecided to
// its samples, counted (FieldCounters::segments_left_to_samples; pfrender --stats). The interval evaluations a lane may spend are capped (the
// iteration cap): past it the lane is a runaway, drawn as a miss and counted, as sphere tracing's.
#pragma once

#include <cstdint>

#include "raster/field/field_rays.h"
#include "raster/field/float_evaluator.h"
#include "raster/field/interval_batch.h"
#include "raster/field/interval_evaluator.h"
#include "raster/field/interval_slope_batch.h"
#include "raster/field/interval_slope_evaluator.h"

namespace pf::field {

struct FieldCounters;
struct RayBox;

struct RaySearchLimits {
  double stated_width = 0.0;   // in t: undecided segments are split down to this
  double sample_step = 0.0;    // in t: segments this short where f may be NaN are decided by points
  uint64_t budget = 65536;     // interval evaluations one lane may spend (the iteration cap)
  // Interval evaluations past which a lane's undecided segments are left to its samples (where
  // the enclosures do not shrink).
  uint64_t soft_budget = 256;
  // A bound on |df/dt| over the slab (from its region's rate enclosure; +inf: none): a segment
  // whose ends are outside by f(a), f(b) < 0 is clear when (f(a) + f(b) + K (b - a)) / 2 < 0,
  // the most f can rise between them -- no interval evaluation needed.
  double rate_bound = 0.0;
};

// Whether the rate bound proves [a, b] clear, from f at its ends.
inline bool clearByRateBound(double fa, double fb, double width, double rate_bound) {
  return fa < 0.0 && fb < 0.0 && 0.5 * (fa + fb + rate_bound * width) < 0.0;
}

struct RaySearchOutcome {
  enum Kind {
    Nothing,  // the segment is proven free of surface
    Surface,  // the first surface is at lo (proven inside from there)
    Bracket,  // f(lo) < 0 <= f(hi), hi - lo <= the stated width, nothing before lo
    Runaway,  // the budget ran out at lo: a miss, counted
  } kind = Nothing;
  double lo = 0.0, hi = 0.0;
};

// One segment of one lane's ray, for the batched first steps below.
struct LaneSegment {
  const PixelRay* ray;
  const RaySearchLimits* limits;
  double a, b;
  float fa, fb;
};

class RaySegmentSearch {
 public:
  // The evaluators run the same tape (a region's simplified one, or the field's own); the batch
  // ones too, for the batched first steps.
  RaySegmentSearch(IntervalEvaluator& intervals, IntervalSlopeEvaluator& slopes, FloatEvaluator& points,
                   IntervalBatchEvaluator& interval_batch, IntervalSlopeBatchEvaluator& slope_batch,
                   const FieldRays& rays, FieldCounters& c)
      : intervals_(intervals), slopes_(slopes), points_(points), interval_batch_(interval_batch),
        slope_batch_(slope_batch), rays_(rays), counters_(c) {}

  // The first step of clear() for the segments of the lanes in `which` (at most 64), all at
  // once: the lanes whose whole segment the interval form proves outside -- for which clear()
  // would return Nothing at that step, counting that one evaluation, as here. The others are
  // clear()'s to search, from the start.
  uint64_t provenClear(const LaneSegment* segments, uint64_t which);
  // The first step of refine() for the brackets of the lanes in `which`, all at once: the lanes
  // where f is proven monotone along the ray over the whole bracket -- for which refine() would
  // return the bracket itself at that step, counting that one evaluation, as here.
  uint64_t provenMonotone(const LaneSegment* segments, uint64_t which);

  // The first surface on [a, b] of `ray`, given f(a) = fa < 0 and f(b) = fb < 0 (or NaN) at the
  // points.
  RaySearchOutcome clear(const PixelRay& ray, double a, float fa, double b, float fb, const RaySearchLimits& limits);
  // The first crossing on [a, b], given f(a) = fa < 0 <= f(b) at the points: a bracket no wider
  // than the stated width, or an earlier surface found inside.
  RaySearchOutcome refine(const PixelRay& ray, double a, float fa, double b, const RaySearchLimits& limits);

 private:
  struct Lane {
    const PixelRay* ray;
    const RaySearchLimits* limits;
    uint64_t spent;
    bool left_to_samples;
  };
  RaySearchOutcome clearSegment(Lane& lane, double a, float fa, double b, float fb);
  RaySearchOutcome refineBracket(Lane& lane, double a, float fa, double b);
  float pointAt(const Lane& lane, double t);

  IntervalSlope slopeOver(Lane& lane, const RayBox& box);

  IntervalEvaluator& intervals_;
  IntervalSlopeEvaluator& slopes_;
  FloatEvaluator& points_;
  IntervalBatchEvaluator& interval_batch_;
  IntervalSlopeBatchEvaluator& slope_batch_;
  const FieldRays& rays_;
  FieldCounters& counters_;
};

}  // namespace pf::field
