// The rays an implicit instance casts: one per pixel centre, from the near plane (t = 0) to the
// far plane (t = 1) in the instance's object space -- the same ray the language's
// object_ray_near()/object_ray_far() give a primitive, computed here in double from the inverse
// of viewport x projection x modelview -- clipped to the instance's bounding box.
#pragma once

#include <array>

namespace pf::field {

using Vec3d = std::array<double, 3>;

struct PixelRay {
  Vec3d origin{}, direction{};  // object space; the point at t is origin + t * direction
  double entry = 0.0, exit = -1.0;  // t range inside the box; empty when exit < entry
  bool empty() const { return !(exit >= entry); }
  Vec3d at(double t) const {
    return {origin[0] + t * direction[0], origin[1] + t * direction[1], origin[2] + t * direction[2]};
  }
};

struct FieldRays {
  // window_to_object: column-major 4x4 (as GL), mapping (x_w, y_w, z_w, 1) to object space.
  std::array<double, 16> window_to_object{};
  double depth_near = 0.0, depth_far = 1.0;  // window z of the near and far planes
  Vec3d box_min{}, box_max{};

  PixelRay ray(double x, double y) const;  // x, y: window coordinates (pixel centres at +0.5)
  // The rays of the 64 pixels of the 8x8 block whose lower-left pixel is (bx, by): out[i] is
  // ray(bx + i % 8 + 0.5, by + i / 8 + 0.5), bit for bit, computed as vector loops (a block's
  // rays one by one were a seventh of a 2D model's frame).
  void blockRays(int bx, int by, PixelRay out[64]) const;
  // The same ray, not clipped to the box (entry 0, exit 1); empty where it is degenerate.
  PixelRay unclipped(double x, double y) const;
  // Whether the rays are affine in (x, y) (glOrtho, glFrustum, gluPerspective projections): then
  // the points of a rectangle of pixels over a t range lie in the box of its corner rays' points,
  // which is what culling a whole region needs. A projection with x or y in its last row breaks it.
  bool affine() const;
};

}  // namespace pf::field
