// The built-in primitives' source text, embedded at build time from primitives/*.pfl
// (cmake/EmbedPrimitives.cmake). The API compiles these when a context is created.
#pragma once

namespace pf {

struct EmbeddedSource {
  const char* file_name;
  const char* text;
};

extern const EmbeddedSource kEmbeddedPrimitives[];
extern const int kEmbeddedPrimitiveCount;

// The language's standard library (compiler/stdlib.pfl), part of every compilation.
extern const EmbeddedSource kStandardLibrary[];
extern const int kStandardLibraryCount;

}  // namespace pf
