// FieldRayCaster against the double-precision reference (dense marching + bisection to 1e-12):
// every method on a sphere, the analytic and interval methods on the tanglecube quartic in
// perspective, interval on the bear; what the counters show; and that results do not depend on
// the order blocks are cast in.
#include <gtest/gtest.h>

#include <cstdio>

#include "compiler/field/fidget_reader.h"
#include "field/field_reference.h"
#include "raster/field/ray_caster.h"

namespace pf::field {
namespace {

using Mat4 = std::array<double, 16>;  // column-major

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int c = 0; c < 4; ++c)
    for (int rr = 0; rr < 4; ++rr)
      for (int k = 0; k < 4; ++k) r[c * 4 + rr] += a[k * 4 + rr] * b[c * 4 + k];
  return r;
}

Mat4 invert(Mat4 m) {  // Gauss-Jordan with partial pivoting on rows of the row-major view
  double a[4][8];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      a[r][c] = m[c * 4 + r];
      a[r][c + 4] = r == c ? 1.0 : 0.0;
    }
  for (int c = 0; c < 4; ++c) {
    int piv = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::fabs(a[r][c]) > std::fabs(a[piv][c])) piv = r;
    std::swap(a[c], a[piv]);
    const double d = a[c][c];
    for (double& v : a[c]) v /= d;
    for (int r = 0; r < 4; ++r) {
      if (r == c) continue;
      const double k = a[r][c];
      for (int j = 0; j < 8; ++j) a[r][j] -= k * a[c][j];
    }
  }
  Mat4 inv{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) inv[c * 4 + r] = a[r][c + 4];
  return inv;
}

// Looking down -z at the box from above it; the image covers the box's x and y extent.
FieldRays orthoRays(int w, int h, const Vec3d& lo, const Vec3d& hi) {
  FieldRays r;
  r.window_to_object = {};
  r.window_to_object[0] = (hi[0] - lo[0]) / w;
  r.window_to_object[12] = lo[0];
  r.window_to_object[5] = (hi[1] - lo[1]) / h;
  r.window_to_object[13] = lo[1];
  r.window_to_object[10] = -(hi[2] - lo[2]);
  r.window_to_object[14] = hi[2];
  r.window_to_object[15] = 1.0;
  r.box_min = lo;
  r.box_max = hi;
  return r;
}

// A camera at (0.3, 0.2, eye_z) looking down -z, 40 degree field of view.
FieldRays perspectiveRays(int w, int h, double eye_z, const Vec3d& lo, const Vec3d& hi) {
  const double n = 0.5, f = 20.0, t = 1.0 / std::tan(20.0 * 3.14159265358979 / 180.0);
  const Mat4 view = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -0.3, -0.2, -eye_z, 1};
  const Mat4 proj = {t * h / w, 0, 0, 0, 0, t, 0, 0, 0, 0, (f + n) / (n - f), -1, 0, 0, 2 * f * n / (n - f), 0};
  const Mat4 viewport = {w / 2.0, 0, 0, 0, 0, h / 2.0, 0, 0, 0, 0, 0.5, 0, w / 2.0, h / 2.0, 0.5, 1};
  FieldRays r;
  r.window_to_object = invert(multiply(viewport, multiply(proj, view)));
  r.box_min = lo;
  r.box_max = hi;
  return r;
}

FieldTape sphereTape(float radius) {
  FieldTapeBuilder b;
  uint32_t r2 = b.binary(FieldOp::Add, b.unary(FieldOp::Square, b.x()), b.unary(FieldOp::Square, b.y()));
  r2 = b.binary(FieldOp::Add, r2, b.unary(FieldOp::Square, b.z()));
  return b.finish(b.binary(FieldOp::Sub, b.constant(radius * radius), r2));
}

FieldTape model(const std::string& name) {
  DiagnosticLog log;
  return *readFidgetModel(name, testing::readModelText(name), log);
}

struct Comparison {
  int judged = 0, coverage_mismatches = 0;
  double max_depth_error = 0.0;  // in object units along the ray
  FieldCounters counters;
};

