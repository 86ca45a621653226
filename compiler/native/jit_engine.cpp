// The process's LLJIT (see jit_engine.h).
#include "compiler/native/jit_engine.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

#include <llvm/ADT/StringMap.h>
#include <llvm/ExecutionEngine/JITEventListener.h>
#include <llvm/ExecutionEngine/Orc/CompileUtils.h>
#include <llvm/ExecutionEngine/Orc/ExecutionUtils.h>
#include <llvm/ExecutionEngine/Orc/LLJIT.h>
#include <llvm/ExecutionEngine/Orc/RTDyldObjectLinkingLayer.h>
#include <llvm/ExecutionEngine/SectionMemoryManager.h>
#include <llvm/IR/LegacyPassManager.h>
#include <llvm/IR/Module.h>
#include <llvm/Object/SymbolSize.h>
#include <llvm/Passes/PassBuilder.h>
#include <llvm/Transforms/InstCombine/InstCombine.h>
#include <llvm/Transforms/Scalar/ADCE.h>
#include <llvm/Transforms/Scalar/EarlyCSE.h>
#include <llvm/Transforms/Scalar/GVN.h>
#include <llvm/Transforms/Scalar/LICM.h>
#include <llvm/Transforms/Scalar/SROA.h>
#include <llvm/Transforms/Scalar/SimplifyCFG.h>
#include <llvm/Support/Host.h>
#include <llvm/Support/TargetSelect.h>
#include <llvm/Support/raw_ostream.h>
#include <llvm/Target/TargetMachine.h>

#include "compiler/native/native_runtime.h"

