// The process-wide cache of native programs (see native_cache.h).
#include "compiler/native/native_cache.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <mutex>
#include <unordered_map>

#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/Module.h>
#include <llvm/IR/Verifier.h>
#include <llvm/Support/raw_ostream.h>

#include "compiler/native/jit_engine.h"
#include "compiler/native/pixel_codegen.h"
#include "compiler/native/setup_codegen.h"

namespace pf {

bool nativeCodeWantedByEnvironment() {
  const char* e = std::getenv("PF_JIT");
  return !(e && std::strcmp(e, "0") == 0);
}

bool nativeCodeAvailable() { return JitEngine::instance() != nullptr; }

namespace {

// The key: every byte that can change the generated code. Written into a buffer the caller
// keeps, so that finding a function compiled before allocates nothing (a frame's draws look
// their programs up again each frame: raster/native_blocks.h).
class KeyWriter {
 public:
  explicit KeyWriter(std::string& key) : key_(key) { key_.clear(); }
  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const char* p = reinterpret_cast<const char*>(&v);
    key_.append(p, sizeof v);
  }
  void program(const PixelProgram& p) {
    bytecode(p);
    put(p.num_uniform_slots);
    put(p.num_interp_uniform_slots);
    put(p.reads_surface);
  }
  void words(const std::vector<uint32_t>& v) {
    put(v.size());
    key_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(uint32_t));
  }
  void bytecode(const Bytecode& p) {
    put(p.code.size());
    for (const Instr& in : p.code) {
      put(in.op);
      put(in.imm);
      put(in.dst);
      put(in.a);
      put(in.b);
      put(in.c);
      put(in.d);
      put(in.masked_write);
    }
    put(p.constants.size());
    key_.append(reinterpret_cast<const char*>(p.constants.data()), p.constants.size() * sizeof(uint32_t));
    put(p.num_regs);
    put(p.num_interp_regs);
  }
  void variant(const NativeSetupVariant& v) {
    put(v.isa);
    put(v.channels);
    put(v.kind_begin);
    put(v.kind_end);
    put(v.named_bound.size());
    for (bool b : v.named_bound) put(b);
  }
  void variant(const NativePixelVariant& v) {
    put(v.isa);
    put(v.gang);
    put(v.channels);
    put(v.kind_begin);
    put(v.kind_end);
    put(v.commit_surface);
    put(v.surface_eye);
    put(v.writes_normal);
    put(v.shared.size());
    for (const NativePixelVariant::Shared& s : v.shared) {
      put(s.first);
      put(s.record_offset);
      put(s.named_index);
      if (s.named_index < 0 && s.pixel) program(*s.pixel);
    }
    put(v.named_bound.size());
    for (bool b : v.named_bound) put(b);
  }

 private:
  std::string& key_;
};

enum class Built { Yes, Unsupported, Unavailable, Broken };

// A module holding the function `build` adds (named `name`), with its target set for `isa`.
Built buildModule(const std::function<llvm::Function*(llvm::Module&, const std::string&, std::string&)>& build,
                  NativeIsa isa, const std::string& name, llvm::LLVMContext& context,
                  std::unique_ptr<llvm::Module>& module, std::string& error) {
  JitEngine* engine = JitEngine::instance();
  if (!engine) {
    error = "native code is unavailable";
    return Built::Unavailable;
  }
  module = std::make_unique<llvm::Module>("primflow." + name, context);
  llvm::Function* fn = build(*module, name, error);
  if (!fn) return Built::Unsupported;
  engine->setTarget(*fn, isa);
  std::string problems;
  llvm::raw_string_ostream os(problems);
  if (llvm::verifyModule(*module, &os)) {
    error = "generated code does not verify: " + os.str();
    return Built::Broken;
  }
  return Built::Yes;
}

// The pixel function for `program` under `variant` -- or, without a variant, its
// block-rejection walk (scalar code: the baseline instruction set computes it as well as any).
Built buildPixelModule(const PixelProgram& program, const NativePixelVariant* variant, const std::string& name,
                       llvm::LLVMContext& context, std::unique_ptr<llvm::Module>& module, std::string& error) {
  auto build = [&](llvm::Module& m, const std::string& n, std::string& e) {
    return variant ? buildPixelFunction(m, n, program, *variant, e) : buildVerdictFunction(m, n, program, e);
  };
  return buildModule(build, variant ? variant->isa : NativeIsa::Sse2, name, context, module, error);
}