// Casts every block of a w x h image and compares with the reference per pixel.
Comparison compare(const ImplicitField& field, const FieldRays& rays, int w, int h, RootMethod method, float param,
                   int reference_steps) {
  FieldRayCaster caster;
  CastRequest req;
  req.field = &field;
  req.rays = rays;
  req.method = method;
  req.param = param;
  Comparison cmp;
  for (int by = 0; by < h; by += 8)
    for (int bx = 0; bx < w; bx += 8) {
      uint64_t mask = 0;
      for (int i = 0; i < 64; ++i)
        if (bx + i % 8 < w && by + i / 8 < h) mask |= uint64_t(1) << i;
      float t[64];
      caster.castBlock(req, bx, by, mask, t, cmp.counters);
      for (int i = 0; i < 64; ++i) {
        if (!(mask >> i & 1)) continue;
        const PixelRay ray = rays.ray(bx + i % 8 + 0.5, by + i / 8 + 0.5);
        const double want = testing::referenceHit(field.tape, ray.origin, ray.direction, ray.entry, ray.exit, reference_steps);
        ++cmp.judged;
        if (std::isinf(want) != std::isinf(t[i])) {
          ++cmp.coverage_mismatches;
          continue;
        }
        if (std::isinf(want)) continue;
        const double len = std::sqrt(ray.direction[0] * ray.direction[0] + ray.direction[1] * ray.direction[1] +
                                     ray.direction[2] * ray.direction[2]);
        cmp.max_depth_error = std::max(cmp.max_depth_error, std::fabs(t[i] - want) * len);
      }
    }
  return cmp;
}

TEST(FieldRayCaster, EveryMethodFindsTheSphere) {
  const ImplicitField sphere("sphere", sphereTape(1.0f), 4.2f);  // |grad| = 2r <= 2 sqrt(3) 1.2 in the box
  const Vec3d lo = {-1.2, -1.2, -1.2}, hi = {1.2, 1.2, 1.2};
  const FieldRays rays = orthoRays(40, 40, lo, hi);
  for (RootMethod m : {RootMethod::Auto, RootMethod::Analytic, RootMethod::Interval, RootMethod::March, RootMethod::Sphere}) {
    SCOPED_TRACE(std::string(rootMethodName(m)));
    const Comparison c = compare(sphere, rays, 40, 40, m, m == RootMethod::March ? 256.0f : 0.0f, 4000);
    std::printf("sphere %-8s: %d pixels, %d coverage mismatches, max depth error %.3g\n",
                std::string(rootMethodName(m)).c_str(), c.judged, c.coverage_mismatches, c.max_depth_error);
    EXPECT_EQ(c.coverage_mismatches, 0);
    EXPECT_LT(c.max_depth_error, 2e-5);
    EXPECT_GT(c.counters.hits, 850u);  // the disk of radius 1 in a 2.4-wide image: 872 pixels
  }
}

TEST(FieldRayCaster, TanglecubeInPerspectiveAnalyticAndInterval) {
  const ImplicitField tangle("tanglecube", model("fidget/tanglecube.vm"));
  EXPECT_EQ(resolveMethod(tangle, RootMethod::Auto), RootMethod::Analytic);
  const Vec3d lo = {-4, -4, -4}, hi = {4, 4, 4};
  const FieldRays rays = perspectiveRays(48, 48, 14.0, lo, hi);
  for (RootMethod m : {RootMethod::Analytic, RootMethod::Interval}) {
    SCOPED_TRACE(std::string(rootMethodName(m)));
    const Comparison c = compare(tangle, rays, 48, 48, m, 0.0f, 3000);
    std::printf("tanglecube %-8s: %d pixels, %d coverage mismatches, max depth error %.3g, %llu interval evaluations\n",
                std::string(rootMethodName(m)).c_str(), c.judged, c.coverage_mismatches, c.max_depth_error,
                static_cast<unsigned long long>(c.counters.interval_evaluations));
    EXPECT_LE(c.coverage_mismatches, 1);
    EXPECT_LT(c.max_depth_error, 1e-4);
  }
}

TEST(FieldRayCaster, BearByIntervalsCullsAndPrunes) {
  const ImplicitField bear("bear", model("fidget/bear.vm"));
  EXPECT_EQ(resolveMethod(bear, RootMethod::Auto), RootMethod::Interval);
  const Vec3d lo = {-1, -1, -1}, hi = {1, 1, 1};
  const Comparison c = compare(bear, orthoRays(32, 32, lo, hi), 32, 32, RootMethod::Interval, 0.0f, 1500);
  std::printf("bear interval: %d pixels, %d coverage mismatches, max depth error %.3g; slabs culled %llu, filled %llu; "
              "ops run %llu of %llu\n",
              c.judged, c.coverage_mismatches, c.max_depth_error, static_cast<unsigned long long>(c.counters.slabs_culled),
              static_cast<unsigned long long>(c.counters.slabs_filled),
              static_cast<unsigned long long>(c.counters.tape_ops_run),
              static_cast<unsigned long long>(c.counters.tape_ops_full));
  EXPECT_LE(c.coverage_mismatches, 2);  // features thinner than the reference's step
  EXPECT_LT(c.max_depth_error, 1e-4);
  EXPECT_GT(c.counters.slabs_culled, 0u);
  EXPECT_LT(c.counters.tape_ops_run, c.counters.tape_ops_full);
}

