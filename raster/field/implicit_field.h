// A field ready to be drawn as an `implicit` instance: its tape, what the compiler derived about
// it (polynomial degree, variables it reads), a declared Lipschitz bound, and the root-finding
// methods (seed 000, seed 004, Keeter 2020) with the rule `auto` follows.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/field/field_tape.h"
#include "raster/field/csg_tree.h"

namespace pf::field {

enum class RootMethod : int {
  Auto = 0,      // analytic if polynomial of degree <= 4 (or a small CSG tree of such leaves),
                 // sphere if Lipschitz, interval otherwise
  Analytic = 1,  // the ray polynomial's first root (ray_polynomial.h, polynomial_roots.h), or the
                 // first hit among a CSG tree's leaves' roots (csg_tree.h)
  Interval = 2,  // interval subdivision in t, with region culling and tape simplification
  March = 3,     // M uniform steps, then bisection of the first sign change
  Sphere = 4,    // sphere tracing with the declared Lipschitz bound, checked as it goes
  // Seed 000's approximate search: the march's M steps, then a fixed number of refinement
  // steps instead of bisection to float resolution (bracket_refinement.cpp).
  Newton = 5,       // Newton's method from the bracket's middle (f' from the gradient form)
  RegulaFalsi = 6,  // regula falsi between the bracket's ends (Illinois variant)
};
constexpr int kRootMethodCount = 7;

std::string_view rootMethodName(RootMethod m);
std::optional<RootMethod> parseRootMethod(std::string_view name);

struct ImplicitField {
  std::string name;
  FieldTape tape;
  int polynomial_degree = -1;  // fieldPolynomialDegree(tape)
  // Where the field is not one polynomial: the CSG tree of polynomial leaves with its sign, if any.
  std::shared_ptr<const CsgTree> csg;
  bool reads[3] = {false, false, false};  // uses var-x, var-y, var-z
  float lipschitz = 0.0f;      // declared bound on |grad f| (0: none declared)
  // The field's attributes (HyperFun's s array; seed 000's procedural colour), one tape per item:
  // the values field_color() evaluates at a hit point. Empty when the model defines none.
  std::vector<FieldTape> attributes;

  ImplicitField() = default;
  ImplicitField(std::string name, FieldTape tape, float lipschitz = 0.0f, std::vector<FieldTape> attributes = {});
};

// A context's fields, by id - 1 (ids start at 1). Entries never move or change once added.
using FieldTable = std::vector<std::unique_ptr<const ImplicitField>>;

// The most leaves of a CSG tree for which `auto` picks the analytic method: every leaf's ray
// polynomial is computed and solved per ray, so large trees (Prospero's thousands of leaves)
// are the interval method's, whose tape simplification prunes them per region. (Nor does auto
// take it for fields that do not read z: see resolveMethod.)
constexpr size_t kAutoCsgLeaves = 64;

// The method `auto` resolves to for this field (other methods are returned unchanged).
RootMethod resolveMethod(const ImplicitField& field, RootMethod requested);

}  // namespace pf::field
