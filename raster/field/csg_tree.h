// A field as a CSG tree of polynomial leaves, for the `analytic` method (issue #8: "per CSG leaf
// when the tree is a min/max/R-function tree of such leaves").
//
// Root finding needs only the field's sign, and many non-polynomial fields have the sign of a
// min/max combination of polynomials of degree <= 4:
//   min(a, b), max(a, b)                        -> a AND b, a OR b
//   a + b +- sqrt(a^2 + b^2)  (HyperFun's | &)  -> a OR b, a AND b (the R0 functions have the
//   a - b - sqrt(a^2 + b^2)   (HyperFun's \)       sign of max / min of their arguments)
//   -a, c * a (constant c)                      -> NOT a, a or NOT a by c's sign
//   A + k sqrt(B)  (A, B polynomial, k > 0,     -> A OR (k^2 B - A^2)   (the torus: HyperFun's
//   A - k sqrt(B)   B >= 0 by its form)         -> A AND (A^2 - k^2 B)   hfTorus is of this form)
// (B must be a sum of squares or the like: where B < 0 the field is NaN, outside for every
// method, and no combination of polynomials says so.) NaN leaves are ignored by AND / OR as the
// field's own min / max ignore NaN.
// where AND / OR / NOT are min / max / negation of the values. The combination g(t) of the leaves'
// ray polynomials has the field's sign everywhere along the ray, and changes sign only where a
// leaf is zero: so the first surface point is among the leaves' roots -- found in double by
// derivative splitting (polynomial_roots.h), exact where the leaves are, with no sampling.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "compiler/field/field_tape.h"
#include "raster/field/ray_polynomial.h"

namespace pf::field {

struct CsgNode {
  enum class Kind : uint8_t { Leaf, And, Or, Not } kind = Kind::Leaf;
  uint32_t a = 0, b = 0;  // And / Or: both operands; Not: a (node indices, earlier nodes)
  uint32_t value = 0;     // Leaf: the polynomial's value in CsgTree::tape
};

struct CsgTree {
  // The field's tape with the leaves the sqrt forms need appended (k^2 B - A^2): every leaf is a
  // value of this tape, a polynomial of degree <= 4 in (x, y, z).
  FieldTape tape;
  std::vector<CsgNode> nodes;  // children before parents; the root is the last
  size_t leaf_count = 0;

  // The field's first surface point along the ray in [entry, exit]: entry itself where the
  // field is >= 0 there, else the first leaf root after which the combination is positive (or
  // where it touches zero). nullopt: none. `solved` is false where a leaf has no polynomial
  // along this ray after all (a division by a constant 0): the caller uses another method.
  std::optional<double> firstHit(const std::array<double, 3>& origin, const std::array<double, 3>& direction,
                                 double entry, double exit, bool& solved) const;

  // The combination's value at t from the leaves' ray polynomials (indexed by tape value).
  double combine(const std::vector<RayPolynomial>& polys, double t) const;
};

// The tree, or nullopt where the field is not such a combination of at least two polynomial
// leaves (a single polynomial is the plain analytic case) or would need more than `max_leaves`.
std::optional<CsgTree> csgTreeOf(const FieldTape& tape, size_t max_leaves = 4096);

}  // namespace pf::field
