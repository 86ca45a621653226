// The built-in primitives (primitives/*.pfl), compiled once per process and shared, read-only,
// by every context -- registered exactly as a user's primitives are (paper section 4: "all
// primitives, including the built-in ones, must register themselves").
#pragma once

#include <string>
#include <vector>

#include "compiler/compiler.h"

namespace pf {

struct BuiltinPrimitives {
  std::vector<std::shared_ptr<const CompiledPrimitive>> in_order;  // as their files define them
  PrimitiveTable by_name;
  std::string errors;  // a built-in failed to compile: a bug of the build, reported by the API
};

const BuiltinPrimitives& builtinPrimitives();

}  // namespace pf
