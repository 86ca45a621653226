// FieldRayCaster: the dispatcher, the interval method's slab hierarchy, and the shared
// sample-and-bisect search (ray_caster.h describes the methods).
#include "raster/field/ray_caster.h"

#include "raster/field/cast_lanes.h"

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
}

struct FieldRayCaster::Slab {
  double ta = 0.0, tb = 0.0;
  bool full = false;                     // proven inside over the whole tile
  std::shared_ptr<const FieldTape> tape; // simplified for the tile slab's box
  HitBox box;                            // (for full slabs: where the tape holds, for gradients)
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
constexpr int kBisections = 30;  // the bracket shrinks to 2^-30 of a sample step

struct Box {
  Interval x, y, z;
  bool empty = false;
};

float down(double v) { return floatBelow(static_cast<float>(v)); }
float up(double v) { return floatAbove(static_cast<float>(v)); }

// The box of points o + t d, t in [a, b], of the given rays, intersected with the field's box
// and rounded outward (one float step: the double points round to floats within half a step).
template <int N>
Box boxOf(const PixelRay* const (&rays)[N], double a, double b, const FieldRays& fr) {
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::numeric_limits<double>::infinity();
    hi[k] = -lo[k];
  }
  for (const PixelRay* r : rays) {
    for (double t : {a, b}) {
      const Vec3d p = r->at(t);
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
    }
  }
  Box box;
  Interval* axes[3] = {&box.x, &box.y, &box.z};
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::max(lo[k], fr.box_min[k]);
    hi[k] = std::min(hi[k], fr.box_max[k]);
    if (!(lo[k] <= hi[k])) box.empty = true;
    *axes[k] = {down(lo[k]), up(hi[k])};
  }
  return box;
}

