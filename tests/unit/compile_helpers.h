// Test helpers: compile a source string, run one instance of a primitive over one pixel block.
#pragma once

#include <bit>
#include <string>
#include <vector>

#include "compiler/compiler.h"
#include "compiler/native/native_cache.h"
#include "compiler/native/pixel_codegen.h"
#include "raster/pixel_executor.h"
#include "raster/setup_executor.h"
#include "reference_interpreter.h"

#include <gtest/gtest.h>

namespace pf::test {

struct Compiled {
  bool ok = false;
  std::string diagnostics;
  CompiledModule module;
  const CompiledPrimitive* find(const std::string& name) const {
    for (auto& p : module.primitives)
      if (p->name == name) return p.get();
    return nullptr;
  }
};

inline Compiled compile(const std::string& source, const std::string& name = "test.pfl", bool optimize = true,
                        std::string* explain = nullptr) {
  Compiled c;
  DiagnosticLog log;
  c.ok = compileSource(name, source, c.module, log, explain ? EmitStage::Explain : EmitStage::None, explain, optimize);
  c.diagnostics = log.format();
  return c;
}

inline uint32_t f2u(float f) { return std::bit_cast<uint32_t>(f); }

// Runs setup and then the pixel program of `prim` over the 8x8 block at (0, 0) of an 8x8
// framebuffer whose depth starts at `initial_depth`. Results: depth and channel values.
struct BlockRun {
  bool killed = false;
  SetupOutput setup;
  BlockCounters counters;
  std::vector<float> depth = std::vector<float>(64, 1.0f);
  std::vector<uint32_t> shade_ids = std::vector<uint32_t>(64 * 64, 0);
  std::vector<float> channels;  // slot-major planes of 64*64
  float channel(int slot, int x, int y) const { return channels[static_cast<size_t>(slot) * 4096 + y * 64 + x]; }
  bool drawn(int x, int y) const { return shade_ids[y * 64 + x] != 0; }
};

// The same with the channels laid out by `layout` (e.g. channels bound to shared interpolators).
inline BlockRun runBlockIn(const CompiledPrimitive& prim, const std::vector<float>& params,
                           const std::vector<float>& vertex_channels, const ChannelLayout& layout,
                           bool depth_test = true, float initial_depth = 1.0f, uint32_t iteration_cap = 65536,
                           int sequence_points = -1, const field::FieldTable* fields = nullptr) {
  const int nch = layout.count;
  BlockRun r;
  std::fill(r.depth.begin(), r.depth.end(), initial_depth);
  std::vector<uint32_t> p(params.size());
  for (size_t i = 0; i < params.size(); ++i) p[i] = f2u(params[i]);
  RasterState st;
  st.vp_scale_x = 4;
  st.vp_offset_x = 4;
  st.vp_scale_y = 4;
  st.vp_offset_y = 4;
  st.vp_x1 = 8;
  st.vp_y1 = 8;
  st.depth_test = depth_test;
  st.iteration_cap = iteration_cap;
  st.fields = fields;
  std::vector<uint32_t> record(SetupExecutor::recordWords(prim, nch) + 1);
  SetupExecutor setup;
  r.setup = setup.run(prim, SetupInput{p.data(), vertex_channels.data(), &layout, &st,
                                      sequence_points < 0 ? prim.sequence_points : sequence_points}, record.data());
  r.killed = r.setup.killed;
  if (r.killed) return r;
  r.channels.assign(static_cast<size_t>(std::max(nch, 1)) * 4096, 0.0f);
  std::vector<float*> planes;
  for (int i = 0; i < std::max(nch, 1); ++i) planes.push_back(r.channels.data() + static_cast<size_t>(i) * 4096);
  BlockTarget t;
  t.depth = r.depth.data();
  t.depth_stride = 8;
  t.shade_ids = r.shade_ids.data();
  t.slots = planes.data();
  PixelExecutor ex;
  ex.use_native = false;
  ex.runBlock(prim, record.data(), layout, st, 1, 0, 0, ~0ull, t);
  r.counters = ex.counters;
  // The block again as native code (compiler/native/), compiled on its first block: the
  // same depth, shading ids and channels to the bit, the same lanes stopped by the cap.
  {
    NativeProgramCache::instance().setThreshold(0);
    std::vector<float> depth(64, initial_depth);
    std::vector<uint32_t> ids(64 * 64, 0);
    std::vector<float> channels(r.channels.size(), 0.0f);
    std::vector<float*> native_planes;
    for (int i = 0; i < std::max(nch, 1); ++i) native_planes.push_back(channels.data() + static_cast<size_t>(i) * 4096);
    BlockTarget nt = t;
    nt.depth = depth.data();
    nt.shade_ids = ids.data();
    nt.slots = native_planes.data();
    PixelExecutor nx;
    nx.use_native = true;
    nx.runBlock(prim, record.data(), layout, st, 1, 0, 0, ~0ull, nt);
    bool compiles = nativeCodeAvailable() && nativePixelSupports(prim.pixel);
    for (const ChannelLayout::SharedInterpolator& s : layout.shared)
      compiles = compiles && nativePixelSupports(s.program->pixel);
    if (compiles) {
      EXPECT_EQ(nx.counters.blocks_native, nx.counters.blocks_run) << "the block did not run as native code";
    }
    EXPECT_EQ(nx.counters.lanes_committed, ex.counters.lanes_committed);
    EXPECT_EQ(nx.counters.iteration_cap_lanes, ex.counters.iteration_cap_lanes);
    for (int i = 0; i < 64; ++i)
      EXPECT_EQ(std::bit_cast<uint32_t>(depth[i]), std::bit_cast<uint32_t>(r.depth[i]))
          << "native code and interpreter disagree on depth at lane " << i;
    EXPECT_TRUE(ids == r.shade_ids) << "native code and interpreter disagree on the pixels drawn";
    size_t differing = 0;
    for (size_t i = 0; i < channels.size(); ++i)
      differing += std::bit_cast<uint32_t>(channels[i]) != std::bit_cast<uint32_t>(r.channels[i]);
    EXPECT_EQ(differing, 0u) << "native code and interpreter disagree on G-buffer channel values";
  }
  // The second execution mode: every lane again through the scalar reference interpreter of
  // the IR, which must agree exactly with setup + SIMD pixel program.
  if (prim.ir) {
    for (int i = 0; i < 64; ++i) {
      int x = i % 8, y = i / 8;
      ReferencePixel ref = runReference(*prim.ir, p, vertex_channels, layout, st, x + 0.5f, y + 0.5f, initial_depth);
      EXPECT_EQ(ref.drawn, r.drawn(x, y)) << "reference and SIMD disagree on coverage at lane " << i;
      float want_depth = ref.drawn && ref.depth_written ? ref.depth : initial_depth;
      EXPECT_EQ(std::bit_cast<uint32_t>(want_depth), std::bit_cast<uint32_t>(r.depth[i]))
          << "reference and SIMD disagree on depth at lane " << i << ": " << want_depth << " vs " << r.depth[i];
      if (ref.drawn) {
        for (int ch = 0; ch < nch; ++ch) {
          EXPECT_EQ(std::bit_cast<uint32_t>(ref.channels[ch]), std::bit_cast<uint32_t>(r.channel(ch, x, y)))
              << "reference and SIMD disagree on channel " << ch << " at lane " << i;
        }
      }
    }
  }
  return r;
}

inline BlockRun runBlock(const CompiledPrimitive& prim, const std::vector<float>& params,
                         const std::vector<float>& vertex_channels, int nch, bool depth_test = true,
                         float initial_depth = 1.0f, InterpKind kind = InterpKind::PerspectiveLinear,
                         uint32_t iteration_cap = 65536, int sequence_points = -1,
                         const field::FieldTable* fields = nullptr) {
  return runBlockIn(prim, params, vertex_channels, ChannelLayout::ofKind(nch, kind), depth_test, initial_depth,
                    iteration_cap, sequence_points, fields);
}

}  // namespace pf::test
