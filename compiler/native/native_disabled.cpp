// primflow built without LLVM (PRIMFLOW_JIT=OFF): the native-code cache exists and answers
// that there is none, so every program runs on the interpreter.
#include <cstdio>

#include "compiler/native/native_cache.h"

namespace pf {

bool nativeCodeWantedByEnvironment() { return false; }
bool nativeCodeAvailable() { return false; }

const char* nativeIsaName(NativeIsa isa) {
  return isa == NativeIsa::Avx512 ? "avx512" : isa == NativeIsa::Avx2 ? "avx2" : "sse2";
}

struct NativeProgramCache::Impl {};
NativeProgramCache::NativeProgramCache()
    : impl_(nullptr),
      threshold_(kDefaultNativeThreshold),
      walk_threshold_(kDefaultWalkThreshold),
      setup_threshold_(kDefaultSetupThreshold) {}
NativeProgramCache::~NativeProgramCache() = default;

NativeProgramCache& NativeProgramCache::instance() {
  static NativeProgramCache* cache = new NativeProgramCache;
  return *cache;
}

NativeProgramCache::Entry* NativeProgramCache::pixelEntry(const PixelProgram&, const NativePixelVariant&) {
  static Entry none;  // never compiled
  return &none;
}

NativeProgramCache::Entry* NativeProgramCache::verdictEntry(const PixelProgram&) {
  static Entry none;
  return &none;
}

NativeProgramCache::Entry* NativeProgramCache::blockVerdictsEntry(const PixelProgram&, NativeIsa, int) {
  static Entry none;
  return &none;
}

NativeProgramCache::Entry* NativeProgramCache::setupEntry(const SetupProgram&, const NativeSetupVariant&) {
  static Entry none;
  return &none;
}

bool NativeProgramCache::drawn(Entry*, uint64_t) { return false; }

void* NativeProgramCache::compile(Entry*, const PixelProgram&, const NativePixelVariant*) { return nullptr; }
void* NativeProgramCache::compileSetup(Entry*, const SetupProgram&, const NativeSetupVariant&) { return nullptr; }
void* NativeProgramCache::compileBlockVerdicts(Entry*, const PixelProgram&, NativeIsa, int) { return nullptr; }

NativeCacheStats NativeProgramCache::stats() const { return {}; }

bool nativePixelListing(const PixelProgram&, const NativePixelVariant&, std::string&, std::string& error) {
  error = "primflow was built without LLVM (PRIMFLOW_JIT=OFF)";
  return false;
}

bool nativeSetupListing(const SetupProgram&, const NativeSetupVariant&, std::string&, std::string& error) {
  error = "primflow was built without LLVM (PRIMFLOW_JIT=OFF)";
  return false;
}

}  // namespace pf
