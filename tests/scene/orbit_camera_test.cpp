// pfview's orbit camera (tools/pfview/orbit_camera.cpp): orbiting keeps the distance and comes
// back after a full turn, stops short of the pole, panning moves eye and target together by the
// world size of the pixels at the target, zooming scales the distance (or the ortho height).
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>

#include "pfview/orbit_camera.h"

namespace {

pf::scene::Camera start() {
  pf::scene::Camera c;
  c.eye = {1, 2, 5};
  c.target = {0.5, 0, 0};
  c.up = {0, 1, 0};
  c.fov_degrees = 60;
  return c;
}

TEST(OrbitCamera, AFullTurnComesBackAndKeepsTheDistance) {
  pf::view::OrbitCamera cam(start());
  const double d0 = glm::length(start().eye - start().target);
  for (int i = 0; i < 36; ++i) {
    cam.orbit(10, 0);
    EXPECT_NEAR(glm::length(cam.camera().eye - cam.camera().target), d0, 1e-9);
    EXPECT_NEAR(cam.camera().eye.y, 2, 1e-9);  // yaw keeps the height above the target
  }
  EXPECT_NEAR(glm::length(cam.camera().eye - start().eye), 0, 1e-9);
}

TEST(OrbitCamera, PitchStopsShortOfThePole) {
  pf::view::OrbitCamera cam(start());
  cam.orbit(0, 500);
  const glm::dvec3 dir = glm::normalize(cam.camera().eye - cam.camera().target);
  EXPECT_NEAR(std::asin(dir.y) * 180 / M_PI, 89.0, 1e-6);
  EXPECT_GT(glm::length(glm::cross(dir, glm::dvec3(0, 1, 0))), 0.01);  // still a valid view
}

TEST(OrbitCamera, PanMovesEyeAndTargetByTheirPixelSize) {
  pf::view::OrbitCamera cam(start());
  const double d = glm::length(start().eye - start().target);
  const double per_pixel = 2 * d * std::tan(M_PI / 6) / 100;  // fov 60, a view 100 pixels tall
  cam.pan(10, 0, 100);
  const glm::dvec3 moved = cam.camera().target - start().target;
  EXPECT_NEAR(glm::length(moved), 10 * per_pixel, 1e-9);
  EXPECT_NEAR(glm::length((cam.camera().eye - start().eye) - moved), 0, 1e-12);
  EXPECT_NEAR(glm::dot(moved, start().target - start().eye), 0, 1e-9);  // across the view
}

TEST(OrbitCamera, ZoomScalesTheDistanceOrTheOrthoHeight) {
  pf::view::OrbitCamera cam(start());
  const double d0 = glm::length(start().eye - start().target);
  cam.zoom(0.5);
  EXPECT_NEAR(glm::length(cam.camera().eye - cam.camera().target), d0 * 0.5, 1e-9);
  pf::scene::Camera o = start();
  o.ortho = true;
  o.height = 4;
  pf::view::OrbitCamera ortho(o);
  ortho.zoom(2);
  EXPECT_NEAR(ortho.camera().height, 8, 1e-12);
  EXPECT_EQ(ortho.camera().eye, o.eye);
}

}  // namespace
