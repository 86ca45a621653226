// pfview's orbit camera (see orbit_camera.h).
#include "pfview/orbit_camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace pf::view {

void OrbitCamera::orbit(double yaw_degrees, double pitch_degrees) {
  const glm::dvec3 up = glm::normalize(camera_.up);
  glm::dvec3 offset = camera_.eye - camera_.target;
  const double distance = glm::length(offset);
  // Yaw: about the up vector.
  offset = glm::dvec3(glm::rotate(glm::dmat4(1), glm::radians(yaw_degrees), up) * glm::dvec4(offset, 0));
  // Pitch: about the view's right vector, clamped 1 degree short of either pole.
  const double elevation = std::asin(std::clamp(glm::dot(offset / distance, up), -1.0, 1.0));
  const double limit = glm::radians(89.0);
  const double target_elevation = std::clamp(elevation + glm::radians(pitch_degrees), -limit, limit);
  const glm::dvec3 right = glm::normalize(glm::cross(offset, up));
  offset = glm::dvec3(glm::rotate(glm::dmat4(1), target_elevation - elevation, right) * glm::dvec4(offset, 0));
  camera_.eye = camera_.target + glm::normalize(offset) * distance;
}

void OrbitCamera::pan(double dx, double dy, int height_px) {
  const glm::dvec3 forward = glm::normalize(camera_.target - camera_.eye);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, camera_.up));
  const glm::dvec3 up = glm::cross(right, forward);
  // World units per pixel at the target's depth.
  const double view_height = camera_.ortho
                                 ? camera_.height
                                 : 2 * glm::length(camera_.target - camera_.eye) *
                                       std::tan(glm::radians(camera_.fov_degrees) / 2);
  const double per_pixel = view_height / std::max(height_px, 1);
  const glm::dvec3 move = (-dx * right + dy * up) * per_pixel;
  camera_.eye += move;
  camera_.target += move;
}

void OrbitCamera::zoom(double factor) {
  if (!(factor > 0)) return;
  if (camera_.ortho) {
    camera_.height = std::clamp(camera_.height * factor, 1e-6, 1e9);
    return;
  }
  const glm::dvec3 offset = camera_.eye - camera_.target;
  const double distance = std::clamp(glm::length(offset) * factor, 1e-4, 1e9);
  camera_.eye = camera_.target + glm::normalize(offset) * distance;
}

}  // namespace pf::view
