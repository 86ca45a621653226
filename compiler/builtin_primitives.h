// The built-in primitives (primitives/*.pfl) and shared interpolators
// (primitives/interpolators/*.pfl), compiled once per process and shared, read-only,
// by every context -- registered exactly as a user's primitives are (paper section 4: "all
// primitives, including the built-in ones, must register themselves").
#pragma once

#include <string>
#include <vector>

#include "compiler/compiler.h"

namespace pf {

struct BuiltinPrimitives {
  std::vector<std::shared_ptr<const CompiledPrimitive>> in_order;  // as their files define them
  // The shared interpolators of primitives/interpolators/*.pfl, registered by every context as
  // pfglCompilePrimitivesEXT registers a user's.
  std::vector<std::shared_ptr<const CompiledPrimitive>> interpolators;
  PrimitiveTable by_name;
  std::string errors;  // a built-in failed to compile: a bug of the build, reported by the API
};

const BuiltinPrimitives& builtinPrimitives();

}  // namespace pf
