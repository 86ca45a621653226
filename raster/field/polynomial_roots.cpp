// Root isolation by derivative splitting (see polynomial_roots.h).
#include "raster/field/polynomial_roots.h"

#include <algorithm>
#include <cmath>

namespace pf::field {
namespace {

double evaluate(const std::array<double, 5>& c, int degree, double t) {
  double v = 0.0;
  for (int k = degree; k >= 0; --k) v = v * t + c[k];
  return v;
}

// A bound on the rounding error of evaluate() at t: Horner's error is about
// degree * eps * sum |c_k| |t|^k.
double evaluationError(const std::array<double, 5>& c, int degree, double t) {
  double s = 0.0;
  for (int k = degree; k >= 0; --k) s = s * std::fabs(t) + std::fabs(c[k]);
  return 4.0 * (degree + 1) * 2.220446049250313e-16 * s;
}

// A line's or a quadratic's root in [a, b], where p is monotone with a sign change: in closed form
// (the quadratic's by the formula that does not cancel: q = -(c1 + sign(c1) sqrt(disc)) / 2, roots
// q / c2 and c0 / q), the one nearest the bracket, clamped into it. NaN when the formula breaks
// down (q = 0, or no finite root): the caller then iterates. Most leaves of shipped models --
// planes, spheres, cylinders, cones -- are of these degrees, and a ray casts one per pixel.
double closedFormRoot(const std::array<double, 5>& c, int degree, double a, double b) {
  double t = std::nan("");
  if (degree == 1) {
    t = -c[0] / c[1];
  } else {
    const double disc = std::max(c[1] * c[1] - 4.0 * c[2] * c[0], 0.0);  // >= 0 up to rounding: p changes sign
    const double q = -0.5 * (c[1] + std::copysign(std::sqrt(disc), c[1]));
    if (q == 0.0) return std::nan("");
    const double r1 = q / c[2], r2 = c[0] / q;
    auto outside = [&](double r) { return r < a ? a - r : r > b ? r - b : 0.0; };
    t = outside(r1) <= outside(r2) ? r1 : r2;
  }
  if (!std::isfinite(t)) return std::nan("");
  return std::min(std::max(t, a), b);
}

// The root in [a, b] of p, monotone there with p(a) and p(b) of opposite signs.
double refine(const std::array<double, 5>& c, int degree, double a, double b, double fa) {
  const std::array<double, 5> dc = {c[1], 2 * c[2], 3 * c[3], 4 * c[4], 0.0};
  double t = 0.5 * (a + b);
  // Degrees 1 and 2 start from their closed-form root, where Newton below has converged already
  // (it then stops after a step or two instead of five or six from the midpoint).
  if (degree <= 2) {
    const double r = closedFormRoot(c, degree, a, b);
    if (r == r && r > a && r < b) t = r;
  }
  for (int it = 0; it < 200 && b - a > 0.0; ++it) {
    const double f = evaluate(c, degree, t);
    if (f == 0.0) return t;
    if ((f < 0.0) == (fa < 0.0)) {
      a = t;
      fa = f;
    } else {
      b = t;
    }
    // Newton from t where it stays inside the bracket, else bisection.
    const double df = evaluate(dc, degree - 1, t);
    double next = df != 0.0 ? t - f / df : a - 1.0;
    if (!(next > a && next < b)) next = 0.5 * (a + b);
    if (next == t || next == a || next == b) break;
    t = next;
  }
  return t;
}

// Splitting at the derivative's roots, found the same way: each piece is monotone. With
// `first_only`, stops at the first root: the pieces are visited left to right and each pushes its
// roots in order, so the first root pushed is the one the whole list would begin with.
PolynomialRoots rootsOf(const std::array<double, 5>& c, int degree, double lo, double hi, bool first_only) {
  PolynomialRoots roots;
  if (!(hi >= lo)) return roots;
  while (degree > 0 && c[degree] == 0.0) --degree;
  if (degree == 0) return roots;
  // lo, the derivative's roots (at most R(3) = 6, see PolynomialRoots), hi.
  std::array<double, PolynomialRoots::kCapacity> cuts;
  size_t cut_count = 0;
  cuts[cut_count++] = lo;
  if (degree >= 2) {
    const std::array<double, 5> dc = {c[1], 2 * c[2], 3 * c[3], 4 * c[4], 0.0};
    for (double r : rootsOf(dc, degree - 1, lo, hi, false)) cuts[cut_count++] = r;
  }
  cuts[cut_count++] = hi;
  for (size_t i = 0; i + 1 < cut_count; ++i) {
    if (first_only && !roots.empty()) return roots;
    const double a = cuts[i], b = cuts[i + 1];
    const double fa = evaluate(c, degree, a), fb = evaluate(c, degree, b);
    // A cut where p is zero within rounding: a touching (double) root, or a root at an end.
    if (std::fabs(fa) <= evaluationError(c, degree, a)) {
      if (roots.empty() || roots.back() != a) roots.push_back(a);
      continue;
    }
    if (std::fabs(fb) <= evaluationError(c, degree, b)) continue;  // the next piece reports it
    if ((fa < 0.0) != (fb < 0.0)) roots.push_back(refine(c, degree, a, b, fa));
  }
  if (first_only && !roots.empty()) return roots;
  const double fh = evaluate(c, degree, hi);
  if (std::fabs(fh) <= evaluationError(c, degree, hi) && (roots.empty() || roots.back() != hi)) roots.push_back(hi);
  return roots;
}

}  // namespace

PolynomialRoots rootsIn(const std::array<double, 5>& c, int degree, double lo, double hi) {
  return rootsOf(c, degree, lo, hi, false);
}

std::optional<double> firstRootIn(const std::array<double, 5>& c, int degree, double lo, double hi) {
  if (!(hi >= lo)) return std::nullopt;
  const PolynomialRoots roots = rootsOf(c, degree, lo, hi, true);
  if (roots.empty()) return std::nullopt;
  return roots.front();
}

}  // namespace pf::field
