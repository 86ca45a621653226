// Finding the surface of an implicit instance for the pixels of one block (8x8 lanes): the
// pixel program's field_hit() runs this. Per lane it returns the ray parameter t of the first
// point with f >= 0 on the pixel's ray inside the instance's box (a ray that starts inside the
// solid hits where it enters the box: the box cuts the solid, as HyperFun's does), or +inf.
//
// Methods (implicit_field.h):
//   interval -- Keeter 2020 on the CPU: the tile (64x64 pixels) and then the block is cut into
//     slabs along t, front to back; over each slab's box of ray points the interval form proves
//     the slab empty (skipped), full (hit at its front) or neither, and in the last case the tape
//     is simplified to what can matter there and the region is split further: along t while it
//     is deeper than wide, else into quarters, down to 4x4 pixels. Regions that stay undecided
//     are sampled at steps under half a pixel's footprint and the first sign change is bisected
//     (a feature thinner than that inside an undecided 4x4-pixel slab can be missed). The
//     tile's slabs are computed once and shared by its blocks. Counters say how much was culled
//     and pruned.
//   march -- M uniform steps over the ray's span in the box (the full tape, no culling), then
//     bisection: seed 004's method; M = 1 on a 2D model is plain per-pixel evaluation.
//   sphere -- sphere tracing with the declared Lipschitz bound L: from outside, the surface is at
//     least -f/L away. Each step is checked: f is also evaluated halfway, and a sign change in
//     the step (a crossing it would have skipped) is bisected instead; a change of f faster than
//     L allows raises the lane's L to twice the rate seen and retakes the step from where it
//     began. Both are counted as overshoots: the declared bound was too small.
//   analytic -- where f along the ray is a polynomial of degree <= 4, its first root in the span,
//     by derivative splitting in double (polynomial_roots.h). A lane whose field has no
//     polynomial form falls back to interval, counted.
#pragma once

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "raster/field/field_rays.h"
#include "raster/field/float_evaluator.h"
#include "raster/field/gradient_evaluator.h"
#include "raster/field/implicit_field.h"
#include "raster/field/interval_evaluator.h"
#include "raster/limits.h"

namespace pf::field {

struct CastLanes;

struct FieldCounters {
  uint64_t rays = 0;                  // lanes whose ray meets the box
  uint64_t hits = 0;
  uint64_t point_evaluations = 0;     // float evaluations of the field, one per point
  uint64_t interval_evaluations = 0;  // interval evaluations of a tape over a box
  uint64_t slabs_culled = 0;          // tile or block slabs proven empty
  uint64_t slabs_filled = 0;          // proven entirely inside
  uint64_t slabs_monotone = 0;        // undecided 4x4-pixel slabs where f is proven monotone along the rays
  uint64_t segments_searched = 0;     // lanes' parts of the other undecided slabs, searched ray by ray
  uint64_t segments_left_to_samples = 0;  // ... where the enclosures did not shrink (ray_search.h)
  uint64_t tape_ops_full = 0;         // per sampled block slab: the field's instructions ...
  uint64_t tape_ops_run = 0;          // ... and those its simplified tape kept
  uint64_t lipschitz_overshoots = 0;  // sphere tracing steps that showed the bound too small
  uint64_t analytic_fallbacks = 0;    // analytic lanes without a polynomial form
  uint64_t iteration_cap_lanes = 0;   // lanes stopped by the iteration cap (sphere tracing, march)
  void add(const FieldCounters& o);
};

// A box of object space, as the interval form saw it (outward-rounded floats).
struct HitBox {
  float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool contains(const float p[3]) const {
    return lo[0] <= p[0] && p[0] <= hi[0] && lo[1] <= p[1] && p[1] <= hi[1] && lo[2] <= p[2] && p[2] <= hi[2];
  }
};

// Per lane of a cast: the simplified tape that found the lane's hit and the box over which it
// equals the field (tape simplification is exact there), so that the gradient at the hit can
// run the short tape. A null tape: the field's own.
struct HitTapes {
  std::shared_ptr<const FieldTape> tape[kLanes];
  HitBox box[kLanes];
};

struct CastRequest {
  const ImplicitField* field = nullptr;  // must outlive the caster's use (contexts keep fields)
  FieldRays rays;
  RootMethod method = RootMethod::Auto;
  // march: the number of steps M (0: 64); sphere: the Lipschitz bound (0: the field's declared
  // one); analytic and interval: unused.
  float param = 0.0f;
  unsigned iteration_cap = 65536;  // steps per lane: sphere tracing stops there, a march of more is refused
};

class FieldRayCaster {
 public:
  static constexpr int kDefaultMarchSteps = 64;

