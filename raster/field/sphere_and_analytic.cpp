// FieldRayCaster's sphere tracing and analytic methods (ray_caster.h describes both).
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "raster/field/cast_lanes.h"
#include "raster/field/polynomial_roots.h"
#include "raster/field/ray_caster.h"
#include "raster/field/ray_polynomial.h"

namespace pf::field {

namespace {
double norm(const Vec3d& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
}  // namespace

// Batched across lanes: each iteration evaluates f halfway along and at the end of every
// tracing lane's step. From outside (f < 0) the surface is at least -f / L away, so the step is
// that distance. f >= 0 at the entry is a hit there. A sign change at the halfway point or the
// end brackets the first crossing, which is bisected. |f| changing faster than L along the step
// shows the bound is wrong: the lane's L becomes twice the rate seen and the step is retaken
// (shorter). A step under a millionth of the span counts as arrival.
void FieldRayCaster::castSphere(const CastRequest& r, int bx, int by, Lanes& lanes, FieldCounters& c) {
  const double declared = r.param > 0.0f ? r.param : r.field->lipschitz;
  if (!(declared > 0.0)) {  // no bound: sphere tracing is not sound for this field
    castInterval(r, bx, by, lanes, c);
    return;
  }
  FloatEvaluator& eval = fullEvaluator(*r.field);
  double t[kLanes], f0[kLanes], speed[kLanes], L[kLanes], step[kLanes];
  double from[kLanes], to[kLanes];
  float px[2 * kLanes], py[2 * kLanes], pz[2 * kLanes], f[2 * kLanes];
  int index[kLanes];
  uint64_t tracing = 0, bracketed = 0;
  // f at each entry: inside there is a hit at once.
  {
    double entry[kLanes];
    for (uint64_t p = lanes.pending; p; p &= p - 1) entry[std::countr_zero(p)] = lanes.ray[std::countr_zero(p)].entry;
    const int n = lanes.evaluateAt(eval, lanes.pending, entry, f, index, c);
    for (int j = 0; j < n; ++j) {
      const int i = index[j];
      if (f[j] >= 0.0f) {
        lanes.hit(i, lanes.ray[i].entry);
        continue;
      }
      if (std::isnan(f[j])) continue;  // no distance to step by: a miss (it stepped NaN to the cap)
      t[i] = lanes.ray[i].entry;
      f0[i] = f[j];
      speed[i] = norm(lanes.ray[i].direction);  // object units per unit of t
      L[i] = declared;
      tracing |= uint64_t(1) << i;
    }
  }
  unsigned iterations = 0;
  for (; tracing && iterations < r.iteration_cap; ++iterations) {
    int n = 0;
    for (uint64_t p = tracing; p; p &= p - 1) {
      const int i = std::countr_zero(p);
      const PixelRay& ray = lanes.ray[i];
      step[i] = std::min(-f0[i] / L[i] / speed[i], ray.exit - t[i]);
      for (int half = 1; half <= 2; ++half) {
        const Vec3d q = ray.at(t[i] + step[i] * (half * 0.5));
        px[2 * n + half - 1] = static_cast<float>(q[0]);
        py[2 * n + half - 1] = static_cast<float>(q[1]);
        pz[2 * n + half - 1] = static_cast<float>(q[2]);
      }
      index[n++] = i;
    }
    for (int k = 0; k < 2 * n; k += kLanes) eval.evaluate(px + k, py + k, pz + k, std::min(kLanes, 2 * n - k), f + k);
    c.point_evaluations += 2 * n;
    for (int j = 0; j < n; ++j) {
      const int i = index[j];
      const uint64_t bit = uint64_t(1) << i;
      const PixelRay& ray = lanes.ray[i];
      const double fm = f[2 * j], fe = f[2 * j + 1];
      const double dist = 0.5 * step[i] * speed[i];
      if (std::isnan(fm) || std::isnan(fe)) {  // into a region where f is NaN: inside nothing, a miss
        if (!(fm >= 0.0 || fe >= 0.0)) {
          tracing &= ~bit;
          continue;
        }
      }
      if (fm >= 0.0 || fe >= 0.0) {  // a crossing in this step
        tracing &= ~bit;
        if (fm >= 0.0 || fe > 1e-5) ++c.lipschitz_overshoots;  // the step went past the surface
        from[i] = fm >= 0.0 ? t[i] : t[i] + 0.5 * step[i];
        to[i] = fm >= 0.0 ? t[i] + 0.5 * step[i] : t[i] + step[i];
        bracketed |= bit;
        continue;
      }
      const double rate = std::max(std::fabs(fm - f0[i]), std::fabs(fe - fm)) / dist;
      if (rate > L[i] * (1.0 + 1e-6)) {  // f changed faster than the bound allows
        ++c.lipschitz_overshoots;
        L[i] = 2.0 * rate;
        continue;
      }
      t[i] += step[i];
      f0[i] = fe;
      if (t[i] >= ray.exit) {
        tracing &= ~bit;  // left the box: no surface on this ray
      } else if (-f0[i] / L[i] / speed[i] < 1e-7 * (ray.exit - ray.entry)) {
        tracing &= ~bit;  // arrived: within a ten-millionth of the span of the surface
        lanes.hit(i, t[i]);
      }
    }
  }
  if (tracing) {
    c.iteration_cap_lanes += std::popcount(tracing);
    lanes.pending &= ~tracing;  // stopped: reported, drawn as a miss
  }
  if (bracketed) sampleAndBisect(eval, lanes, bracketed, from, to, 1, c);
  // Lanes that left the box stay pending with t = +inf: a miss.
}

// Per lane in double: the ray polynomial's first root in the lane's span, or for a CSG tree of
// polynomial leaves the first hit among the leaves' roots. Lanes whose field is neither go to
// the interval method.
void FieldRayCaster::castAnalytic(const CastRequest& r, int bx, int by, Lanes& lanes, FieldCounters& c) {
  uint64_t fallback = 0;
  for (uint64_t p = lanes.pending; p; p &= p - 1) {
    const int i = std::countr_zero(p);
    const PixelRay& ray = lanes.ray[i];
    ++c.point_evaluations;
    if (r.field->csg) {
      bool solved = false;
      const auto t = r.field->csg->firstHit(ray.origin, ray.direction, ray.entry, ray.exit, solved);
      if (!solved) fallback |= uint64_t(1) << i;
      else if (t) lanes.hit(i, *t);
      continue;
    }
    const auto poly = rayPolynomial(r.field->tape, ray.origin, ray.direction);
    if (!poly) {
      fallback |= uint64_t(1) << i;
      continue;
    }
    if (poly->evaluate(ray.entry) >= 0.0) {
      lanes.hit(i, ray.entry);
      continue;
    }
    if (auto t = firstRootIn(poly->c, poly->degree, ray.entry, ray.exit)) lanes.hit(i, *t);
  }
  if (fallback) {
    c.analytic_fallbacks += std::popcount(fallback);
    const uint64_t misses = lanes.pending & ~fallback;
    lanes.pending = fallback;
    castInterval(r, bx, by, lanes, c);
    lanes.pending |= misses;
  }
}

}  // namespace pf::field
