// The process's one JIT: LLVM's ORC LLJIT over the shared libLLVM-15 -- the same library
// Debian's OSMesa (llvmpipe) loads, so the two share one LLVM in a process. It optimizes and
// links the modules the code generators build (pixel_codegen.h) and resolves the helpers of
// native_runtime.h. Created on first use and never destroyed (LLVM's own statics may be torn
// down first at exit); thread-safe: modules compile in the thread that adds them, each in its
// own LLVMContext. Only compiler/native/ includes LLVM.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "compiler/native/native_abi.h"

namespace llvm {
class Function;
class LLVMContext;
class Module;
}  // namespace llvm

namespace pf {

class JitEngine {
 public:
  // The engine, or null when native code cannot run here: LLVM failed to initialise for the
  // host (said once on stderr, "primflow: native code unavailable: ..."), or the host is not
  // x86-64.
  static JitEngine* instance();

  // The attributes that make `f` compile for `isa` (CPU, features, vector width, no
  // floating-point contraction), whatever the host's best.
  void setTarget(llvm::Function& f, NativeIsa isa) const;

  // Optimizes `module` (-O2's pipeline), compiles and links it, and returns the address of
  // each of `symbols` in `addresses`; false with `error` set if LLVM refused it.
  bool add(std::unique_ptr<llvm::Module> module, std::unique_ptr<llvm::LLVMContext> context,
           const std::vector<std::string>& symbols, std::vector<void*>& addresses, std::string& error);

  // What `pfc --emit=native` prints: the module optimized as add() would, as LLVM IR and as
  // the machine's assembly.
  std::string listing(llvm::Module& module) const;

  // The host's CPU as LLVM names it (for logs and listings).
  const std::string& hostCpu() const { return host_cpu_; }

 private:
  JitEngine() = default;
  bool initialise(std::string& error);
  void optimize(llvm::Module& module) const;

  struct State;
  std::shared_ptr<State> state_;
  std::string host_cpu_, host_features_;
};

}  // namespace pf
