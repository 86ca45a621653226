// Compiling the embedded primitive sources (see builtin_primitives.h).
#include "compiler/builtin_primitives.h"

#include "compiler/embedded_primitives.h"

namespace pf {

namespace {

// A file may call primitives of other files (and name their shared interpolators in its
// interpolation labels): files are compiled in rounds, each round taking the files whose
// callees are now compiled, until no file is left or a round makes no progress
// (then the errors of what is left are the report).
BuiltinPrimitives compileAll() {
  BuiltinPrimitives out;
  std::set<std::string> interpolator_names;  // compiled so far: interpolation labels may name them
  std::vector<int> pending;
  for (int i = 0; i < kEmbeddedPrimitiveCount; ++i) pending.push_back(i);
  while (!pending.empty()) {
    std::vector<int> failed;
    std::string errors;
    for (int i : pending) {
      const EmbeddedSource& src = kEmbeddedPrimitives[i];
      CompiledModule module;
      DiagnosticLog log;
      if (!compileSource(std::string("primitives/") + src.file_name, src.text, module, log, EmitStage::None,
                         nullptr, true, &out.by_name, &interpolator_names)) {
        failed.push_back(i);
        errors += log.format();
        continue;
      }
      for (auto& p : module.primitives) {
        out.by_name[p->name] = p;
        out.in_order.push_back(p);
      }
      for (auto& p : module.interpolators) {
        out.interpolators.push_back(p);
        interpolator_names.insert(p->name);
      }
    }
    if (failed.size() == pending.size()) {
      out.errors = errors;
      break;
    }
    pending = std::move(failed);
  }
  return out;
}

}  // namespace

const BuiltinPrimitives& builtinPrimitives() {
  static const BuiltinPrimitives compiled = compileAll();
  return compiled;
}

}  // namespace pf
