// Optimization passes over the IR (ir.h), between lowering and code generation:
//   constant folding  -- an instruction whose operands are all constants becomes a constant,
//                        computed by the same evalScalar the executors run;
//   CSE               -- an instruction equal to an earlier one that dominates it (same op,
//                        same operands, commutative operands in either order) reuses it;
//   copy propagation  -- a value defined once as a copy is replaced by what it copies;
//   dead code         -- instructions whose values reach no effect (depth, shading
//                        parameters, bound, control flow) are removed.
// Uniform hoisting (the setup / per-pixel split) is code generation's; inlining is lowering's.
// Every rewrite can say why it fired: `pfc --explain` prints the reasons.
#pragma once

#include <string>
#include <vector>

#include "compiler/ir.h"

namespace pf {

struct PassStats {
  int folded = 0, cse = 0, copies = 0, dead = 0;
};

// Rewrites `f` in place. When `explain` is not null, appends one line per rewrite.
PassStats optimize(IrFunction& f, std::vector<std::string>* explain = nullptr);

}  // namespace pf
