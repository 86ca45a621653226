// pfview's camera: the scene's camera moved by the mouse -- orbit around the target, pan across
// the view, zoom towards the target -- kept as the scene's Camera so drawing is unchanged.
#pragma once

#include "scene/scene.h"

namespace pf::view {

class OrbitCamera {
 public:
  explicit OrbitCamera(const scene::Camera& start) : camera_(start) {}

  // Turns the eye around the target: `yaw` degrees about the up vector, `pitch` degrees towards
  // it (the view never tips over the pole: it stops 1 degree short).
  void orbit(double yaw_degrees, double pitch_degrees);
  // Moves eye and target together across the view by (dx, dy) pixels of a view `height_px`
  // pixels tall, so the point under the cursor at the target's depth follows it.
  void pan(double dx, double dy, int height_px);
  // Multiplies the distance to the target (perspective) or the view's height (orthographic) by
  // `factor` (< 1: closer).
  void zoom(double factor);

  const scene::Camera& camera() const { return camera_; }

 private:
  scene::Camera camera_;
};

}  // namespace pf::view