// The walk over `lanes` regions at once, as vectors of `isa`.
Built buildBlockVerdictsModule(const PixelProgram& program, NativeIsa isa, int lanes, const std::string& name,
                               llvm::LLVMContext& context, std::unique_ptr<llvm::Module>& module, std::string& error) {
  auto build = [&](llvm::Module& m, const std::string& n, std::string& e) {
    return buildBlockVerdictsFunction(m, n, program, lanes, e);
  };
  return buildModule(build, isa, name, context, module, error);
}

Built buildSetupModule(const SetupProgram& program, const NativeSetupVariant& variant, const std::string& name,
                       llvm::LLVMContext& context, std::unique_ptr<llvm::Module>& module, std::string& error) {
  auto build = [&](llvm::Module& m, const std::string& n, std::string& e) {
    return buildSetupFunction(m, n, program, variant, e);
  };
  return buildModule(build, variant.isa, name, context, module, error);
}

}  // namespace

struct NativeProgramCache::Impl {
  mutable std::mutex mutex;
  std::unordered_map<std::string, std::unique_ptr<Entry>> entries;
  NativeCacheStats stats;
  uint64_t serial = 0;  // names the functions: pf_pixel_<serial>
};

namespace {

uint64_t thresholdFromEnvironment(const char* name, uint64_t fallback) {
  const char* e = std::getenv(name);
  if (!e || !*e) return fallback;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(e, &end, 10);
  if (*end != '\0') {
    std::fprintf(stderr, "primflow: %s=%s is not a number: %llu used\n", name, e,
                 static_cast<unsigned long long>(fallback));
    return fallback;
  }
  return v;
}

}  // namespace

NativeProgramCache::NativeProgramCache()
    : impl_(new Impl),
      threshold_(thresholdFromEnvironment("PF_JIT_THRESHOLD", kDefaultNativeThreshold)),
      walk_threshold_(thresholdFromEnvironment("PF_JIT_WALK_THRESHOLD", kDefaultWalkThreshold)),
      setup_threshold_(thresholdFromEnvironment("PF_JIT_SETUP_THRESHOLD", kDefaultSetupThreshold)) {}
NativeProgramCache::~NativeProgramCache() { delete impl_; }

NativeProgramCache& NativeProgramCache::instance() {
  static NativeProgramCache* cache = new NativeProgramCache;  // never destroyed (jit_engine.h)
  return *cache;
}

NativeCacheStats NativeProgramCache::stats() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->stats;
}

NativeProgramCache::Entry* NativeProgramCache::entryFor(const std::string& key, Entry::Kind kind) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  auto it = impl_->entries.find(key);
  if (it != impl_->entries.end()) return it->second.get();
  Entry* e = impl_->entries.emplace(key, std::make_unique<Entry>()).first->second.get();
  e->kind_ = kind;
  return e;
}

NativeProgramCache::Entry* NativeProgramCache::pixelEntry(const PixelProgram& program, const NativePixelVariant& variant) {
  thread_local std::string key;
  KeyWriter w(key);
  w.put('p');
  w.put(nativeFaultForTesting());
  w.program(program);
  w.variant(variant);
  return entryFor(key, Entry::Kind::Pixel);
}

NativeProgramCache::Entry* NativeProgramCache::verdictEntry(const PixelProgram& program) {
  thread_local std::string key;
  KeyWriter w(key);
  w.put('v');
  w.program(program);
  w.put(program.last_early_retire);
  w.put(program.last_coverage_retire);
  w.put(program.covered != nullptr);
  return entryFor(key, Entry::Kind::Verdict);
}

NativeProgramCache::Entry* NativeProgramCache::blockVerdictsEntry(const PixelProgram& program, NativeIsa isa,
                                                                   int lanes) {
  thread_local std::string key;
  KeyWriter w(key);
  w.put('b');
  w.put(isa);
  w.put(lanes);
  w.program(program);
  w.put(program.last_early_retire);
  w.put(program.last_coverage_retire);
  w.put(program.covered != nullptr);
  return entryFor(key, Entry::Kind::BlockVerdicts);
}

NativeProgramCache::Entry* NativeProgramCache::setupEntry(const SetupProgram& program, const NativeSetupVariant& variant) {
  thread_local std::string key;
  KeyWriter w(key);
  w.put('s');
  w.bytecode(program);
  w.words(program.scalar_exports);  // (the function writes the records)
  w.words(program.interp_exports);
  w.variant(variant);
  return entryFor(key, Entry::Kind::Setup);
}

