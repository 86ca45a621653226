// FieldRayCaster's approximate refinements of a march's brackets (seed 000, section 4.1.1): "we
// split up the domain into chunks and find the first one which contains at least one root ...
// After that, we refine the root using the regula-falsi or the Newton's method", a number of
// iterations fixed in advance instead of bisection down to float resolution. Cheaper per ray,
// and only as exact as the field is smooth near its root: pffields charts both against the
// march's bisection (time against depth error), and tests/field/ray_caster_test.cpp bounds
// their error where the field is smooth.
#include <algorithm>
#include <bit>
#include <cmath>

#include "raster/field/cast_lanes.h"
#include "raster/field/gradient_evaluator.h"
#include "raster/field/ray_caster.h"

namespace pf::field {

namespace {
// Newton converges quadratically from a bracket of a march's step on a smooth field: four steps
// take a relative error of 1e-1 under float resolution. Regula falsi (with the Illinois
// halving, so that one end cannot stay put) converges superlinearly, about 1.44 digits per step.
constexpr int kNewtonSteps = 4;
constexpr int kRegulaFalsiSteps = 6;
}  // namespace

void FieldRayCaster::sampleAndRefine(const ImplicitField& field, RootMethod method, FloatEvaluator& eval,
                                     Lanes& lanes, uint64_t which, const double* from, const double* to, int steps,
                                     FieldCounters& c) {
  double lo[kLanes], hi[kLanes];
  const uint64_t bracketed = sampleForBrackets(eval, lanes, which, from, to, steps, lo, hi, c);
  if (method == RootMethod::Newton) newtonBrackets(field, lanes, bracketed, lo, hi, c);
  else regulaFalsiBrackets(eval, lanes, bracketed, lo, hi, c);
}

// Newton's method along each bracketed lane's ray, from the bracket's middle: t -= f / f', with
// f' = grad f . direction from the gradient form. An iterate that leaves the bracket, or a zero
// or non-finite f', is replaced by the bracket's middle (the bracket shrinking by each iterate's
// sign as it goes), so the result stays in the bracket the march found.
void FieldRayCaster::newtonBrackets(const ImplicitField& field, Lanes& lanes, uint64_t bracketed, double* lo,
                                    double* hi, FieldCounters& c) {
  GradientEvaluator& ge = gradients_;
  if (gradients_field_ != &field) {
    ge.reset(field.tape);
    gradients_field_ = &field;
  }
  double t[kLanes];
  for (uint64_t p = bracketed; p; p &= p - 1) {
    const int i = std::countr_zero(p);
    t[i] = 0.5 * (lo[i] + hi[i]);
  }
  float px[kLanes], py[kLanes], pz[kLanes];
  FieldGradient g[kLanes];
  int index[kLanes];
  for (int step = 0; step < kNewtonSteps && bracketed; ++step) {
    int n = 0;
    for (uint64_t p = bracketed; p; p &= p - 1) {
      const int i = std::countr_zero(p);
      const Vec3d q = lanes.ray[i].at(t[i]);
      px[n] = static_cast<float>(q[0]);
      py[n] = static_cast<float>(q[1]);
      pz[n] = static_cast<float>(q[2]);
      index[n++] = i;
    }
    for (int k = 0; k < n; k += GradientEvaluator::kBatch)
      ge.evaluate(px + k, py + k, pz + k, std::min(n - k, GradientEvaluator::kBatch), g + k);
    c.point_evaluations += n;
    for (int j = 0; j < n; ++j) {
      const int i = index[j];
      const Vec3d& d = lanes.ray[i].direction;
      const double at = t[i], f = g[j].value;
      if (f >= 0.0) hi[i] = at;
      else lo[i] = at;
      if (f == 0.0 || static_cast<float>(lo[i]) == static_cast<float>(hi[i])) {
        lanes.hit(i, f == 0.0 ? at : hi[i]);
        bracketed &= ~(uint64_t(1) << i);
        continue;
      }
      const double slope = g[j].dx * d[0] + g[j].dy * d[1] + g[j].dz * d[2];
      const double next = at - f / slope;
      t[i] = next > lo[i] && next < hi[i] ? next : 0.5 * (lo[i] + hi[i]);
    }
  }
  for (uint64_t p = bracketed; p; p &= p - 1) lanes.hit(std::countr_zero(p), t[std::countr_zero(p)]);
}

// Regula falsi on each bracketed lane: the root of the chord through (lo, f(lo)) and (hi, f(hi)),
// which replaces the end of its sign. When the same end is replaced twice running, the other
// end's f is halved (the Illinois variant): plain regula falsi keeps one end forever on a convex
// stretch and converges only linearly.
void FieldRayCaster::regulaFalsiBrackets(FloatEvaluator& eval, Lanes& lanes, uint64_t bracketed, double* lo,
                                         double* hi, FieldCounters& c) {
  double flo[kLanes], fhi[kLanes], t[kLanes];
  int side[kLanes];
  float f[2 * kLanes];
  int index[kLanes];
  {
    // f at both ends of every bracket, in one batch.
    const int n = lanes.evaluateAt(eval, bracketed, lo, f, index, c);
    const int m = lanes.evaluateAt(eval, bracketed, hi, f + kLanes, index, c);
    (void)m;
    for (int j = 0; j < n; ++j) {
      const int i = index[j];
      flo[i] = f[j];
      fhi[i] = f[kLanes + j];
      side[i] = 0;
      t[i] = hi[i];
    }
  }
  for (int step = 0; step < kRegulaFalsiSteps && bracketed; ++step) {
    for (uint64_t p = bracketed; p; p &= p - 1) {
      const int i = std::countr_zero(p);
      const double denom = fhi[i] - flo[i];
      const double chord = denom > 0.0 && std::isfinite(denom) ? lo[i] - flo[i] * (hi[i] - lo[i]) / denom : 0.5 * (lo[i] + hi[i]);
      t[i] = chord > lo[i] && chord < hi[i] ? chord : 0.5 * (lo[i] + hi[i]);
    }
    const int n = lanes.evaluateAt(eval, bracketed, t, f, index, c);
    for (int j = 0; j < n; ++j) {
      const int i = index[j];
      if (f[j] >= 0.0f) {
        hi[i] = t[i];
        fhi[i] = f[j];
        if (side[i] == 1) flo[i] *= 0.5;
        side[i] = 1;
      } else {
        lo[i] = t[i];
        flo[i] = f[j];
        if (side[i] == -1) fhi[i] *= 0.5;
        side[i] = -1;
      }
      if (f[j] == 0.0f || static_cast<float>(lo[i]) == static_cast<float>(hi[i])) {
        lanes.hit(i, hi[i]);
        bracketed &= ~(uint64_t(1) << i);
      }
    }
  }
  for (uint64_t p = bracketed; p; p &= p - 1) lanes.hit(std::countr_zero(p), t[std::countr_zero(p)]);
}

}  // namespace pf::field
