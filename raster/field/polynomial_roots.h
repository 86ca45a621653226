// Real roots of a polynomial of degree <= 4 on an interval, robustly: the interval is cut at the
// roots of the derivative (found the same way, recursively), so each piece is monotone and holds
// at most one root, found by bisection safeguarded Newton to full double precision. A root where
// the polynomial only touches zero (a double root, a tangent ray) is a root of the derivative
// with a value within rounding of zero, and is reported too. No Cardano or Ferrari: their
// cancellation is what makes textbook quartic solvers lose tangent and near-double roots.
#pragma once

#include <array>
#include <cstddef>
#include <optional>

namespace pf::field {

// What rootsIn finds, in place (no heap: it runs per leaf per ray). Its capacity is a bound on
// rootsIn's count, which may exceed the degree: roots within rounding of zero are reported at
// the ends of the pieces, so on a short enough interval a line has two (lo and hi). Degree d
// cuts [lo, hi] at the derivative's R(d - 1) roots into R(d - 1) + 1 pieces, each giving at most
// one root, and hi one more: R(d) <= R(d - 1) + 2, R(0) = 0, so a quartic has at most 8.
struct PolynomialRoots {
  static constexpr int kCapacity = 8;
  std::array<double, kCapacity> t{};
  int count = 0;

  const double* begin() const { return t.data(); }
  const double* end() const { return t.data() + count; }
  size_t size() const { return static_cast<size_t>(count); }
  bool empty() const { return count == 0; }
  const double& operator[](size_t i) const { return t[i]; }
  const double& front() const { return t[0]; }
  const double& back() const { return t[static_cast<size_t>(count) - 1]; }
  void push_back(double r) { t[static_cast<size_t>(count++)] = r; }
};

// The smallest t in [lo, hi] where p(t) = 0 (or p changes sign), for p = sum c[k] t^k, degree
// <= 4. nullopt where p has no root there.
std::optional<double> firstRootIn(const std::array<double, 5>& c, int degree, double lo, double hi);

// Every such t in [lo, hi], sorted, each once (a touching root included). Allocates nothing.
PolynomialRoots rootsIn(const std::array<double, 5>& c, int degree, double lo, double hi);

}  // namespace pf::field
