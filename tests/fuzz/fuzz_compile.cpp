// libFuzzer target for the primitive language: every input is compiled as source, listed at
// every stage, and -- when it compiles -- each of its primitives is run once (setup, and the
// pixel program over one 8x8 block). The same bytes also choose a generated source of a shape
// that breaks compilers (adversarial.h: long chains, deep nesting, call chains, inlining that
// fans out, extreme literals), compiled once at a stage they choose. Every compile runs on a
// 1 MB stack. Nothing may crash, hang (-timeout), or trip ASan/UBSan.
//
// Build and run locally (clang, libclang-rt-14-dev):
//   cmake -S . -B build-fuzz -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
//         -DPRIMFLOW_SANITIZE=address,undefined -DPRIMFLOW_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
//   cmake --build build-fuzz --target fuzz_compile
//   cp -r tests/fuzz/corpus/compile /tmp/corpus && build-fuzz/bin/fuzz_compile /tmp/corpus -max_total_time=60
#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "adversarial.h"
#include "compiler/compiler.h"
#include "raster/pixel_executor.h"
#include "raster/setup_executor.h"

namespace {

// Compiles `text` (listing `stage`); compiled without a listing, runs each primitive once, with
// small parameter values taken from `data`.
void compileAndRun(const std::string& text, pf::EmitStage stage, const uint8_t* data, size_t size) {
  pf::CompiledModule module;
  pf::DiagnosticLog log;
  std::string listing;
  const bool ok = pf::compileSource("fuzz.pfl", text, module, log, stage, &listing);
  (void)log.format();
  if (!ok || stage != pf::EmitStage::None) return;
  const pf::ChannelLayout layout = pf::ChannelLayout::ofKind(4, pf::InterpKind::PerspectiveLinear);
  pf::RasterState state;
  state.vp_scale_x = state.vp_offset_x = state.vp_scale_y = state.vp_offset_y = 4.0f;
  state.vp_x1 = state.vp_y1 = 8;
  state.depth_test = true;
  state.iteration_cap = 1000;  // runaway loops stop quickly
  for (const auto& prim : module.primitives) {
    std::vector<uint32_t> params(static_cast<size_t>(prim->param_floats));
    for (size_t i = 0; i < params.size(); ++i) {
      float v = size ? static_cast<float>(data[i % size]) / 16.0f - 4.0f : 0.5f;
      params[i] = std::bit_cast<uint32_t>(v);
    }
    std::vector<float> channels(static_cast<size_t>(prim->sequence_points) * 4, 0.5f);
    std::vector<uint32_t> record(pf::SetupExecutor::recordWords(*prim, layout.count) + 1);
    pf::SetupExecutor setup;
    pf::SetupOutput out = setup.run(*prim, {params.data(), channels.data(), &layout, &state}, record.data());
    if (out.killed) continue;
    std::vector<float> depth(64, 1.0f);
    std::vector<uint32_t> ids(64 * 64, 0);
    std::vector<float> planes(4 * 64 * 64, 0.0f);
    float* slots[4] = {planes.data(), planes.data() + 4096, planes.data() + 8192, planes.data() + 12288};
    pf::BlockTarget target;
    target.depth = depth.data();
    target.depth_stride = 8;
    target.shade_ids = ids.data();
    target.slots = slots;
    pf::PixelExecutor pixels;
    pixels.runBlock(*prim, record.data(), layout, state, 1, 0, 0, ~0ull, target);
  }
}

constexpr pf::EmitStage kStages[] = {pf::EmitStage::None, pf::EmitStage::Ast, pf::EmitStage::Ir,
                                     pf::EmitStage::Setup, pf::EmitStage::Pixel, pf::EmitStage::Explain};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  pf::fuzz::onSmallStack([&] {
    if (size <= 64 * 1024) {
      const std::string text(reinterpret_cast<const char*>(data), size);
      for (pf::EmitStage stage : kStages) compileAndRun(text, stage, data, size);
    }
    pf::fuzz::Choices in(data, size);
    const pf::EmitStage stage = kStages[in.ConsumeIntegralInRange<size_t>(0, 5)];
    compileAndRun(pf::fuzz::languageSource(in), stage, data, size);
  });
  return 0;
}
