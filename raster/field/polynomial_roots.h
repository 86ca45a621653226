// Real roots of a polynomial of degree <= 4 on an interval, robustly: the interval is cut at the
// roots of the derivative (found the same way, recursively), so each piece is monotone and holds
// at most one root, found by bisection safeguarded Newton to full double precision. A root where
// the polynomial only touches zero (a double root, a tangent ray) is a root of the derivative
// with a value within rounding of zero, and is reported too. No Cardano or Ferrari: their
// cancellation is what makes textbook quartic solvers lose tangent and near-double roots.
#pragma once

#include <array>
#include <optional>
#include <vector>

namespace pf::field {

// The smallest t in [lo, hi] where p(t) = 0 (or p changes sign), for p = sum c[k] t^k, degree
// <= 4. nullopt where p has no root there.
std::optional<double> firstRootIn(const std::array<double, 5>& c, int degree, double lo, double hi);

// Every such t in [lo, hi], sorted, each once (a touching root included).
std::vector<double> rootsIn(const std::array<double, 5>& c, int degree, double lo, double hi);

}  // namespace pf::field
