// pfview's primflow side: a context of its own (with a thread count the viewer can change)
// rendering a scene, seen through a camera, into an RGBA buffer -- at full size, or at a
// fraction of it while the camera moves (progressive refinement).
#pragma once

#include <primflow/gl.h>

#include <string>
#include <vector>

#include "scene/scene.h"

namespace pf::view {

class FrameRenderer {
 public:
  // threads = 0: PF_NUM_THREADS or all cores.
  explicit FrameRenderer(int threads);
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  // A new context with `threads` rasterizer threads (the scene's sources are compiled again
  // at the next render). False if it cannot be created (the old one stays).
  bool setThreads(int threads);
  int threads() const;

  // Renders `scene` through `camera` at width x height. `scene_generation` names the scene's
  // version: a new one compiles its sources into the context again. False, with the message
  // in `error`, if the scene fails to draw; the buffer then holds what was drawn.
  bool render(const scene::Scene& scene, int scene_generation, const scene::Camera& camera, int width, int height,
              std::string& error);

  const std::vector<unsigned char>& pixels() const { return pixels_; }  // RGBA, bottom row first
  int width() const { return width_; }
  int height() const { return height_; }
  double milliseconds() const { return milliseconds_; }  // of the last render, glFinish included
  // The last render's depth buffer (window depth, rows bottom to top), or null.
  const float* depth() const;
  // Implicit surfaces in the last render: field evaluations per ray (0 without any).
  double fieldEvaluationsPerRay() const { return field_evaluations_per_ray_; }

 private:
  PFcontext ctx_ = nullptr;
  int compiled_generation_ = -1;
  std::vector<unsigned char> pixels_;
  int width_ = 0, height_ = 0;
  double milliseconds_ = 0;
  double field_evaluations_per_ray_ = 0;
};

}  // namespace pf::view
