// The pixel program for blocks an instance certainly covers (issue [raster]: "accept fully
// covered blocks without per-pixel tests").
//
// A pixel program's leading `return`s -- the Retires up to PixelProgram::last_coverage_retire,
// such as a triangle's three edge tests and its near/far clip -- decide coverage. Where block rejection's interval
// evaluation (raster/block_rejection.h) proves that none of them runs for any pixel of a
// region, the executor may run this variant instead: the same program with those Retires,
// their MaskIf / JmpIfNone / MaskEnd wrappers and every value only they read removed. Nothing
// else changes, so a block gives bit for bit what the full program gives there. For no
// primitive is this special-cased: it is a transformation of the bytecode.
#pragma once

#include <optional>

#include "compiler/isa.h"

namespace pf {

// The variant, or nullopt when the program has no leading Retire or one of another shape than
// the wrapper codegen emits for a varying `if (...) return;` (the executor then runs the full
// program everywhere).
std::optional<PixelProgram> coveredVariant(const PixelProgram& program);

}  // namespace pf