// Sphere tracing with a bound 40x too small still finds the surface (the overshoot is noticed
// and the crossing bisected), and says so in the counters.
TEST(FieldRayCaster, TooSmallALipschitzBoundIsNoticed) {
  const ImplicitField sphere("sphere", sphereTape(1.0f), 0.1f);
  const Vec3d lo = {-1.2, -1.2, -1.2}, hi = {1.2, 1.2, 1.2};
  const Comparison c = compare(sphere, orthoRays(24, 24, lo, hi), 24, 24, RootMethod::Sphere, 0.0f, 4000);
  EXPECT_GT(c.counters.lipschitz_overshoots, 0u);
  EXPECT_EQ(c.coverage_mismatches, 0);
  EXPECT_LT(c.max_depth_error, 2e-5);
}

// Prospero (2D) at 128x128: the interval method's coverage is the plain evaluation's (one march
// step: f at each pixel) exactly -- culling and simplification change no value -- with far fewer
// operations.
TEST(FieldRayCaster, ProsperoIntervalCoverageEqualsPlainEvaluation) {
  const ImplicitField prospero("prospero", model("fidget/prospero.vm"));
  EXPECT_FALSE(prospero.reads[2]);
  const int n = 128;
  const FieldRays rays = orthoRays(n, n, {-1, -1, -1}, {1, 1, 1});
  FieldRayCaster plain, fast;
  CastRequest a, b;
  a.field = b.field = &prospero;
  a.rays = b.rays = rays;
  a.method = RootMethod::March;
  a.param = 1.0f;
  b.method = RootMethod::Interval;
  FieldCounters ca, cb;
  int inside = 0, differ = 0;
  for (int by = 0; by < n; by += 8)
    for (int bx = 0; bx < n; bx += 8) {
      float ta[64], tb[64];
      plain.castBlock(a, bx, by, ~uint64_t(0), ta, ca);
      fast.castBlock(b, bx, by, ~uint64_t(0), tb, cb);
      for (int i = 0; i < 64; ++i) {
        inside += std::isfinite(ta[i]);
        differ += std::isfinite(ta[i]) != std::isfinite(tb[i]);
      }
    }
  std::printf("prospero 128x128: %d inside; point evaluations plain %llu, interval %llu; ops run %llu of %llu\n", inside,
              static_cast<unsigned long long>(ca.point_evaluations), static_cast<unsigned long long>(cb.point_evaluations),
              static_cast<unsigned long long>(cb.tape_ops_run), static_cast<unsigned long long>(cb.tape_ops_full));
  EXPECT_EQ(differ, 0);
  EXPECT_GT(inside, 1000);
  EXPECT_LT(inside, n * n / 2);
  EXPECT_LT(cb.tape_ops_run * 20, cb.tape_ops_full);
}

// The tile cache must not make a block's result depend on which blocks were cast before it.
TEST(FieldRayCaster, BlockResultsDoNotDependOnCastingOrder) {
  const ImplicitField bear("bear", model("fidget/bear.vm"));
  const FieldRays rays = orthoRays(64, 64, {-1, -1, -1}, {1, 1, 1});
  CastRequest req;
  req.field = &bear;
  req.rays = rays;
  req.method = RootMethod::Interval;
  std::vector<float> forward(64 * 64), backward(64 * 64);
  FieldRayCaster a, b;
  FieldCounters c;
  for (int k = 0; k < 64; ++k) a.castBlock(req, (k % 8) * 8, (k / 8) * 8, ~uint64_t(0), &forward[k * 64], c);
  for (int k = 63; k >= 0; --k) b.castBlock(req, (k % 8) * 8, (k / 8) * 8, ~uint64_t(0), &backward[k * 64], c);
  EXPECT_EQ(forward, backward);
}

}  // namespace
}  // namespace pf::field
