// The sampled-field file (.pfgrid): a voxel array (seed 000, section 3) as a small text header
// and raw samples, read into a SampledGrid (sampled_grid.h) whose tape (sampledFieldTape) any
// evaluator and root-finding method runs. The format, documented in docs/models.md:
//
//   pfgrid 1
//   size NX NY NZ                      at least 2 each, at most 2^24 samples in all
//   box X0 Y0 Z0 X1 Y1 Z1              the samples' extent: sample (0,0,0) at the first corner
//   interpolation trilinear|tricubic   tricubic: the uniform cubic B-spline of the samples
//   data
//   NX*NY*NZ little-endian IEEE float32, x fastest, then y, then z; nothing after them
//
// One keyword line each (size, box, interpolation in any order, `#` starting a comment line), the
// values f >= 0 inside (primflow's sign: negate a signed distance that is negative inside), all
// finite. Errors name the file, the header line and column with a caret, and for the data the
// byte offset.
#pragma once

#include <memory>
#include <string>

#include "compiler/diagnostics.h"
#include "compiler/field/field_tape.h"
#include "compiler/field/sampled_grid.h"

namespace pf::field {

// The grid in `bytes` (the whole file, named `name` in diagnostics), or null with errors in `log`.
std::shared_ptr<const SampledGrid> readSampledField(const std::string& name, const std::string& bytes,
                                                    DiagnosticLog& log);

// The field of a grid: the tape of one `sample` leaf.
FieldTape sampledFieldTape(std::shared_ptr<const SampledGrid> grid);

}  // namespace pf::field
