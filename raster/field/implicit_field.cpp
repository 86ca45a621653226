// ImplicitField: derived facts about a tape, and method names.
#include "raster/field/implicit_field.h"

#include "raster/field/ray_polynomial.h"

namespace pf::field {

namespace {
constexpr std::string_view kMethodNames[kRootMethodCount] = {"auto",   "analytic", "interval",    "march",
                                                             "sphere", "newton",   "regula-falsi"};
}

std::string_view rootMethodName(RootMethod m) {
  const int i = static_cast<int>(m);
  return i >= 0 && i < kRootMethodCount ? kMethodNames[i] : "?";
}

std::optional<RootMethod> parseRootMethod(std::string_view name) {
  for (int i = 0; i < kRootMethodCount; ++i)
    if (kMethodNames[i] == name) return static_cast<RootMethod>(i);
  return std::nullopt;
}

ImplicitField::ImplicitField(std::string n, FieldTape t, float l, std::vector<FieldTape> a)
    : name(std::move(n)), tape(std::move(t)), lipschitz(l), attributes(std::move(a)) {
  polynomial_degree = fieldPolynomialDegree(tape);
  if (polynomial_degree < 0 || polynomial_degree > 4)
    if (auto tree = csgTreeOf(tape)) csg = std::make_shared<const CsgTree>(std::move(*tree));
  for (const FieldInstr& in : tape.instrs) {
    if (in.op == FieldOp::X) reads[0] = true;
    if (in.op == FieldOp::Y) reads[1] = true;
    if (in.op == FieldOp::Z) reads[2] = true;
    if (in.op == FieldOp::Sample) reads[0] = reads[1] = reads[2] = true;
  }
}

RootMethod resolveMethod(const ImplicitField& field, RootMethod requested) {
  if (requested != RootMethod::Auto) return requested;
  if (field.polynomial_degree >= 0 && field.polynomial_degree <= 4) return RootMethod::Analytic;
  // (A field that does not read z is a 2D model, constant along the model views' rays: the
  // interval method decides whole blocks from one evaluation, far cheaper than solving leaves.)
  if (field.csg && field.csg->leaf_count <= kAutoCsgLeaves && field.reads[2]) return RootMethod::Analytic;
  if (field.lipschitz > 0.0f) return RootMethod::Sphere;
  return RootMethod::Interval;
}

}  // namespace pf::field
