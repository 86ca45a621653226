// The process-wide cache of native programs, keyed by content: a program's bytecode and
// constants, the variant it is specialised on (native_abi.h) and the instruction set. Two
// contexts drawing the same primitive compile it once; a primitive recompiled under the same
// name is new content, so new draws get a new function while draws of the old one still
// pending run the old (nothing compiled is ever freed: functions are small, and a pointer to
// one may be held by any thread).
//
// Compiled lazily: a key is compiled once the blocks drawn with it pass the compile threshold
// (PF_JIT_THRESHOLD, default kDefaultNativeThreshold; 0: on its first block). Until then, and
// for programs native code does not run (pixel_codegen.h), the interpreter runs them -- the same
// bits either way. Compiling costs about as much as interpreting a few thousand blocks
// (docs/performance.md), so a program drawn over a few blocks never pays for it. The thread
// that passes the threshold compiles, in its own LLVMContext, while the others go on
// interpreting the program. (Not on a background thread of its own: a compile still running
// when the process exits would run inside LLVM while its static objects are destroyed.)
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "compiler/isa.h"
#include "compiler/native/interval_codegen.h"
#include "compiler/native/native_abi.h"

namespace llvm {
class LLVMContext;
class Module;
}  // namespace llvm

namespace pf {

// Whether the environment leaves native code on: PF_JIT unset or not "0".
bool nativeCodeWantedByEnvironment();
// Whether native code runs in this process: primflow was built with LLVM and it initialised
// for this machine (the first call initialises it).
bool nativeCodeAvailable();

struct NativeCacheStats {
  uint64_t compiled = 0;      // functions compiled (each key once)
  uint64_t refused = 0;       // keys native code does not run
  uint64_t failed = 0;        // keys LLVM failed on (said on stderr once each)
  double milliseconds = 0;    // spent building, optimizing and compiling them
};

// Blocks a key runs on the interpreter before it is compiled, unless PF_JIT_THRESHOLD says;
// for a block-rejection walk, the regions walked (PF_JIT_WALK_THRESHOLD): a walk compiles
// several times slower than a pixel program and saves less per call (docs/performance.md).
constexpr uint64_t kDefaultNativeThreshold = 1024;
constexpr uint64_t kDefaultWalkThreshold = 4096;
// For a setup program, the instances set up (PF_JIT_SETUP_THRESHOLD): a setup program is long
// straight-line code over 16-lane vectors, slower to compile than a pixel program, and saves
// far less per instance than a pixel program per block, so only a program drawn over many
// instances -- a frame of a large mesh, a few frames of a small one -- pays for it.
constexpr uint64_t kDefaultSetupThreshold = 65536;

class NativeProgramCache {
 public:
  static NativeProgramCache& instance();

  // One key's state; found or made by entry(), never freed.
  class Entry {
   public:
    // The compiled function (a NativePixelFunction, NativeVerdictFunction,
    // NativeBlockVerdictsFunction or NativeSetupFunction, as the entry was made), or null (not yet, or never: settled()).
    void* function() const { return function_.load(std::memory_order_acquire); }
    // Whether function() is what it will stay: compiled, or never to be (native code does not
    // run the program, or LLVM failed on it).
    bool settled() const { return status_.load(std::memory_order_acquire) >= kReady; }

   private:
    friend class NativeProgramCache;
    enum : uint8_t { kCold, kCompiling, kReady, kNone };
    enum class Kind : uint8_t { Pixel, Verdict, BlockVerdicts, Setup };
    // What the function is: a pixel program's, a walk's (of one region, or of several at
    // once), a setup program's.
    Kind kind_ = Kind::Pixel;
    std::atomic<void*> function_{nullptr};
    std::atomic<uint8_t> status_{kCold};
    std::atomic<uint64_t> blocks_{0};
  };

  // The entry of `program` under `variant`; of its block-rejection walk (interval_codegen.h).
  Entry* pixelEntry(const PixelProgram& program, const NativePixelVariant& variant);
  Entry* verdictEntry(const PixelProgram& program);
  // The entry of its walk over `lanes` regions at once (a NativeBlockVerdictsFunction), in
  // vectors of `isa`.
  Entry* blockVerdictsEntry(const PixelProgram& program, NativeIsa isa, int lanes);
  // The entry of a setup program under `variant` (setup_codegen.h); its function is a
  // NativeSetupFunction.
  Entry* setupEntry(const SetupProgram& program, const NativeSetupVariant& variant);
  // Counts `blocks` more blocks (regions, for a walk; instances, for a setup program) drawn with the entry's key on the
  // interpreter; true when they passed the threshold and the caller is the one to compile() it.
  bool drawn(Entry* entry, uint64_t blocks);
  // Compiles the entry (`program` and `variant` must be its key's; no variant for a verdict
  // entry) and returns its function, or null if native code does not run it.
  void* compile(Entry* entry, const PixelProgram& program, const NativePixelVariant* variant);
  void* compileSetup(Entry* entry, const SetupProgram& program, const NativeSetupVariant& variant);
  void* compileBlockVerdicts(Entry* entry, const PixelProgram& program, NativeIsa isa, int lanes);


  // The thresholds (kDefault*Threshold, or the environment's at start-up); tests set 0.
  uint64_t threshold() const { return threshold_.load(std::memory_order_relaxed); }
  void setThreshold(uint64_t blocks) { threshold_.store(blocks, std::memory_order_relaxed); }
  uint64_t walkThreshold() const { return walk_threshold_.load(std::memory_order_relaxed); }
  void setWalkThreshold(uint64_t regions) { walk_threshold_.store(regions, std::memory_order_relaxed); }
  uint64_t setupThreshold() const { return setup_threshold_.load(std::memory_order_relaxed); }
  void setSetupThreshold(uint64_t instances) { setup_threshold_.store(instances, std::memory_order_relaxed); }

  NativeCacheStats stats() const;

  NativeProgramCache(const NativeProgramCache&) = delete;
  NativeProgramCache& operator=(const NativeProgramCache&) = delete;

 private:
  NativeProgramCache();
  ~NativeProgramCache();
  struct Impl;
  Entry* entryFor(const std::string& key, Entry::Kind kind);
  // Compiles the module `build` makes (a function of the name it is given, in the context;
  // what it returns: native_cache.cpp's Built) for the entry, and settles the entry.
  using ModuleBuilder = std::function<int(const std::string& name, llvm::LLVMContext& context,
                                          std::unique_ptr<llvm::Module>& module, std::string& error)>;
  void* compileWith(Entry* entry, const char* what, const ModuleBuilder& build);
  Impl* impl_;
  std::atomic<uint64_t> threshold_;
  std::atomic<uint64_t> walk_threshold_;
  std::atomic<uint64_t> setup_threshold_;
};

// What `pfc --emit=native` prints for `program` under `variant`: the optimized LLVM IR and the
// assembly; false with `error` set when native code cannot run it.
bool nativePixelListing(const PixelProgram& program, const NativePixelVariant& variant, std::string& listing,
                        std::string& error);
bool nativeSetupListing(const SetupProgram& program, const NativeSetupVariant& variant, std::string& listing,
                        std::string& error);

}  // namespace pf
