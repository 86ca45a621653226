// HyperFun's SARDF operations and hfDEllipsoid (compiler/field/hyperfun_sardf.cpp) against
// references written here in double, piece by piece from Fayolle's definitions as
// docs/hyperfun.md states them -- the quartic's root found by scanning and bisection (not by
// Newton, as the tape does), the intersection written out in its own quadrants (not as the
// union's mirror), the ellipsoid's closest point by bisection on its secular equation -- plus
// gradients against central differences and a rendered SARDF union against the reference hit.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "compiler/field/hyperfun_reader.h"
#include "field/cast_comparison.h"
#include "field/field_reference.h"
#include "raster/field/gradient_evaluator.h"

namespace pf::field {
namespace {

FieldTape hyperFun(const std::string& body) {
  DiagnosticLog log;
  auto tape = readHyperFunModel("m.hf", "my_model(x[3], a[1]) {\n" + body + "\n}\n", log, {}, "my_model");
  EXPECT_TRUE(tape) << log.format();
  return tape ? *tape : FieldTape{};
}

double f32(double v) { return static_cast<float>(v); }  // constants on the tape are floats

// The largest root below s of m^4 - 4s m^3 - 4R m^2 - 4s u m - v, by a scan down from s and
// bisection.
double quarticRoot(double R, double u, double v) {
  const double s = std::sqrt(R);
  auto q = [&](double m) { return (((m - 4 * s) * m - 4 * R) * m - 4 * s * u) * m - v; };
  const int n = 4000;
  double hi = s, lo = s;
  for (int k = 1; k <= n; ++k) {
    lo = s * (n - k) / n;
    if (q(lo) >= 0) break;
    hi = lo;
  }
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (q(mid) >= 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double stripe(double x, double y, double r, bool unite) {
  if (y <= x + r && y >= x - r) {
    const double root = std::sqrt(2 * r * r - (x - y) * (x - y));
    return unite ? (x + y + 2 * r - root) / 2 : (x + y - 2 * r + root) / 2;
  }
  if (unite) return y < x - r ? x : y;
  return y < x - r ? y : x;
}

// Fayolle's union with bounded blending (radius r) outside both and the angle approach inside both.
double referenceUnion(double x, double y, double r, double alpha) {
  if (std::fabs(x) < 1e-7 && std::fabs(y) < 1e-7) return 0;
  if (std::fabs(x) < 1e-7) return y > 0 ? y : 0;
  if (std::fabs(y) < 1e-7) return x > 0 ? x : 0;
  if (x < 0 && y > 0) return y;
  if (x > 0 && y < 0) return x;
  if (x > 0 && y > 0) {
    const double t = std::tan(alpha), g = x / y;
    if (g < 1 / t && g > t) {
      const double a = t * t + 2 * t - 1, b = -2 * t * (x + y), c = x * x + y * y;
      return (-b - std::sqrt(b * b - 4 * a * c)) / (2 * a);
    }
    return g >= 1 / t ? x : y;
  }
  const bool bounded = x >= -r || y >= -r ||
                       (x >= -2 * r && y >= -2 * r && (x + 2 * r) * (x + 2 * r) + (y + 2 * r) * (y + 2 * r) >= r * r);
  if (!bounded) return stripe(x, y, r, true);
  const double xx = -x * x / (4 * r), yy = -y * y / (4 * r);
  if (x <= yy && y <= xx) {
    const double m = quarticRoot(r, x + y, x * x + y * y);
    return -m * m;
  }
  if (y > xx) return y;
  if (x > yy) return x;
  return 0;
}

// The intersection, in its own quadrants: bounded (+m^2) inside both, angle approach outside both.
double referenceIntersection(double x, double y, double r, double alpha) {
  if (std::fabs(x) < 1e-7 && std::fabs(y) < 1e-7) return 0;
  if (std::fabs(y) < 1e-7) return x > 0 ? 0 : x;
  if (std::fabs(x) < 1e-7) return y > 0 ? 0 : y;
  if (x < 0 && y > 0) return x;
  if (x > 0 && y < 0) return y;
  if (x < 0 && y < 0) {
    const double t = std::tan(alpha), g = x / y;
    if (g < 1 / t && g > t) {
      const double a = 1 - t * t - 2 * t, b = 2 * t * (x + y), c = -x * x - y * y;
      return (-b - std::sqrt(b * b - 4 * a * c)) / (2 * a);
    }
    return g >= 1 / t ? x : y;
  }
  const bool bounded = x <= r || y <= r ||
                       (x <= 2 * r && y <= 2 * r && (x - 2 * r) * (x - 2 * r) + (y - 2 * r) * (y - 2 * r) >= r * r);
  if (!bounded) return stripe(x, y, r, false);
  const double xx = x * x / (4 * r), yy = y * y / (4 * r);
  if (xx <= y && yy <= x) {
    const double m = quarticRoot(r, -(x + y), x * x + y * y);
    return m * m;
  }
  if (xx > y) return y;
  if (yy > x) return x;
  return 0;
}

// The signed distance to the ellipsoid: the closest point's parameter t solves
// sum (a_k d_k / (t + a_k^2))^2 = 1, found by bisection (t > 0 outside, -min a^2 < t < 0 inside).
double referenceEllipsoid(double u, double v, double w, double a, double b, double c) {
  const double d[3] = {u, v, w}, ax[3] = {a, b, c};
  auto F = [&](double t) {
    double s = 0;
    for (int k = 0; k < 3; ++k) s += std::pow(ax[k] * d[k] / (t + ax[k] * ax[k]), 2);
    return s - 1;
  };
  const bool inside = (u / a) * (u / a) + (v / b) * (v / b) + (w / c) * (w / c) < 1;
  double lo = inside ? -std::min({a * a, b * b, c * c}) : 0, hi = inside ? 0 : 1;
  if (!inside)
    while (F(hi) > 0) hi *= 2;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (F(mid) > 0 ? lo : hi) = mid;
  }
  const double t = 0.5 * (lo + hi);
  double dist2 = 0;
  for (int k = 0; k < 3; ++k) dist2 += std::pow(ax[k] * ax[k] * d[k] / (t + ax[k] * ax[k]) - d[k], 2);
  return inside ? std::sqrt(dist2) : -std::sqrt(dist2);
}

TEST(Sardf, UnionIntersectionAndSubtractionAgainstTheReference) {
  std::mt19937 rng(21);
  const double rs[] = {0.3, 1.0, 2.5}, alphas[] = {0.3, 0.6, 1.1};
  int quartic_points = 0;
  for (double r : rs)
    for (double alpha : alphas) {
      char body[200];
      std::snprintf(body, sizeof body, "my_model = hfDUni(x[1], x[2], %g, %g) + 1000 * hfDInt(x[1], x[3], %g, %g);", r,
                    alpha, r, alpha);
      const FieldTape t = hyperFun(body);
      std::snprintf(body, sizeof body, "my_model = hfDSub(x[1], x[2], %g, %g);", r, alpha);
      const FieldTape sub = hyperFun(body);
      std::uniform_real_distribution<double> u(-3.5 * r, 3.5 * r);
      for (int k = 0; k < 3000; ++k) {
        const double x = f32(u(rng)), y = f32(u(rng)), z = f32(u(rng));
        const double uni = referenceUnion(x, y, f32(r), f32(alpha));
        const double inter = referenceIntersection(x, z, f32(r), f32(alpha));
        if (x < 0 && y < 0 && x <= -y * y / (4 * r) && y <= -x * x / (4 * r) &&
            (x >= -r || y >= -r))
          ++quartic_points;
        const double got = testing::evaluateDouble(t, x, y, z);
        ASSERT_NEAR(got, uni + 1000 * inter, 2e-5 * (1 + std::fabs(uni) + 1000 * std::fabs(inter)))
            << "r " << r << " alpha " << alpha << " at " << x << ", " << y << ", " << z << ": union " << uni
            << ", intersection " << inter;
        const double s = referenceIntersection(x, -y, f32(r), f32(alpha));
        ASSERT_NEAR(testing::evaluateDouble(sub, x, y, z), s, 2e-5 * (1 + std::fabs(s))) << x << ", " << y;
      }
    }
  EXPECT_GT(quartic_points, 500);  // the quartic piece is exercised, not only the simple ones
}

TEST(Sardf, StripeBlendsAndEllipsoidAgainstTheReference) {
  const FieldTape blends = hyperFun("my_model = hfDBlendUni(x[1], x[2], 0.7) + 100 * hfDBlendInt(x[2], x[3], 0.4);");
  const FieldTape ellipsoid = hyperFun("array c[3];\nc = [0.2, -0.1, 0.3];\nmy_model = hfDEllipsoid(x, c, 1.5, 0.6, 1.0);");
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  double worst = 0;
  for (int k = 0; k < 4000; ++k) {
    const double x = f32(u(rng)), y = f32(u(rng)), z = f32(u(rng));
    const double want = stripe(x, y, f32(0.7), true) + 100 * stripe(y, z, f32(0.4), false);
    ASSERT_NEAR(testing::evaluateDouble(blends, x, y, z), want, 1e-6 * (1 + std::fabs(want))) << x << ", " << y << ", " << z;
    const double e = referenceEllipsoid(x - f32(0.2), y - f32(-0.1), z - f32(0.3), 1.5, 0.6, 1.0);
    const double got = testing::evaluateDouble(ellipsoid, x, y, z);
    worst = std::max(worst, std::fabs(got - e));
    // HyperFun stops its Newton steps where the polynomial (of degree 6 in t, values up to
    // ~1e3 here) is within 1e-6 of 0: the closest point is that far from exact, as HyperFun's.
    ASSERT_NEAR(got, e, 5e-5) << x << ", " << y << ", " << z;
  }
  std::printf("hfDEllipsoid: max |error| %.3g against the bisected closest point\n", worst);
}

// The tape's derivative through the quartic's Newton steps and the selects is the union's
// derivative: central differences of the reference, at points of every piece away from the
// pieces' borders.
TEST(Sardf, GradientFollowsThePieces) {
  const FieldTape t = hyperFun("my_model = hfDUni(x[1], x[2], 1, 0.5);");
  GradientEvaluator ge(t);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-2.5, 2.5);
  int checked = 0;
  for (int k = 0; k < 3000 && checked < 600; ++k) {
    const double x = f32(u(rng)), y = f32(u(rng));
    const double h = 1e-5;
    const double gx = (referenceUnion(x + h, y, 1, f32(0.5)) - referenceUnion(x - h, y, 1, f32(0.5))) / (2 * h);
    const double gy = (referenceUnion(x, y + h, 1, f32(0.5)) - referenceUnion(x, y - h, 1, f32(0.5))) / (2 * h);
    // Near a border between pieces the difference quotient straddles two formulas: skip.
    const double gx2 = (referenceUnion(x + 2 * h, y, 1, f32(0.5)) - referenceUnion(x - 2 * h, y, 1, f32(0.5))) / (4 * h);
    if (std::fabs(gx - gx2) > 1e-4 || std::fabs(x) < 1e-3 || std::fabs(y) < 1e-3) continue;
    const FieldGradient g = ge.evaluate(static_cast<float>(x), static_cast<float>(y), 0.0f);
    EXPECT_NEAR(g.dx, gx, 2e-3 * (1 + std::fabs(gx))) << x << ", " << y;
    EXPECT_NEAR(g.dy, gy, 2e-3 * (1 + std::fabs(gy))) << x << ", " << y;
    ++checked;
  }
  EXPECT_GE(checked, 600);
}

// Two balls' distances joined by the SARDF union, drawn by every method against the reference.
TEST(Sardf, ASardfUnionRenders) {
  const FieldTape t = hyperFun("array c1[3], c2[3];\nc1 = [-0.35, 0, 0];\nc2 = [0.4, 0.1, 0];\n"
                               "d1 = 0.45 - sqrt((x[1]+0.35)^2 + x[2]^2 + x[3]^2);\n"
                               "d2 = 0.35 - sqrt((x[1]-0.4)^2 + (x[2]-0.1)^2 + x[3]^2);\n"
                               "my_model = hfDUni(d1, d2, 0.2, 0.4);");
  const ImplicitField field("sardf union", t);
  const FieldRays rays = orthoRays(16, 16, {-1, -1, -1}, {1, 1, 1});
  for (RootMethod m : {RootMethod::Auto, RootMethod::Interval, RootMethod::March}) {
    const Comparison c = compare(field, rays, 16, 16, m, m == RootMethod::March ? 64.0f : 0.0f, 1000);
    SCOPED_TRACE(static_cast<int>(m));
    EXPECT_EQ(c.coverage_mismatches, 0);
    EXPECT_LT(c.max_depth_error, 1e-4);
  }
}

}  // namespace
}  // namespace pf::field