bool NativeProgramCache::drawn(Entry* entry, uint64_t blocks) {
  if (entry->status_.load(std::memory_order_acquire) != Entry::kCold) return false;
  const uint64_t threshold = entry->kind_ == Entry::Kind::Verdict || entry->kind_ == Entry::Kind::BlockVerdicts
                                 ? walkThreshold()
                             : entry->kind_ == Entry::Kind::Setup ? setupThreshold()
                                                                  : this->threshold();
  if (entry->blocks_.fetch_add(blocks, std::memory_order_relaxed) + blocks <= threshold) return false;
  // One thread compiles (the others interpret meanwhile).
  uint8_t cold = Entry::kCold;
  return entry->status_.compare_exchange_strong(cold, Entry::kCompiling, std::memory_order_acq_rel);
}

void* NativeProgramCache::compileBlockVerdicts(Entry* entry, const PixelProgram& program, NativeIsa isa, int lanes) {
  return compileWith(entry, "block-rejection walk over several regions",
                     [&](const std::string& name, llvm::LLVMContext& context, std::unique_ptr<llvm::Module>& module,
                         std::string& error) {
                       return static_cast<int>(
                           buildBlockVerdictsModule(program, isa, lanes, name, context, module, error));
                     });
}

void* NativeProgramCache::compile(Entry* entry, const PixelProgram& program, const NativePixelVariant* variant) {
  const bool verdict = entry->kind_ == Entry::Kind::Verdict;
  return compileWith(entry, verdict ? "block-rejection walk" : "pixel program",
                     [&](const std::string& name, llvm::LLVMContext& context, std::unique_ptr<llvm::Module>& module,
                         std::string& error) {
                       return static_cast<int>(buildPixelModule(program, verdict ? nullptr : variant, name, context,
                                                                module, error));
                     });
}

void* NativeProgramCache::compileSetup(Entry* entry, const SetupProgram& program, const NativeSetupVariant& variant) {
  return compileWith(entry, "setup program",
                     [&](const std::string& name, llvm::LLVMContext& context, std::unique_ptr<llvm::Module>& module,
                         std::string& error) {
                       return static_cast<int>(buildSetupModule(program, variant, name, context, module, error));
                     });
}

void* NativeProgramCache::compileWith(Entry* entry, const char* what, const ModuleBuilder& build) {
  uint64_t serial;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    serial = impl_->serial++;
  }
  const auto start = std::chrono::steady_clock::now();
  void* function = nullptr;
  bool refused = false, failed = false;
  std::string error;
  auto context = std::make_unique<llvm::LLVMContext>();
  std::unique_ptr<llvm::Module> module;
  const char* prefix = entry->kind_ == Entry::Kind::Verdict          ? "pf_verdict_"
                       : entry->kind_ == Entry::Kind::BlockVerdicts ? "pf_block_verdicts_"
                       : entry->kind_ == Entry::Kind::Setup ? "pf_setup_"
                                                            : "pf_pixel_";
  const std::string name = prefix + std::to_string(serial);
  std::vector<void*> addresses;
  switch (static_cast<Built>(build(name, *context, module, error))) {
    case Built::Yes:
      if (JitEngine::instance()->add(std::move(module), std::move(context), {name}, addresses, error))
        function = addresses[0];
      else
        failed = true;
      break;
    case Built::Unsupported: refused = true; break;  // (a field search, here or in an interpolator)
    case Built::Unavailable: break;                   // (said once by JitEngine)
    case Built::Broken: failed = true; break;
  }
  if (failed) std::fprintf(stderr, "primflow: native code for a %s failed (%s): it runs on the interpreter\n", what, error.c_str());
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    if (function) ++impl_->stats.compiled;
    if (refused) ++impl_->stats.refused;
    if (failed) ++impl_->stats.failed;
    impl_->stats.milliseconds += ms;
  }
  entry->function_.store(function, std::memory_order_release);
  entry->status_.store(function ? Entry::kReady : Entry::kNone, std::memory_order_release);
  return function;
}

bool nativePixelListing(const PixelProgram& program, const NativePixelVariant& variant, std::string& listing,
                        std::string& error) {
  llvm::LLVMContext context;
  std::unique_ptr<llvm::Module> module;
  if (buildPixelModule(program, &variant, "pf_pixel", context, module, error) != Built::Yes) return false;
  listing = JitEngine::instance()->listing(*module);
  return true;
}

bool nativeSetupListing(const SetupProgram& program, const NativeSetupVariant& variant, std::string& listing,
                        std::string& error) {
  llvm::LLVMContext context;
  std::unique_ptr<llvm::Module> module;
  if (buildSetupModule(program, variant, "pf_setup", context, module, error) != Built::Yes) return false;
  listing = JitEngine::instance()->listing(*module);
  return true;
}

}  // namespace pf
