// The polynomial form of a field along a ray: where f(o + t d) is a polynomial of degree <= 4 in
// t, its coefficients (in double), found by evaluating the tape in truncated polynomial
// arithmetic. This is what seed 004 derived by hand per surface and what the `analytic` method
// solves. Fields that are not polynomial along the ray (sqrt of a non-constant, min/max of
// non-constants, division by a non-constant, degree above 4) have no polynomial form.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "compiler/field/field_tape.h"

namespace pf::field {

struct RayPolynomial {
  std::array<double, 5> c{};  // f(o + t d) = sum c[k] t^k
  int degree = 0;             // highest k with c[k] != 0 (0 for a constant)
  double evaluate(double t) const;
};

std::optional<RayPolynomial> rayPolynomial(const FieldTape& tape, const std::array<double, 3>& origin,
                                           const std::array<double, 3>& direction);

// Every value of the tape along the ray: out[i] is value i's polynomial where valid[i] (a value
// that is not polynomial, or reads one that is not, is invalid; its entry means nothing). With
// stop_at_invalid, returns false at the first invalid value instead (the whole-field case).
bool rayPolynomials(const FieldTape& tape, const std::array<double, 3>& origin, const std::array<double, 3>& direction,
                    std::vector<RayPolynomial>& out, std::vector<uint8_t>& valid, bool stop_at_invalid = false);

// The field's total degree as a polynomial in (x, y, z), or -1 where it is not a polynomial:
// which fields the `analytic` method can take at all, whatever the ray.
int fieldPolynomialDegree(const FieldTape& tape);
// The same for every value of the tape.
std::vector<int> polynomialDegrees(const FieldTape& tape);

}  // namespace pf::field
