// FieldRayCaster: the dispatcher, the interval method's slab hierarchy, and the shared
// sample-and-bisect search (ray_caster.h describes the methods).
#include "raster/field/ray_caster.h"

#include "raster/field/cast_lanes.h"
#include "raster/field/interval_batch.h"
#include "raster/field/ray_box.h"
#include "raster/field/interval_slope_evaluator.h"
#include "raster/field/ray_search.h"
#include "raster/field/tape_pool.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

namespace pf::field {

void FieldCounters::add(const FieldCounters& o) {
  rays += o.rays;
  hits += o.hits;
  point_evaluations += o.point_evaluations;
  interval_evaluations += o.interval_evaluations;
  slabs_culled += o.slabs_culled;
  slabs_filled += o.slabs_filled;
  tape_ops_full += o.tape_ops_full;
  tape_ops_run += o.tape_ops_run;
  lipschitz_overshoots += o.lipschitz_overshoots;
  analytic_fallbacks += o.analytic_fallbacks;
  iteration_cap_lanes += o.iteration_cap_lanes;
  slabs_monotone += o.slabs_monotone;
  segments_searched += o.segments_searched;
  segments_left_to_samples += o.segments_left_to_samples;
}

// The interval form's verdict over the rays through a rectangle of pixel centres for t in
// [ta, tb]: empty (no point of the region in the field's box, or f < 0 throughout), full
// (f >= 0 throughout) or undecided; with the tape simplified for the region's box.
struct FieldRayCaster::RegionVerdict {
  enum Kind { Empty, Full, Undecided } kind = Empty;
  RayBox box;
  std::shared_ptr<const FieldTape> tape;
};

struct FieldRayCaster::Slab {
  double ta = 0.0, tb = 0.0;
  bool full = false;                     // proven inside over the whole tile
  std::shared_ptr<const FieldTape> tape; // simplified for the tile slab's box
  HitBox box;                            // (for full slabs: where the tape holds, for gradients)
  // The tile's 64 blocks judged over this slab at once (judgeTileBlocks), when the first of them
  // reaches it; empty until then.
  std::vector<RegionVerdict> blocks;
};

// One region's judgment after another, with no allocation once grown: the evaluators, rebound
// to each region's tape (judgments and a leaf's search never interleave), the choices of the
// last interval evaluation, and the simplified tapes.
struct FieldRayCaster::Scratch {
  IntervalEvaluator intervals;
  IntervalBatchEvaluator batch;
  IntervalSlopeEvaluator slopes;
  IntervalSlopeBatchEvaluator slope_batch;
  FloatEvaluator points;
  std::vector<Choice> choices;
  TapePool tapes;
};

struct FieldRayCaster::TileSlabs {
  const ImplicitField* field = nullptr;
  FieldRays rays;
  int tx = -1, ty = -1;
  std::vector<Slab> slabs;  // front to back; empty slabs left out
};

namespace {

constexpr int kMaxTileDepth = 6;    // tile slabs: at most 64 along t
constexpr int kMaxBlockDepth = 16;  // block slabs: halvings along t below a tile slab
constexpr int kLeafSize = 4;        // undecided regions stop splitting at 4x4 pixels (measured: 2x faster than 2x2 on the bear)
constexpr int kBisections = 40;  // a bracket shrinks to 2^-40 of its width, or to double precision
// The interval method's stated width (ray_search.h): undecided segments of a ray are split down
// to this fraction of the field box's diagonal; a solid thinner than that along the ray is the
// only kind it can miss.
constexpr double kStatedWidth = 1e-6;
// A lane's share of interval evaluations in one slab's search (RaySearchLimits::soft_budget):
// a crossing narrowed from a sample step to the stated width takes about 2 log2(1000), 20.
constexpr uint64_t kSearchEvaluationsBase = 16, kSearchEvaluationsPerSample = 1;

// The box of the rays through a rectangle of pixel centres [x0, x1] x [y0, y1] for t in
// [a, b]: its four corner rays' points when the rays are affine in the pixel, else the field's
// whole box (sound, and no culling along the ray).
RayBox regionBox(const FieldRays& fr, double x0, double y0, double x1, double y1, double a, double b) {
  const PixelRay c[4] = {fr.unclipped(x0, y0), fr.unclipped(x1, y0), fr.unclipped(x0, y1), fr.unclipped(x1, y1)};
  bool ok = fr.affine();
  for (const PixelRay& r : c) ok = ok && !r.empty();
  if (!ok) {
    RayBox whole;
    whole.x = {roundedDown(fr.box_min[0]), roundedUp(fr.box_max[0])};
    whole.y = {roundedDown(fr.box_min[1]), roundedUp(fr.box_max[1])};
    whole.z = {roundedDown(fr.box_min[2]), roundedUp(fr.box_max[2])};
    return whole;
  }
  const PixelRay* const corners[4] = {&c[0], &c[1], &c[2], &c[3]};
  return rayBoxOf(corners, a, b, fr);
}

double length(const Vec3d& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// Whether cutting [a, b] in two can sharpen the intervals: the field reads a coordinate that
// changes along the rays, and the slab is deeper along the ray than `ratio` times the
// rectangle's width there (slabs end about as deep as they are wide, as Keeter's voxels).
bool worthSplitting(const FieldRays& fr, const ImplicitField& field, double x0, double y0, double x1, double y1,
                    double a, double b, double ratio) {
  const PixelRay mid = fr.unclipped(0.5 * (x0 + x1), 0.5 * (y0 + y1));
  if (mid.empty()) return false;
  bool varies = false;
  for (int k = 0; k < 3; ++k) varies = varies || (field.reads[k] && mid.direction[k] != 0.0);
  if (!varies) return false;
  const double tm = 0.5 * (a + b);
  const PixelRay left = fr.unclipped(x0 - 0.5, y0), right = fr.unclipped(x1 + 0.5, y0);
  const Vec3d pl = left.at(tm), pr = right.at(tm);
  const double width = length({pr[0] - pl[0], pr[1] - pl[1], pr[2] - pl[2]});
  return (b - a) * length(mid.direction) > ratio * width;
}

HitBox hitBoxOf(const RayBox& b) { return {{b.x.lo, b.y.lo, b.z.lo}, {b.x.hi, b.y.hi, b.z.hi}}; }

Interval evaluateBox(IntervalEvaluator& ie, const RayBox& b, std::vector<Choice>* choices) {
  return ie.evaluate(b.x, b.y, b.z, choices);
}


// f and its rate along the rays through a rectangle of pixel centres, over the region's box and
// the box of the rays' directions (the corner rays' hull: directions are affine in the pixel
// where the rays are); the whole line for rays that are not affine.
IntervalSlope regionSlope(IntervalSlopeEvaluator& se, const FieldRays& fr, const RayBox& box, double x0, double y0,
                          double x1, double y1, FieldCounters& c) {
  const IntervalSlope unknown{Interval::whole(), Interval::whole()};
  if (!fr.affine()) return unknown;
  const PixelRay corner[4] = {fr.unclipped(x0, y0), fr.unclipped(x1, y0), fr.unclipped(x0, y1), fr.unclipped(x1, y1)};
  Interval d[3];
  for (int k = 0; k < 3; ++k) {
    double lo = corner[0].direction[k], hi = lo;
    for (const PixelRay& ray : corner) {
      if (ray.empty()) return unknown;
      lo = std::min(lo, ray.direction[k]);
      hi = std::max(hi, ray.direction[k]);
    }
    d[k] = {roundedDown(lo), roundedUp(hi)};
  }
  ++c.interval_evaluations;
  return se.evaluate(box.x, box.y, box.z, d[0], d[1], d[2]);
}

// Whether some coordinate the field reads changes along the rays (checked on the centre ray of
// the viewport-independent family: ortho rays are all parallel, perspective ones all diverge).
bool variesAlongRays(const CastRequest& r) {
  const PixelRay ray = r.rays.unclipped(0.0, 0.0);
  for (int k = 0; k < 3; ++k)
    if (r.field->reads[k] && (ray.empty() || ray.direction[k] != 0.0)) return true;
  return !r.rays.affine();
}

}  // namespace

// The tape simplified by the choices (the same tape where nothing was decided: no rebuild for
// fields with few min/max, such as the bear), from the scratch's pool.
FieldRayCaster::RegionVerdict FieldRayCaster::judgeRegion(const FieldRays& rays, double x0, double y0, double x1,
                                                          double y1, double ta, double tb,
                                                          const std::shared_ptr<const FieldTape>& tape, Scratch& sc,
                                                          FieldCounters& c) {
  RegionVerdict v;
  v.box = regionBox(rays, x0, y0, x1, y1, ta, tb);
  if (v.box.empty) return v;
  sc.intervals.reset(*tape);
  const Interval f = evaluateBox(sc.intervals, v.box, &sc.choices);
  ++c.interval_evaluations;
  if (f.allNegative()) {
    ++c.slabs_culled;
    return v;
  }
  v.kind = f.allNonNegative() ? RegionVerdict::Full : RegionVerdict::Undecided;
  v.tape = sc.tapes.simplified(tape, sc.choices);
  return v;
}

// judgeRegion for each 8x8 block of the tile over an undecided tile slab, in one batched
// evaluation (interval_batch.h): the same boxes, the same intervals and choices, so the same
// verdicts and tapes as judging each block when it comes -- one pass over the slab's tape for
// all of them instead of one each.
void FieldRayCaster::judgeTileBlocks(const CastRequest& r, const TileSlabs& ts, Slab& slab, FieldCounters& c) {
  constexpr int kBlocks = (kTileSize / kBlockSize) * (kTileSize / kBlockSize);
  static_assert(kBlocks == IntervalBatchEvaluator::kBoxes, "a tile's blocks are one batch");
  Scratch& sc = scratch();
  slab.blocks.assign(kBlocks, RegionVerdict{});
  IntervalBatchEvaluator::Boxes boxes;
  for (int k = 0; k < kBlocks; ++k) {
    const double x0 = ts.tx + (k % 8) * kBlockSize + 0.5, y0 = ts.ty + (k / 8) * kBlockSize + 0.5;
    RegionVerdict& v = slab.blocks[k];
    v.box = regionBox(r.rays, x0, y0, x0 + kBlockSize - 1, y0 + kBlockSize - 1, slab.ta, slab.tb);
    boxes.x_lo[k] = v.box.x.lo, boxes.x_hi[k] = v.box.x.hi;
    boxes.y_lo[k] = v.box.y.lo, boxes.y_hi[k] = v.box.y.hi;
    boxes.z_lo[k] = v.box.z.lo, boxes.z_hi[k] = v.box.z.hi;
  }
  sc.batch.reset(*slab.tape);
  Interval f[kBlocks];
  sc.batch.evaluate(boxes, kBlocks, f, true);
  for (int k = 0; k < kBlocks; ++k) {
    RegionVerdict& v = slab.blocks[k];
    if (v.box.empty) continue;
    ++c.interval_evaluations;
    if (f[k].allNegative()) {
      ++c.slabs_culled;
      continue;
    }
    v.kind = f[k].allNonNegative() ? RegionVerdict::Full : RegionVerdict::Undecided;
    sc.batch.choicesOf(k, sc.choices);
    v.tape = sc.tapes.simplified(slab.tape, sc.choices);
  }
}

FieldRayCaster::FieldRayCaster() = default;
FieldRayCaster::~FieldRayCaster() = default;
FieldRayCaster::FieldRayCaster(FieldRayCaster&&) noexcept = default;
FieldRayCaster& FieldRayCaster::operator=(FieldRayCaster&&) noexcept = default;

FieldRayCaster::Scratch& FieldRayCaster::scratch() {
  if (!scratch_) scratch_ = std::make_unique<Scratch>();
  return *scratch_;
}

FloatEvaluator& FieldRayCaster::fullEvaluator(const ImplicitField& field) {
  std::unique_ptr<FloatEvaluator>& e = full_evaluators_[&field];
  if (!e) e = std::make_unique<FloatEvaluator>(field.tape);
  return *e;
}

void FieldRayCaster::castBlock(const CastRequest& r, int bx, int by, uint64_t mask, float* t_out, FieldCounters& c,
                               HitTapes* tapes) {
  if (!r.field || r.field->tape.instrs.empty()) return;
  Lanes lanes;
  lanes.pending = 0;
  lanes.tapes = tapes;
  static_assert(kLanes == 64 && kBlockSize == 8, "blockRays fills an 8x8 block");
  r.rays.blockRays(bx, by, lanes.ray);
  for (uint64_t m = mask; m; m &= m - 1) {
    const int i = std::countr_zero(m);
    lanes.t[i] = std::numeric_limits<double>::infinity();
    if (!lanes.ray[i].empty()) lanes.pending |= uint64_t(1) << i;
  }
  c.rays += std::popcount(lanes.pending);
  const uint64_t cast = lanes.pending;
  const RootMethod method = resolveMethod(*r.field, r.method);
  switch (method) {
    case RootMethod::March:
    case RootMethod::Newton:
    case RootMethod::RegulaFalsi: {
      double from[kLanes], to[kLanes];
      for (uint64_t p = lanes.pending; p; p &= p - 1) {
        const int i = std::countr_zero(p);
        from[i] = lanes.ray[i].entry;
        to[i] = lanes.ray[i].exit;
      }
      // Where nothing the field reads changes along the rays (a 2D model seen from above), f at
      // the entry decides the whole ray: one evaluation per pixel.
      const int steps = !variesAlongRays(r) ? 0
                        : r.param >= 1.0f   ? static_cast<int>(std::min(r.param, 1e6f))
                                            : kDefaultMarchSteps;
      // More steps a ray than the iteration cap allows is a runaway, as a sphere-traced ray past
      // the cap is: stopped before it starts, reported, drawn as a miss (1e6 steps of 256 rays
      // took minutes).
      if (static_cast<uint64_t>(steps) > r.iteration_cap) {
        c.iteration_cap_lanes += std::popcount(lanes.pending);
        lanes.pending = 0;
        break;
      }
      FloatEvaluator& eval = fullEvaluator(*r.field);
      if (method == RootMethod::March) {
        sampleAndBisect(eval, lanes, lanes.pending, from, to, steps, c);
        break;
      }
      sampleAndRefine(*r.field, method, eval, lanes, lanes.pending, from, to, steps, c);
      break;
    }
    case RootMethod::Sphere: castSphere(r, bx, by, lanes, c); break;
    case RootMethod::Analytic: castAnalytic(r, bx, by, lanes, c); break;
    case RootMethod::Interval:
    case RootMethod::Auto: castInterval(r, bx, by, lanes, c); break;
  }
  for (uint64_t m = mask; m; m &= m - 1) {
    const int i = std::countr_zero(m);
    const bool found = (cast >> i & 1) && std::isfinite(lanes.t[i]);
    t_out[i] = found ? static_cast<float>(lanes.t[i]) : std::numeric_limits<float>::infinity();
    c.hits += found;
  }
}

FieldRayCaster::TileSlabs& FieldRayCaster::tileSlabs(const CastRequest& r, int bx, int by, FieldCounters& c) {
  const int tx = bx - bx % kTileSize, ty = by - by % kTileSize;
  if (tile_ && tile_->field == r.field && tile_->tx == tx && tile_->ty == ty &&
      std::memcmp(&tile_->rays, &r.rays, sizeof(FieldRays)) == 0)
    return *tile_;
  if (!tile_) tile_ = std::make_unique<TileSlabs>();
  TileSlabs& ts = *tile_;
  ts.field = r.field;
  ts.rays = r.rays;
  ts.tx = tx;
  ts.ty = ty;
  ts.slabs.clear();
  const double x0 = tx + 0.5, y0 = ty + 0.5, x1 = tx + kTileSize - 0.5, y1 = ty + kTileSize - 0.5;
  Scratch& sc = scratch();
  // Front to back: the recursion visits the near half first.
  auto visit = [&](auto&& self, double ta, double tb, std::shared_ptr<const FieldTape> tape, int depth) -> void {
    RegionVerdict v = judgeRegion(r.rays, x0, y0, x1, y1, ta, tb, tape, sc, c);
    if (v.kind == RegionVerdict::Empty) return;
    if (v.kind == RegionVerdict::Undecided && depth < kMaxTileDepth &&
        worthSplitting(r.rays, *r.field, x0, y0, x1, y1, ta, tb, 4.0)) {
      const double tm = 0.5 * (ta + tb);
      self(self, ta, tm, v.tape, depth + 1);
      self(self, tm, tb, v.tape, depth + 1);
      return;
    }
    ts.slabs.push_back({ta, tb, v.kind == RegionVerdict::Full, std::move(v.tape), hitBoxOf(v.box), {}});
  };
  // The field's own tape, not owned (the field outlives the caster's use of it).
  visit(visit, 0.0, 1.0, std::shared_ptr<const FieldTape>(std::shared_ptr<const FieldTape>(), &r.field->tape), 0);
  return ts;
}

void FieldRayCaster::castInterval(const CastRequest& r, int bx, int by, Lanes& lanes, FieldCounters& c) {
  TileSlabs& ts = tileSlabs(r, bx, by, c);
  for (Slab& slab : ts.slabs) {
    if (!lanes.pending) break;
    const uint64_t over = lanes.overlapping(slab.ta, slab.tb);
    if (!over) continue;
    if (slab.full) {
      ++c.slabs_filled;
      lanes.deciding_tape = slab.tape;
      lanes.deciding_box = slab.box;
      for (uint64_t p = over; p; p &= p - 1) {
        const int i = std::countr_zero(p);
        lanes.hit(i, std::max(slab.ta, lanes.ray[i].entry));
      }
      lanes.deciding_tape = nullptr;
      continue;
    }
    // The block's verdict over the slab: judged with the tile's other blocks, at once, when the
    // first of them comes here.
    if (slab.blocks.empty()) judgeTileBlocks(r, ts, slab, c);
    const int k = (by - ts.ty) / kBlockSize * (kTileSize / kBlockSize) + (bx - ts.tx) / kBlockSize;
    regionSlab(r, bx, by, {0, 0, kBlockSize}, slab.ta, slab.tb, slab.tape, 0, lanes, c, &slab.blocks[k]);
  }
}

void FieldRayCaster::regionSlab(const CastRequest& r, int bx, int by, const LaneRect& rect, double ta, double tb,
                                const std::shared_ptr<const FieldTape>& tape, int depth, Lanes& lanes,
                                FieldCounters& c, const RegionVerdict* judged) {
  uint64_t in_rect = 0;
  for (int y = rect.y; y < rect.y + rect.size; ++y)
    for (int x = rect.x; x < rect.x + rect.size; ++x) in_rect |= uint64_t(1) << (y * kBlockSize + x);
  const uint64_t over = lanes.overlapping(ta, tb) & in_rect;
  if (!over) return;
  const double x0 = bx + rect.x + 0.5, y0 = by + rect.y + 0.5;
  const double x1 = x0 + rect.size - 1, y1 = y0 + rect.size - 1;
  Scratch& sc = scratch();
  RegionVerdict own;
  if (!judged) {
    own = judgeRegion(r.rays, x0, y0, x1, y1, ta, tb, tape, sc, c);
    judged = &own;
  }
  const RegionVerdict& v = *judged;
  if (v.kind == RegionVerdict::Empty) return;
  const RayBox& box = v.box;
  const std::shared_ptr<const FieldTape>& simplified = v.tape;
  if (v.kind == RegionVerdict::Full) {
    ++c.slabs_filled;
    lanes.deciding_tape = simplified;
    lanes.deciding_box = hitBoxOf(box);
    for (uint64_t p = over; p; p &= p - 1) {
      const int i = std::countr_zero(p);
      lanes.hit(i, std::max(ta, lanes.ray[i].entry));
    }
    lanes.deciding_tape = nullptr;
    return;
  }
  // Deeper than wide: halve along the ray, near half first (front to back).
  if (depth < kMaxBlockDepth && worthSplitting(r.rays, *r.field, x0, y0, x1, y1, ta, tb, 1.0)) {
    const double tm = 0.5 * (ta + tb);
    regionSlab(r, bx, by, rect, ta, tm, simplified, depth + 1, lanes, c);
    regionSlab(r, bx, by, rect, tm, tb, simplified, depth + 1, lanes, c);
    return;
  }
  // About as deep as wide: quarter the rectangle (its quarters hold different lanes, so their
  // order does not matter), down to kLeafSize pixels -- where the field varies along the rays.
  // Where it does not (a 2D model seen from above), a leaf costs one point a lane, and a
  // quarter's interval evaluation and simplification cost more than the points its shorter
  // tape saves: the block is the leaf.
  if (rect.size > kLeafSize && variesAlongRays(r)) {
    const int h = rect.size / 2;
    for (int q = 0; q < 4; ++q)
      regionSlab(r, bx, by, {rect.x + (q % 2) * h, rect.y + (q / 2) * h, h}, ta, tb, simplified, depth, lanes, c);
    return;
  }
  // An undecided slab a few pixels wide: each lane's part of it is sampled at steps under half
  // a pixel's footprint (in batches across lanes), then searched soundly (ray_search.h): the
  // samples before the first one inside are proven clear by intervals, and the bracket of the
  // first sign change is narrowed with its front halves proven clear, down to the stated width.
  c.tape_ops_full += r.field->tape.size();
  c.tape_ops_run += simplified->size();
  const PixelRay mid = r.rays.unclipped(0.5 * (x0 + x1), 0.5 * (y0 + y1));
  const Vec3d pa = mid.at(0.5 * (ta + tb));
  const PixelRay next = r.rays.unclipped(0.5 * (x0 + x1) + 1.0, 0.5 * (y0 + y1));
  const Vec3d pb = next.at(0.5 * (ta + tb));
  const double pixel = length({pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]});
  const double depth_len = (tb - ta) * length(mid.direction);
  // Where nothing the field reads changes along the ray (a 2D model seen from above), the
  // slab's first point decides the whole lane.
  bool varies = false;
  for (int k = 0; k < 3; ++k) varies = varies || (r.field->reads[k] && mid.direction[k] != 0.0);
  const int steps = !varies ? 0
                    : pixel > 0.0 ? static_cast<int>(std::clamp(std::ceil(depth_len / (0.5 * pixel)), 1.0, 256.0))
                                  : 16;
  double from[kLanes], to[kLanes], lo[kLanes], hi[kLanes];
  for (uint64_t p = over; p; p &= p - 1) {
    const int i = std::countr_zero(p);
    from[i] = std::max(ta, lanes.ray[i].entry);
    to[i] = std::min(tb, lanes.ray[i].exit);
  }
  FloatEvaluator& fe = sc.points;
  fe.reset(*simplified);
  lanes.deciding_tape = simplified;
  lanes.deciding_box = hitBoxOf(box);
  if (!varies) {
    bisectBrackets(fe, lanes, sampleForBrackets(fe, lanes, over, from, to, 0, lo, hi, c), lo, hi, c);
    lanes.deciding_tape = nullptr;
    return;
  }
  IntervalSlopeEvaluator& se = sc.slopes;
  se.reset(*simplified);
  const IntervalSlope slope = regionSlope(se, r.rays, box, x0, y0, x1, y1, c);
  // f proven monotone along every ray of the slab: one crossing at most per lane, found from
  // the lane's two ends -- no samples, no search.
  if (slope.monotone()) {
    ++c.slabs_monotone;
    bisectBrackets(fe, lanes, sampleForBrackets(fe, lanes, over, from, to, 1, lo, hi, c), lo, hi, c);
    lanes.deciding_tape = nullptr;
    return;
  }
  SampleGaps gaps;
  const bool continuous = !slope.rate.isWhole() && std::isfinite(slope.value.lo) && std::isfinite(slope.value.hi);
  gaps.rate_bound = continuous ? std::max(std::fabs(slope.rate.lo), std::fabs(slope.rate.hi))
                               : std::numeric_limits<double>::infinity();