// The box of the rays through a rectangle of pixel centres [x0, x1] x [y0, y1] for t in
// [a, b]: its four corner rays' points when the rays are affine in the pixel, else the field's
// whole box (sound, and no culling along the ray).
Box regionBox(const FieldRays& fr, double x0, double y0, double x1, double y1, double a, double b) {
  const PixelRay c[4] = {fr.unclipped(x0, y0), fr.unclipped(x1, y0), fr.unclipped(x0, y1), fr.unclipped(x1, y1)};
  bool ok = fr.affine();
  for (const PixelRay& r : c) ok = ok && !r.empty();
  if (!ok) {
    Box whole;
    whole.x = {down(fr.box_min[0]), up(fr.box_max[0])};
    whole.y = {down(fr.box_min[1]), up(fr.box_max[1])};
    whole.z = {down(fr.box_min[2]), up(fr.box_max[2])};
    return whole;
  }
  const PixelRay* const corners[4] = {&c[0], &c[1], &c[2], &c[3]};
  return boxOf(corners, a, b, fr);
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

// The tape simplified by an interval evaluation's choices -- the same tape where nothing was
// decided (no rebuild for fields with few min/max, such as the bear).
std::shared_ptr<const FieldTape> simplifiedTape(const std::shared_ptr<const FieldTape>& tape,
                                                const std::vector<Choice>& choices) {
  for (Choice c : choices)
    if (c != Choice::Both) return std::make_shared<const FieldTape>(simplify(*tape, choices));
  return tape;
}

HitBox hitBoxOf(const Box& b) { return {{b.x.lo, b.y.lo, b.z.lo}, {b.x.hi, b.y.hi, b.z.hi}}; }

Interval evaluateBox(IntervalEvaluator& ie, const Box& b, std::vector<Choice>* choices) {
  return ie.evaluate(b.x, b.y, b.z, choices);
}

// The interval form's verdict over the rays through a rectangle of pixel centres for t in
// [ta, tb]: empty (no point of the region in the field's box, or f < 0 throughout), full
// (f >= 0 throughout) or undecided; with the tape simplified for the region's box.
struct RegionVerdict {
  enum Kind { Empty, Full, Undecided } kind = Empty;
  Box box;
  std::shared_ptr<const FieldTape> tape;
};

RegionVerdict judgeRegion(const FieldRays& rays, double x0, double y0, double x1, double y1, double ta, double tb,
                          const std::shared_ptr<const FieldTape>& tape, FieldCounters& c) {
  RegionVerdict v;
  v.box = regionBox(rays, x0, y0, x1, y1, ta, tb);
  if (v.box.empty) return v;
  std::vector<Choice> choices;
  IntervalEvaluator ie(*tape);
  const Interval f = evaluateBox(ie, v.box, &choices);
  ++c.interval_evaluations;
  if (f.allNegative()) {
    ++c.slabs_culled;
    return v;
  }
  v.kind = f.allNonNegative() ? RegionVerdict::Full : RegionVerdict::Undecided;
  v.tape = simplifiedTape(tape, choices);
  return v;
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

FieldRayCaster::FieldRayCaster() = default;
FieldRayCaster::~FieldRayCaster() = default;
FieldRayCaster::FieldRayCaster(FieldRayCaster&&) noexcept = default;
FieldRayCaster& FieldRayCaster::operator=(FieldRayCaster&&) noexcept = default;

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
  for (uint64_t m = mask; m; m &= m - 1) {
    const int i = std::countr_zero(m);
    lanes.ray[i] = r.rays.ray(bx + i % kBlockSize + 0.5, by + i / kBlockSize + 0.5);
    lanes.t[i] = std::numeric_limits<double>::infinity();
    if (!lanes.ray[i].empty()) lanes.pending |= uint64_t(1) << i;
  }
  c.rays += std::popcount(lanes.pending);
  const uint64_t cast = lanes.pending;
  switch (resolveMethod(*r.field, r.method)) {
    case RootMethod::March: {
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
      sampleAndBisect(fullEvaluator(*r.field), lanes, lanes.pending, from, to, steps, c);
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

const FieldRayCaster::TileSlabs& FieldRayCaster::tileSlabs(const CastRequest& r, int bx, int by, FieldCounters& c) {
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
  // Front to back: the recursion visits the near half first.
  auto visit = [&](auto&& self, double ta, double tb, std::shared_ptr<const FieldTape> tape, int depth) -> void {
    RegionVerdict v = judgeRegion(r.rays, x0, y0, x1, y1, ta, tb, tape, c);
    if (v.kind == RegionVerdict::Empty) return;
    if (v.kind == RegionVerdict::Undecided && depth < kMaxTileDepth &&
        worthSplitting(r.rays, *r.field, x0, y0, x1, y1, ta, tb, 4.0)) {
      const double tm = 0.5 * (ta + tb);
      self(self, ta, tm, v.tape, depth + 1);
      self(self, tm, tb, v.tape, depth + 1);
      return;
    }
    ts.slabs.push_back({ta, tb, v.kind == RegionVerdict::Full, std::move(v.tape), hitBoxOf(v.box)});
  };
  // The field's own tape, not owned (the field outlives the caster's use of it).
  visit(visit, 0.0, 1.0, std::shared_ptr<const FieldTape>(std::shared_ptr<const FieldTape>(), &r.field->tape), 0);
  return ts;
}

void FieldRayCaster::castInterval(const CastRequest& r, int bx, int by, Lanes& lanes, FieldCounters& c) {
  const TileSlabs& ts = tileSlabs(r, bx, by, c);
  for (const Slab& slab : ts.slabs) {
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
    regionSlab(r, bx, by, {0, 0, kBlockSize}, slab.ta, slab.tb, slab.tape, 0, lanes, c);
  }
}

void FieldRayCaster::regionSlab(const CastRequest& r, int bx, int by, const LaneRect& rect, double ta, double tb,
                                const std::shared_ptr<const FieldTape>& tape, int depth, Lanes& lanes,
                                FieldCounters& c) {
  uint64_t in_rect = 0;
  for (int y = rect.y; y < rect.y + rect.size; ++y)
    for (int x = rect.x; x < rect.x + rect.size; ++x) in_rect |= uint64_t(1) << (y * kBlockSize + x);
  const uint64_t over = lanes.overlapping(ta, tb) & in_rect;
  if (!over) return;
  const double x0 = bx + rect.x + 0.5, y0 = by + rect.y + 0.5;
  const double x1 = x0 + rect.size - 1, y1 = y0 + rect.size - 1;
  const RegionVerdict v = judgeRegion(r.rays, x0, y0, x1, y1, ta, tb, tape, c);
  if (v.kind == RegionVerdict::Empty) return;
  const Box& box = v.box;
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
  // order does not matter), down to kLeafSize pixels.
  if (rect.size > kLeafSize) {
    const int h = rect.size / 2;
    for (int q = 0; q < 4; ++q)
      regionSlab(r, bx, by, {rect.x + (q % 2) * h, rect.y + (q / 2) * h, h}, ta, tb, simplified, depth, lanes, c);
    return;
  }
  // An undecided slab a few pixels wide: sample each lane's part of it at steps under half a
  // pixel's footprint, then bisect the first sign change.
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
  double from[kLanes], to[kLanes];
  for (uint64_t p = over; p; p &= p - 1) {
    const int i = std::countr_zero(p);
    from[i] = std::max(ta, lanes.ray[i].entry);
    to[i] = std::min(tb, lanes.ray[i].exit);
  }
  FloatEvaluator fe(*simplified);
  lanes.deciding_tape = simplified;
  lanes.deciding_box = hitBoxOf(box);
  sampleAndBisect(fe, lanes, over, from, to, steps, c);
  lanes.deciding_tape = nullptr;
}

// For each lane in `which`: samples t_k = from + k (to - from) / steps, k = 0..steps (steps = 0:
// only `from`), in batches
// across lanes; the first sample with f >= 0 ends the lane -- at `from` if it is the first, else
// after bisecting the bracket [t_(k-1), t_k] to the double precision of t.
void FieldRayCaster::sampleAndBisect(FloatEvaluator& eval, Lanes& lanes, uint64_t which, const double* from,
                                     const double* to, int steps, FieldCounters& c) {
  float f[kLanes];
  int index[kLanes];
  double lo[kLanes], hi[kLanes];  // bracket: f(lo) < 0 <= f(hi)
  auto evaluateAt = [&](uint64_t set, const double* ts) { return lanes.evaluateAt(eval, set, ts, f, index, c); };
  uint64_t searching = which, bracketed = 0;
  double tk[kLanes];
  for (int k = 0; k <= steps && searching; ++k) {
    for (uint64_t p = searching; p; p &= p - 1) {
      const int i = std::countr_zero(p);
      tk[i] = k == 0 ? from[i] : k == steps ? to[i] : from[i] + (to[i] - from[i]) * (static_cast<double>(k) / steps);
    }
    const int n = evaluateAt(searching, tk);
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
      } else {
        lo[i] = tk[i];
      }
    }
  }
  for (int it = 0; it < kBisections && bracketed; ++it) {
    double mid[kLanes];
    for (uint64_t p = bracketed; p; p &= p - 1) {
      const int i = std::countr_zero(p);
      mid[i] = 0.5 * (lo[i] + hi[i]);
    }
    const int n = evaluateAt(bracketed, mid);
    for (int j = 0; j < n; ++j) {
      const int i = index[j];
      if (f[j] >= 0.0f) hi[i] = mid[i];
      else lo[i] = mid[i];
      if (!(hi[i] - lo[i] > 1e-12 * std::max(1.0, std::fabs(hi[i])))) {
        lanes.hit(i, hi[i]);
        bracketed &= ~(uint64_t(1) << i);
      }
    }
  }
  for (uint64_t p = bracketed; p; p &= p - 1) lanes.hit(std::countr_zero(p), hi[std::countr_zero(p)]);
  // Lanes that found nothing in [from, to] stay pending: a later slab may hold their surface.
}

}  // namespace pf::field
