// FieldRayCaster against the double-precision reference (dense marching + bisection to 1e-12):
// every method on a sphere, the analytic and interval methods on the tanglecube quartic in
// perspective, interval on the bear; what the counters show; and that results do not depend on
// the order blocks are cast in.
#include <gtest/gtest.h>

#include <cstdio>

#include "field/cast_comparison.h"

namespace pf::field {
namespace {

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

// Seed 000's approximate search: the march's brackets refined by a fixed number of Newton or
// regula falsi steps instead of bisection. Where the field is smooth at its root (a sphere, the
// tanglecube quartic in perspective), the few steps reach the reference's depth as closely as
// bisection does, with fewer point evaluations; both stay inside the march's bracket, so
// coverage is the march's.
TEST(FieldRayCaster, NewtonAndRegulaFalsiRefineTheMarchsBrackets) {
  const ImplicitField sphere("sphere", sphereTape(1.0f));
  const Vec3d lo = {-1.2, -1.2, -1.2}, hi = {1.2, 1.2, 1.2};
  const FieldRays rays = orthoRays(40, 40, lo, hi);
  const Comparison march = compare(sphere, rays, 40, 40, RootMethod::March, 64.0f, 4000);
  for (RootMethod m : {RootMethod::Newton, RootMethod::RegulaFalsi}) {
    SCOPED_TRACE(std::string(rootMethodName(m)));
    const Comparison c = compare(sphere, rays, 40, 40, m, 64.0f, 4000);
    std::printf("sphere %-12s: %d coverage mismatches, max depth error %.3g, %llu point evaluations (march: %.3g, %llu)\n",
                std::string(rootMethodName(m)).c_str(), c.coverage_mismatches, c.max_depth_error,
                static_cast<unsigned long long>(c.counters.point_evaluations), march.max_depth_error,
                static_cast<unsigned long long>(march.counters.point_evaluations));
    EXPECT_EQ(c.coverage_mismatches, 0);
    EXPECT_LT(c.max_depth_error, 2e-5);
    EXPECT_LT(c.counters.point_evaluations, march.counters.point_evaluations);
  }
  const ImplicitField tangle("tanglecube", model("fidget/tanglecube.vm"));
  const Vec3d tlo = {-4, -4, -4}, thi = {4, 4, 4};
  const FieldRays persp = perspectiveRays(48, 48, 14.0, tlo, thi);
  for (RootMethod m : {RootMethod::Newton, RootMethod::RegulaFalsi}) {
    SCOPED_TRACE(std::string(rootMethodName(m)));
    const Comparison c = compare(tangle, persp, 48, 48, m, 256.0f, 3000);
    std::printf("tanglecube %-12s: %d coverage mismatches, max depth error %.3g\n", std::string(rootMethodName(m)).c_str(),
                c.coverage_mismatches, c.max_depth_error);
    EXPECT_LE(c.coverage_mismatches, 1);
    EXPECT_LT(c.max_depth_error, 1e-4);
  }
  // The names pffields, pfrender --method and scenes use.
  EXPECT_EQ(parseRootMethod("newton"), RootMethod::Newton);
  EXPECT_EQ(parseRootMethod("regula-falsi"), RootMethod::RegulaFalsi);
  EXPECT_EQ(resolveMethod(sphere, RootMethod::Auto), RootMethod::Analytic) << "auto never picks an approximate method";
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