  const uint64_t sampled = lanes.pending & over;
  uint64_t bracketed = sampleForBrackets(fe, lanes, over, from, to, steps, lo, hi, c, &gaps);
  IntervalEvaluator& ie = sc.intervals;
  ie.reset(*simplified);
  sc.batch.reset(*simplified);
  sc.slope_batch.reset(*simplified);
  RaySegmentSearch search(ie, se, fe, sc.batch, sc.slope_batch, r.rays, c);
  const double diagonal = length({r.rays.box_max[0] - r.rays.box_min[0], r.rays.box_max[1] - r.rays.box_min[1],
                                  r.rays.box_max[2] - r.rays.box_min[2]});
  // Lanes still pending after the samples: those with a bracket, and those with no sample
  // inside. The gaps before the first one the rate bound cannot clear are clear; the others
  // are searched (the first step of every lane's search at once, batched, the rest lane by
  // lane), then the brackets of the lanes that found nothing before them are narrowed (their
  // first step batched too). Each lane's outcome is what searching it alone gives.
  const uint64_t searching = sampled & lanes.pending;
  RaySearchLimits limits[kLanes];
  RaySearchOutcome found[kLanes];
  LaneSegment segment[kLanes];
  uint64_t open = 0;
  for (uint64_t p = searching; p; p &= p - 1) {
    const int i = std::countr_zero(p);
    const PixelRay& ray = lanes.ray[i];
    RaySearchLimits& l = limits[i];
    l.stated_width = kStatedWidth * diagonal / length(ray.direction);
    l.sample_step = (to[i] - from[i]) / steps;
    l.budget = r.iteration_cap;
    l.rate_bound = gaps.rate_bound;
    l.soft_budget = kSearchEvaluationsPerSample * static_cast<uint64_t>(steps + 1) + kSearchEvaluationsBase;
    found[i] = RaySearchOutcome{};
    if (!std::isinf(gaps.open_t[i])) {
      open |= uint64_t(1) << i;
      segment[i] = {&ray, &l, gaps.open_t[i], lo[i], gaps.open_f[i], gaps.f_lo[i]};
    }
  }
  const uint64_t cleared = search.provenClear(segment, open);

