// firstRootIn (which stops at the first root) against the first of rootsIn's roots, over random
// polynomials of degree 1 to 4 with roots in and around the span -- simple, double and clustered
// -- and against the roots they were built from.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "raster/field/polynomial_roots.h"

namespace pf::field {
namespace {

TEST(PolynomialRoots, FirstRootIsTheFirstOfAllRoots) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int found = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    // k (t - r1)(t - r2)... with some roots repeated or nearly so.
    const int degree = 1 + trial % 4;
    double r[4];
    for (int k = 0; k < degree; ++k) r[k] = u(rng);
    if (trial % 5 == 0 && degree >= 2) r[1] = r[0];                  // a double root
    if (trial % 7 == 0 && degree >= 3) r[2] = r[0] + 1e-9 * u(rng);  // a cluster
    std::array<double, 5> c{1.0, 0, 0, 0, 0};
    for (int k = 0; k < degree; ++k) {  // multiply by (t - r_k)
      for (int j = k + 1; j > 0; --j) c[j] = c[j - 1] - r[k] * c[j];
      c[0] = -r[k] * c[0];
    }
    const double scale = trial % 2 ? -3.0 : 0.5;
    for (double& v : c) v *= scale;
    const double lo = -1.0, hi = 1.0;
    const PolynomialRoots all = rootsIn(c, degree, lo, hi);
    const std::optional<double> first = firstRootIn(c, degree, lo, hi);
    ASSERT_EQ(first.has_value(), !all.empty()) << "trial " << trial;
    if (!first) continue;
    ASSERT_EQ(*first, all.front()) << "trial " << trial;
    ++found;
    // It is the first of the roots the polynomial was built from that lie in the span.
    double want = hi + 1.0;
    for (int k = 0; k < degree; ++k)
      if (r[k] >= lo && r[k] <= hi) want = std::min(want, r[k]);
    if (want <= hi && trial % 7 != 0) {
      EXPECT_NEAR(*first, want, 1e-6) << "trial " << trial;
    }
  }
  EXPECT_GT(found, 10000);
}

// Lines and quadratics start from their closed-form root (polynomial_roots.cpp): each root of
// k (t - r1)(t - r2) is found as accurately as the coefficients (rounded when built from the
// roots) determine it -- within 8 eps (|c0| + |c1 r| + |c2 r^2|) / |p'(r)| -- including the small
// root beside a large one, where the textbook formula cancels.
TEST(PolynomialRoots, QuadraticRootsAreAccurateToDoublePrecision) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto check = [](double r1, double r2, double k) {
    const std::array<double, 5> c{k * r1 * r2, -k * (r1 + r2), k, 0.0, 0.0};
    const PolynomialRoots all = rootsIn(c, 2, -2.0, 2.0);
    for (double r : {r1, r2}) {
      if (r < -2.0 || r > 2.0) continue;
      const double slope = std::fabs(2 * c[2] * r + c[1]);
      const double tol = 8 * 2.3e-16 * (std::fabs(c[0]) + std::fabs(c[1] * r) + std::fabs(c[2] * r * r)) / slope;
      bool seen = false;
      for (double got : all) seen = seen || std::fabs(got - r) <= tol;
      EXPECT_TRUE(seen) << "root " << r << " of k = " << k << " (t - " << r1 << ")(t - " << r2 << ")";
    }
  };
  for (int trial = 0; trial < 5000; ++trial) check(u(rng), u(rng), trial % 2 ? 3.0 : -0.25);
  check(1e-9, 1e8, 1.0);    // c1 ~ -1e8: the small root by c0 / q, not by cancellation
  check(-1e-12, 5e7, -2.0);
  // Roots 1e-7 apart: p at the vertex is below evaluate()'s rounding bound, so the pair is one
  // touching root there (within 1e-7 of both).
  const std::array<double, 5> pair{0.5 * (0.5 + 1e-7), -(1.0 + 1e-7), 1.0, 0.0, 0.0};
  const auto touching = firstRootIn(pair, 2, 0.0, 1.0);
  ASSERT_TRUE(touching);
  EXPECT_NEAR(*touching, 0.5 + 5e-8, 1e-7);
  const std::array<double, 5> line{-0.3, 1.5, 0.0, 0.0, 0.0};  // 1.5 t - 0.3
  const auto r = firstRootIn(line, 1, -1.0, 1.0);
  ASSERT_TRUE(r);
  EXPECT_NEAR(*r, 0.2, 1e-16);
}

}  // namespace
}  // namespace pf::field
