// A field's source in any of the formats primflow reads -- Fidget .vm, HyperFun .hf, a `field`
// unit of the primitive language (.pfl), or a sampled field's .pfgrid bytes -- compiled to a tape
// by the matching front end.
// The one place that maps a format (or a file's extension) to its front end: the API, pfrender,
// pfview, scene files and the benchmarks all go through it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "compiler/diagnostics.h"
#include "compiler/field/field_tape.h"

namespace pf::field {

enum class FieldFormat { Fidget, HyperFun, Language, Sampled };

// The format a model file's extension names: .vm, .hf, .pfl, .pfgrid (a sampled field,
// sampled_reader.h); nullopt for any other.
std::optional<FieldFormat> fieldFormatOfPath(const std::string& path);

// Compiles `text` (named `name` in diagnostics) in `format`. `params`: HyperFun's a[1], a[2], ...
// or a language field's parameters after its point; `time`: HyperFun's x[4]. Fidget sources take
// neither, language sources no time (the caller checks). The language's field is the unit named
// `unit` (empty: `name`'s stem, as for a file foo.pfl), or the source's only one. nullopt with
// errors in `log`. `attributes`, when given, receives the field's attributes -- HyperFun's s
// array, one tape per item (readHyperFunModel) -- and stays empty for the other formats.
std::optional<FieldTape> compileFieldSource(FieldFormat format, const std::string& name, const std::string& text,
                                            const std::vector<double>& params, double time, DiagnosticLog& log,
                                            const std::string& unit = "",
                                            std::vector<FieldTape>* attributes = nullptr);

}  // namespace pf::field