  for (uint64_t p = open; p; p &= p - 1) {
    const int i = std::countr_zero(p);
    ++c.segments_searched;
    if (!(cleared >> i & 1))
      found[i] = search.clear(lanes.ray[i], gaps.open_t[i], gaps.open_f[i], lo[i], gaps.f_lo[i], limits[i]);
  }
  uint64_t narrowing = 0;
  for (uint64_t p = searching & bracketed; p; p &= p - 1) {
    const int i = std::countr_zero(p);
    if (found[i].kind != RaySearchOutcome::Nothing) continue;
    narrowing |= uint64_t(1) << i;
    segment[i] = {&lanes.ray[i], &limits[i], lo[i], hi[i], gaps.f_lo[i], 0.0f};
  }
  const uint64_t monotone = search.provenMonotone(segment, narrowing);
  for (uint64_t p = narrowing; p; p &= p - 1) {
    const int i = std::countr_zero(p);
    found[i] = monotone >> i & 1 ? RaySearchOutcome{RaySearchOutcome::Bracket, lo[i], hi[i]}
                                 : search.refine(lanes.ray[i], lo[i], gaps.f_lo[i], hi[i], limits[i]);
  }
  for (uint64_t p = searching; p; p &= p - 1) {
    const int i = std::countr_zero(p);
    bracketed &= ~(uint64_t(1) << i);
    switch (found[i].kind) {
      case RaySearchOutcome::Nothing: break;  // stays pending: a later slab may hold its surface
      case RaySearchOutcome::Surface: lanes.hit(i, found[i].lo); break;
      case RaySearchOutcome::Runaway: lanes.pending &= ~(uint64_t(1) << i); break;  // a miss, counted
      case RaySearchOutcome::Bracket:
        lo[i] = found[i].lo;
        hi[i] = found[i].hi;
        bracketed |= uint64_t(1) << i;
        break;
    }
  }
  bisectBrackets(fe, lanes, bracketed, lo, hi, c);
  lanes.deciding_tape = nullptr;
}

// For each lane in `which`: samples t_k = from + k (to - from) / steps, k = 0..steps (steps = 0:
// only `from`), in batches across lanes; the first sample with f >= 0 ends the lane at `from` if
// it is the first, else brackets it: [lo, hi] = [t_(k-1), t_k], the lane's bit set in the result.
// Lanes with no sample inside are neither. With `gaps`, also notes per lane f(lo) and the first
// gap between outside samples that the rate bound does not prove clear (SampleGaps).
uint64_t FieldRayCaster::sampleForBrackets(FloatEvaluator& eval, Lanes& lanes, uint64_t which, const double* from,
                                           const double* to, int steps, double* lo, double* hi, FieldCounters& c,
                                           SampleGaps* gaps) {
  float f[kLanes];
  int index[kLanes];
  uint64_t searching = which, bracketed = 0;
  double tk[kLanes];
  for (int k = 0; k <= steps && searching; ++k) {
    for (uint64_t p = searching; p; p &= p - 1) {
      const int i = std::countr_zero(p);
      tk[i] = k == 0 ? from[i] : k == steps ? to[i] : from[i] + (to[i] - from[i]) * (static_cast<double>(k) / steps);
    }
    const int n = lanes.evaluateAt(eval, searching, tk, f, index, c);
    for (int j = 0; j < n; ++j) {
      const int i = index[j];
      if (f[j] >= 0.0f) {
        searching &= ~(uint64_t(1) << i);
        if (k == 0) {
          lanes.hit(i, from[i]);
        } else {
          hi[i] = tk[i];
          bracketed |= uint64_t(1) << i;
        }
        continue;
      }
      if (gaps) {
        if (k == 0) {
          gaps->open_t[i] = std::numeric_limits<double>::infinity();
        } else if (std::isinf(gaps->open_t[i]) &&
                   !clearByRateBound(gaps->f_lo[i], f[j], tk[i] - lo[i], gaps->rate_bound)) {
          gaps->open_t[i] = lo[i];
          gaps->open_f[i] = gaps->f_lo[i];
        }
        gaps->f_lo[i] = f[j];
      }
      lo[i] = tk[i];
    }
  }
  return bracketed;
}

// Bisects each bracket f(lo) < 0 <= f(hi) of the lanes in `bracketed` to the float the lane's t
// is returned as, or to the double precision of t (at most kBisections halvings), and ends the
// lane at its upper end.
void FieldRayCaster::bisectBrackets(FloatEvaluator& eval, Lanes& lanes, uint64_t bracketed, double* lo, double* hi,
                                    FieldCounters& c) {
  float f[kLanes];
  int index[kLanes];
  for (int it = 0; it < kBisections && bracketed; ++it) {
    double mid[kLanes];
    for (uint64_t p = bracketed; p; p &= p - 1) {
      const int i = std::countr_zero(p);
      mid[i] = 0.5 * (lo[i] + hi[i]);
    }
    const int n = lanes.evaluateAt(eval, bracketed, mid, f, index, c);
    for (int j = 0; j < n; ++j) {
      const int i = index[j];
      if (f[j] >= 0.0f) hi[i] = mid[i];
      else lo[i] = mid[i];
      // Done at double precision, or once both ends round to the same float: the lane's t
      // leaves the caster as a float (castBlock), and every t between the ends rounds to that
      // float too -- further halvings could not change it (rounding is monotone).
      if (!(hi[i] - lo[i] > 1e-12 * std::max(1.0, std::fabs(hi[i]))) ||
          static_cast<float>(lo[i]) == static_cast<float>(hi[i])) {
        lanes.hit(i, hi[i]);
        bracketed &= ~(uint64_t(1) << i);
      }
    }
  }
  for (uint64_t p = bracketed; p; p &= p - 1) lanes.hit(std::countr_zero(p), hi[std::countr_zero(p)]);
}

// The march's search: the first sign change among the samples, bisected. Lanes that found
// nothing in [from, to] stay pending: a later slab may hold their surface.
void FieldRayCaster::sampleAndBisect(FloatEvaluator& eval, Lanes& lanes, uint64_t which, const double* from,
                                     const double* to, int steps, FieldCounters& c) {
  double lo[kLanes], hi[kLanes];
  const uint64_t bracketed = sampleForBrackets(eval, lanes, which, from, to, steps, lo, hi, c);
  bisectBrackets(eval, lanes, bracketed, lo, hi, c);
}

}  // namespace pf::field
