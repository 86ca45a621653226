// firstRootIn (which stops at the first root) against the first of rootsIn's roots, over random
// polynomials of degree 1 to 4 with roots in and around the span -- simple, double and clustered
// -- and against the roots they were built from.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace pf::field
