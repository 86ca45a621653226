// pfview's primflow side (see frame_renderer.h).
#include "pfview/frame_renderer.h"

// The context internals, for the work counters the overlay shows.
#include "api/src/context_state.h"

#include <chrono>

namespace pf::view {

namespace {
PFcontext makeContext(int threads) {
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, threads, 0};
  return pfCreateContextAttribs(attribs);
}
}  // namespace

FrameRenderer::FrameRenderer(int threads) : ctx_(makeContext(threads)) {}

FrameRenderer::~FrameRenderer() {
  if (ctx_) {
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
    pfDestroyContext(ctx_);
  }
}

bool FrameRenderer::setThreads(int threads) {
  PFcontext next = makeContext(threads);
  if (!next) return false;
  if (ctx_) {
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
    pfDestroyContext(ctx_);
  }
  ctx_ = next;
  compiled_generation_ = -1;
  width_ = height_ = 0;
  return true;
}

const float* FrameRenderer::depth() const {
  GLint w = 0, h = 0, bytes = 0;
  void* data = nullptr;
  return ctx_ && pfGetDepthBuffer(ctx_, &w, &h, &bytes, &data) ? static_cast<const float*>(data) : nullptr;
}

int FrameRenderer::threads() const { return ctx_ ? pfGetThreadCount(ctx_) : 0; }

bool FrameRenderer::render(const scene::Scene& scene, int scene_generation, const scene::Camera& camera, int width,
                           int height, std::string& error) {
  if (!ctx_) {
    error = "pfview: no primflow context";
    return false;
  }
  pixels_.resize(static_cast<size_t>(width) * height * 4);
  width_ = width;
  height_ = height;
  if (!pfMakeCurrent(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, width, height)) {
    error = "pfview: cannot bind a " + std::to_string(width) + "x" + std::to_string(height) + " buffer";
    return false;
  }
  scene::Scene seen = scene;
  seen.camera = camera;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    const bool compile = compiled_generation_ != scene_generation;
    scene::drawScene(seen, width, height, compile);
    compiled_generation_ = scene_generation;
  } catch (const scene::SceneError& e) {
    error = e.what();
    compiled_generation_ = -1;
    return false;
  }
  milliseconds_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const field::FieldCounters& f = ctx_->renderer.stats().field;
  field_evaluations_per_ray_ = f.rays ? double(f.point_evaluations) / double(f.rays) : 0.0;
  ctx_->renderer.resetStats();
  return true;
}

}  // namespace pf::view