  FieldRayCaster();
  ~FieldRayCaster();
  FieldRayCaster(FieldRayCaster&&) noexcept;
  FieldRayCaster& operator=(FieldRayCaster&&) noexcept;

  // t for the lanes set in `mask` of the block whose lower-left pixel is (bx, by); lane i is
  // pixel (bx + i % 8, by + i / 8). t_out has 64 entries; lanes outside the mask are left alone.
  // With `tapes`, records for each hit lane the tape that found it (HitTapes).
  void castBlock(const CastRequest& request, int bx, int by, uint64_t mask, float* t_out, FieldCounters& counters,
                 HitTapes* tapes = nullptr);

 private:
  struct Slab;
  struct TileSlabs;
  // Per lane of a sampled slab: f at its last outside sample (lo), and where the first gap
  // between outside samples begins that the rate bound could not prove clear (+inf: none).
  struct SampleGaps {
    double rate_bound = 0.0;
    double open_t[kLanes];
    float open_f[kLanes];
    float f_lo[kLanes];
  };
  using Lanes = CastLanes;

  void castInterval(const CastRequest& r, int bx, int by, Lanes& lanes, FieldCounters& c);
  struct LaneRect {
    int x, y, size;  // lanes [x, x + size) x [y, y + size) of the block
  };
  struct RegionVerdict;
  struct Scratch;
  // The interval form's verdict over a region of rays (ray_caster.cpp).
  static RegionVerdict judgeRegion(const FieldRays& rays, double x0, double y0, double x1, double y1, double ta,
                                   double tb, const std::shared_ptr<const FieldTape>& tape, Scratch& sc,
                                   FieldCounters& c);
  // A region's slab: judged here, or -- `judged` -- already (a tile's blocks judged at once).
  void regionSlab(const CastRequest& r, int bx, int by, const LaneRect& rect, double ta, double tb,
                  const std::shared_ptr<const FieldTape>& tape, int depth, Lanes& lanes, FieldCounters& c,
                  const RegionVerdict* judged = nullptr);
  TileSlabs& tileSlabs(const CastRequest& r, int bx, int by, FieldCounters& c);
  void judgeTileBlocks(const CastRequest& r, const TileSlabs& ts, Slab& slab, FieldCounters& c);
  void sampleAndBisect(FloatEvaluator& eval, Lanes& lanes, uint64_t which, const double* from, const double* to,
                       int steps, FieldCounters& c);
  uint64_t sampleForBrackets(FloatEvaluator& eval, Lanes& lanes, uint64_t which, const double* from, const double* to,
                             int steps, double* lo, double* hi, FieldCounters& c, SampleGaps* gaps = nullptr);
  void bisectBrackets(FloatEvaluator& eval, Lanes& lanes, uint64_t bracketed, double* lo, double* hi, FieldCounters& c);
  // The march's samples, then the brackets refined by `method`, Newton or RegulaFalsi.
  void sampleAndRefine(const ImplicitField& field, RootMethod method, FloatEvaluator& eval, Lanes& lanes,
                       uint64_t which, const double* from, const double* to, int steps, FieldCounters& c);
  // Seed 000's approximate refinements of the march's brackets (bracket_refinement.cpp).
  void newtonBrackets(const ImplicitField& field, Lanes& lanes, uint64_t bracketed, double* lo, double* hi,
                      FieldCounters& c);
  void regulaFalsiBrackets(FloatEvaluator& eval, Lanes& lanes, uint64_t bracketed, double* lo, double* hi,
                           FieldCounters& c);
  void castSphere(const CastRequest& r, int bx, int by, Lanes& lanes, FieldCounters& c);
  void castAnalytic(const CastRequest& r, int bx, int by, Lanes& lanes, FieldCounters& c);
  FloatEvaluator& fullEvaluator(const ImplicitField& field);
  Scratch& scratch();

  std::unordered_map<const ImplicitField*, std::unique_ptr<FloatEvaluator>> full_evaluators_;
  GradientEvaluator gradients_;  // Newton's: the full tape of gradients_field_
  const ImplicitField* gradients_field_ = nullptr;
  std::unique_ptr<TileSlabs> tile_;  // the last tile's slabs (blocks of a tile come together)
  // The interval method's working storage, reused region after region (ray_caster.cpp).
  std::unique_ptr<Scratch> scratch_;
};

}  // namespace pf::field
