// The benchmark scenes drawn by primflow, through <primflow/gl_mangle.h>.
#include <primflow/gl_mangle.h>

#include <chrono>
#include <vector>

#include "api/src/context_state.h"  // the renderer's work counters
#include "bench/scene_data.h"

#include "bench/scenes.inc"

namespace pfbench {

std::vector<double> timePrimflow(const SceneData& s, int warmup, int frames, int threads, FrameWork* work,
                                 std::vector<unsigned char>* image) {
  std::vector<double> times;
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, threads, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  if (!ctx) return times;
  std::vector<unsigned char> buffer(static_cast<size_t>(s.width) * s.height * 4);
  if (!pfMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, s.width, s.height)) {
    pfDestroyContext(ctx);
    return times;
  }
  for (int i = 0; i < warmup + frames; ++i) {
    if (i == warmup) ctx->renderer.resetStats();
    auto t0 = std::chrono::steady_clock::now();
    drawSceneFrame(s);
    auto t1 = std::chrono::steady_clock::now();
    if (i >= warmup) times.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
  }
  const pf::FrameStats& st = ctx->renderer.stats();
  const uint64_t f = static_cast<uint64_t>(frames);
  work->pixels_run = st.lanes_started / f;
  work->pixels_shaded = st.pixels_shaded / f;
  work->setup_instructions = st.setup_instructions / f;
  work->pixel_instructions = st.pixel_instructions / f;
  work->blocks_run = st.blocks_run / f;
  work->blocks_native = st.blocks_native / f;
  work->blocks_rejected = st.blocks_rejected / f;
  work->blocks_accepted = st.blocks_accepted / f;
  work->blocks_packed = st.blocks_packed / f;
  if (image) *image = readFrame(s);
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
  return times;
}

}  // namespace pfbench