namespace pf {

const char* nativeIsaName(NativeIsa isa) {
  switch (isa) {
    case NativeIsa::Sse2: return "sse2";
    case NativeIsa::Avx2: return "avx2";
    case NativeIsa::Avx512: return "avx512";
  }
  return "?";
}

struct JitEngine::State {
  std::unique_ptr<llvm::orc::LLJIT> jit;
  llvm::orc::JITTargetMachineBuilder machine{llvm::Triple()};
  // PF_JIT_PERF=1: perf sees the functions by name -- /tmp/perf-PID.map, which `perf report`
  // reads by itself, and LLVM's jitdump files for `perf inject --jit`.
  bool perf = false;
  std::mutex perf_mutex;
  FILE* perf_map = nullptr;
  llvm::JITEventListener* perf_listener = nullptr;
};

namespace {

// Writes the loaded object's functions to perf's map file: "address size name" per line.
void writePerfMap(FILE* map, std::mutex& mutex, const llvm::object::ObjectFile& object,
                  const llvm::RuntimeDyld::LoadedObjectInfo& loaded) {
  std::lock_guard<std::mutex> lock(mutex);
  for (const auto& [symbol, size] : llvm::object::computeSymbolSizes(object)) {
    auto type = symbol.getType();
    if (!type || *type != llvm::object::SymbolRef::ST_Function) continue;
    auto name = symbol.getName();
    auto address = symbol.getAddress();
    auto section = symbol.getSection();
    if (!name || !address || !section || *section == object.section_end()) continue;
    const uint64_t load = loaded.getSectionLoadAddress(**section);
    if (load == 0) continue;
    const uint64_t at = load + (*address - (*section)->getAddress());
    std::fprintf(map, "%llx %llx %s\n", static_cast<unsigned long long>(at), static_cast<unsigned long long>(size),
                 name->str().c_str());
  }
  std::fflush(map);
}

}  // namespace

JitEngine* JitEngine::instance() {
  static JitEngine* engine = [] {
    auto* e = new JitEngine;  // never destroyed (see jit_engine.h)
    std::string error;
    if (!e->initialise(error)) {
      std::fprintf(stderr, "primflow: native code unavailable (%s): programs run on the interpreter\n",
                   error.c_str());
      delete e;
      return static_cast<JitEngine*>(nullptr);
    }
    return e;
  }();
  return engine;
}

bool JitEngine::initialise(std::string& error) {
#if !defined(__x86_64__)
  error = "native code is generated for x86-64 only";
  return false;
#else
  // For the test of this fallback (tests/CMakeLists.txt: pfrender.native_code_unavailable).
  if (const char* e = std::getenv("PF_JIT_TEST_INIT_FAILURE"); e && *e && std::strcmp(e, "0") != 0) {
    error = "PF_JIT_TEST_INIT_FAILURE is set";
    return false;
  }
  if (llvm::InitializeNativeTarget() || llvm::InitializeNativeTargetAsmPrinter()) {
    error = "LLVM has no target for this host";
    return false;
  }
  auto state = std::make_shared<State>();
  auto machine = llvm::orc::JITTargetMachineBuilder::detectHost();
  if (!machine) {
    error = llvm::toString(machine.takeError());
    return false;
  }
  state->machine = std::move(*machine);
  state->machine.setCodeGenOptLevel(llvm::CodeGenOpt::Default);
  // No fused multiply-add: the interpreter rounds every product (bit-identical results).
  state->machine.getOptions().AllowFPOpFusion = llvm::FPOpFusion::Strict;
  host_cpu_ = llvm::sys::getHostCPUName().str();
  llvm::StringMap<bool> features;
  if (llvm::sys::getHostCPUFeatures(features))
    for (const auto& f : features) host_features_ += (host_features_.empty() ? "" : ",") + std::string(f.second ? "+" : "-") + f.first().str();

  const char* perf = std::getenv("PF_JIT_PERF");
  state->perf = perf && *perf && std::strcmp(perf, "0") != 0;
  if (state->perf) {
    char path[64];
    std::snprintf(path, sizeof path, "/tmp/perf-%d.map", static_cast<int>(getpid()));
    state->perf_map = std::fopen(path, "a");
    state->perf_listener = llvm::JITEventListener::createPerfJITEventListener();
  }
  State* raw = state.get();
  auto jit = llvm::orc::LLJITBuilder()
                 .setJITTargetMachineBuilder(state->machine)
                 // A target machine per compile: the default shares one, and the rasterizer's
                 // threads compile at once.
                 .setCompileFunctionCreator([](llvm::orc::JITTargetMachineBuilder machine)
                                                -> llvm::Expected<std::unique_ptr<llvm::orc::IRCompileLayer::IRCompiler>> {
                   return std::make_unique<llvm::orc::ConcurrentIRCompiler>(std::move(machine));
                 })
                 .setObjectLinkingLayerCreator([raw](llvm::orc::ExecutionSession& session, const llvm::Triple&) {
                   auto layer = std::make_unique<llvm::orc::RTDyldObjectLinkingLayer>(
                       session, [] { return std::make_unique<llvm::SectionMemoryManager>(); });
                   if (raw->perf_listener) layer->registerJITEventListener(*raw->perf_listener);
                   if (raw->perf_map)
                     layer->setNotifyLoaded([raw](llvm::orc::MaterializationResponsibility&,
                                                  const llvm::object::ObjectFile& object,
                                                  const llvm::RuntimeDyld::LoadedObjectInfo& loaded) {
                       writePerfMap(raw->perf_map, raw->perf_mutex, object, loaded);
                     });
                   return std::unique_ptr<llvm::orc::ObjectLayer>(std::move(layer));
                 })
                 .create();
  if (!jit) {
    error = llvm::toString(jit.takeError());
    return false;
  }
  state->jit = std::move(*jit);
  // The helpers by address; anything else LLVM calls (floorf on SSE2, memset) from the process.
  llvm::orc::JITDylib& main = state->jit->getMainJITDylib();
  llvm::orc::SymbolMap helpers;
  int count = 0;
  const NativeHelper* h = nativeHelpers(count);
  for (int i = 0; i < count; ++i)
    helpers[state->jit->mangleAndIntern(h[i].name)] = llvm::JITEvaluatedSymbol(
        llvm::pointerToJITTargetAddress(h[i].address), llvm::JITSymbolFlags::Exported | llvm::JITSymbolFlags::Callable);
  if (auto err = main.define(llvm::orc::absoluteSymbols(std::move(helpers)))) {
    error = llvm::toString(std::move(err));
    return false;
  }
  auto process = llvm::orc::DynamicLibrarySearchGenerator::GetForCurrentProcess(
      state->jit->getDataLayout().getGlobalPrefix());
  if (!process) {
    error = llvm::toString(process.takeError());
    return false;
  }
  main.addGenerator(std::move(*process));
  state_ = std::move(state);
  return true;
#endif
}

void JitEngine::setTarget(llvm::Function& f, NativeIsa isa) const {
  // A function's target-features replace the machine's: every function names its own, so an
  // AVX2 function stays AVX2 on an AVX-512 host.
  switch (isa) {
    case NativeIsa::Avx512:
      f.addFnAttr("target-cpu", host_cpu_);
      f.addFnAttr("target-features", host_features_);
      // Without these LLVM splits 512-bit vectors in two on CPUs it tunes for 256 bits.
      f.addFnAttr("prefer-vector-width", "512");
      f.addFnAttr("min-legal-vector-width", "512");
      break;
    case NativeIsa::Avx2:
      f.addFnAttr("target-cpu", "x86-64-v3");
      f.addFnAttr("target-features", "+avx,+avx2,+bmi,+bmi2,+f16c,+fma,+lzcnt,+movbe,+popcnt,+sse4.1,+sse4.2,+ssse3,"
                                     "-avx512f,-avx512bw,-avx512dq,-avx512vl,-avx512cd");
      f.addFnAttr("prefer-vector-width", "256");
      break;
    case NativeIsa::Sse2:
      f.addFnAttr("target-cpu", "x86-64");
      f.addFnAttr("target-features", "+sse2,-sse3,-ssse3,-sse4.1,-sse4.2,-avx,-avx2,-avx512f,-fma,-popcnt");
      break;
  }
  f.addFnAttr(llvm::Attribute::NoUnwind);
}

void JitEngine::optimize(llvm::Module& module) const {
  auto machine = state_->machine.createTargetMachine();
  if (!machine) {
    llvm::consumeError(machine.takeError());
    return;
  }
  llvm::LoopAnalysisManager lam;
  llvm::FunctionAnalysisManager fam;
  llvm::CGSCCAnalysisManager cgam;
  llvm::ModuleAnalysisManager mam;
  llvm::PassBuilder builder(machine->get());
  builder.registerModuleAnalyses(mam);
  builder.registerCGSCCAnalyses(cgam);
  builder.registerFunctionAnalyses(fam);
  builder.registerLoopAnalyses(lam);
  builder.crossRegisterProxies(lam, fam, cgam, mam);
  // Not -O2's whole pipeline: the generated code is straight-line vector code in one loop
  // over the block's chunks, and needs its variables in registers (SROA), redundancies
  // folded, the record's loads out of the loop (LICM) and dead code gone; the rest of -O2
  // doubled the compile time without a measurable gain (docs/architecture.md).
  llvm::FunctionPassManager f;
  f.addPass(llvm::SROAPass());
  f.addPass(llvm::EarlyCSEPass(true));
  f.addPass(llvm::InstCombinePass());
  f.addPass(llvm::SimplifyCFGPass());
  f.addPass(llvm::createFunctionToLoopPassAdaptor(llvm::LICMPass(llvm::LICMOptions()), /*UseMemorySSA=*/true));
  f.addPass(llvm::GVNPass());
  f.addPass(llvm::InstCombinePass());
  f.addPass(llvm::SimplifyCFGPass());
  f.addPass(llvm::ADCEPass());
  llvm::ModulePassManager passes;
  passes.addPass(llvm::createModuleToFunctionPassAdaptor(std::move(f)));
  passes.run(module, mam);
}

bool JitEngine::add(std::unique_ptr<llvm::Module> module, std::unique_ptr<llvm::LLVMContext> context,
                    const std::vector<std::string>& symbols, std::vector<void*>& addresses, std::string& error) {
  module->setDataLayout(state_->jit->getDataLayout());
  module->setTargetTriple(state_->jit->getTargetTriple().str());
  // PF_JIT_LOG=1: a line per module on stderr -- its functions, IR instructions before and
  // after optimisation, the milliseconds each stage took.
  static const bool log = [] {
    const char* e = std::getenv("PF_JIT_LOG");
    return e && *e && std::strcmp(e, "0") != 0;
  }();
  auto instructions = [&] {
    size_t n = 0;
    for (const llvm::Function& f : *module)
      for (const llvm::BasicBlock& b : f) n += b.size();
    return n;
  };
  const auto t0 = std::chrono::steady_clock::now();
  const size_t before = log ? instructions() : 0;
  optimize(*module);
  const size_t after = log ? instructions() : 0;
  const auto t1 = std::chrono::steady_clock::now();
  if (auto err = state_->jit->addIRModule(llvm::orc::ThreadSafeModule(std::move(module), std::move(context)))) {
    error = llvm::toString(std::move(err));
    return false;
  }
  addresses.clear();
  for (const std::string& s : symbols) {
    auto address = state_->jit->lookup(s);  // (compiles and links the module)
    if (!address) {
      error = llvm::toString(address.takeError());
      return false;
    }
    addresses.push_back(address->toPtr<void*>());
  }
  if (log) {
    const auto t2 = std::chrono::steady_clock::now();
    std::fprintf(stderr, "primflow: native %s: %zu -> %zu IR instructions, optimised in %.1f ms, compiled in %.1f ms\n",
                 symbols.empty() ? "?" : symbols[0].c_str(), before, after,
                 std::chrono::duration<double, std::milli>(t1 - t0).count(),
                 std::chrono::duration<double, std::milli>(t2 - t1).count());
  }
  return true;
}

std::string JitEngine::listing(llvm::Module& module) const {
  module.setDataLayout(state_->jit->getDataLayout());
  module.setTargetTriple(state_->jit->getTargetTriple().str());
  optimize(module);
  std::string out;
  llvm::raw_string_ostream os(out);
  os << "; LLVM IR, optimized\n";
  module.print(os, nullptr);
  auto machine = state_->machine.createTargetMachine();
  if (!machine) {
    os << "; no target machine: " << llvm::toString(machine.takeError()) << "\n";
    return out;
  }
  llvm::SmallString<0> assembly;
  llvm::raw_svector_ostream as(assembly);
  llvm::legacy::PassManager pm;
  if ((*machine)->addPassesToEmitFile(pm, as, nullptr, llvm::CGFT_AssemblyFile)) {
    os << "; this target cannot print assembly\n";
    return out;
  }
  pm.run(module);
  os << "\n; assembly (" << host_cpu_ << " host)\n" << assembly;
  return out;
}

}  // namespace pf
