// The exact image of a pfspheres scene in double precision (see sphere_reference.h). Spheres are
// binned into 16x16-pixel tiles by a conservative screen box, so each ray meets only the spheres
// that can cover its tile.
#include "bench/sphere_reference.h"

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pfspheres {

namespace {

constexpr int kTile = 16;

glm::dmat4 matrixInDouble(const float* m) {
  glm::dmat4 r;
  double* p = glm::value_ptr(r);
  for (int i = 0; i < 16; ++i) p[i] = m[i];
  return r;
}

struct EyeSphere {
  glm::dvec3 center;  // eye coordinates (the modelview is rigid: the radius is unchanged)
  double radius;
  glm::dvec3 color;
};

struct Ray {
  glm::dvec3 origin, direction;  // eye coordinates: near plane at t = 0, far plane at t = 1
};

struct Hit {
  double t = 2;   // > 1: none
  uint32_t id = 0;
};

class ExactCaster {
 public:
  explicit ExactCaster(const SphereScene& s)
      : scene_(s), projection_(matrixInDouble(s.projection)), inverse_projection_(glm::inverse(projection_)) {
    const glm::dmat4 modelview = matrixInDouble(s.modelview);
    for (const Sphere& sp : s.spheres)
      spheres_.push_back({glm::dvec3(modelview * glm::dvec4(sp.center[0], sp.center[1], sp.center[2], 1)),
                          static_cast<double>(sp.radius), glm::dvec3(sp.color[0], sp.color[1], sp.color[2])});
    binSpheres();
  }

  // The ray through window point (wx, wy), from the near plane to the far.
  Ray rayThrough(double wx, double wy) const {
    const double nx = wx / scene_.width * 2 - 1, ny = wy / scene_.height * 2 - 1;
    const glm::dvec4 a = inverse_projection_ * glm::dvec4(nx, ny, -1, 1);
    const glm::dvec4 b = inverse_projection_ * glm::dvec4(nx, ny, 1, 1);
    const glm::dvec3 o = glm::dvec3(a) / a.w;
    return {o, glm::dvec3(b) / b.w - o};
  }

  // The nearest crossing of `ray` with the spheres binned to tile (tx, ty).
  Hit nearest(const Ray& ray, int tx, int ty) const {
    Hit best;
    for (uint32_t i : tiles_[static_cast<size_t>(ty) * tiles_x_ + tx]) {
      const double t = crossing(ray, spheres_[i]);
      if (t >= 0 && t < best.t) best = {t, i + 1};
    }
    return best;
  }

  double windowDepth(const glm::dvec3& eye) const {
    const glm::dvec4 clip = projection_ * glm::dvec4(eye, 1);
    return clip.z / clip.w * 0.5 + 0.5;
  }

  // GL's lighting equation (GL 1.5 section 2.14.1) in double: GL_LIGHT0 directional with its
  // defaults (no ambient, white diffuse and specular), the scene ambient (0.2, 0.2, 0.2), the
  // colour as ambient and diffuse (GL_COLOR_MATERIAL), the scene's specular and shininess, an
  // infinite viewer (half vector from (0, 0, 1)). Clamped to [0, 1].
  glm::dvec3 litColor(const Hit& hit, const Ray& ray) const {
    const EyeSphere& sp = spheres_[hit.id - 1];
    const glm::dvec3 n = (ray.origin + ray.direction * hit.t - sp.center) / sp.radius;
    const glm::dvec3 vp = glm::normalize(glm::dvec3(scene_.light_direction[0], scene_.light_direction[1],
                                                    scene_.light_direction[2]));
    const glm::dvec3 h = glm::normalize(vp + glm::dvec3(0, 0, 1));
    const glm::dvec3 specular(scene_.specular[0], scene_.specular[1], scene_.specular[2]);
    const double n_dot_vp = std::max(glm::dot(n, vp), 0.0);
    glm::dvec3 c = sp.color * 0.2 + n_dot_vp * sp.color;
    if (n_dot_vp > 0) c += std::pow(std::max(glm::dot(n, h), 0.0), static_cast<double>(scene_.shininess)) * specular;
    return glm::clamp(c, 0.0, 1.0);
  }

 private:
  // The ray parameter of the first crossing after the near plane (t in [0, 1]), or -1.
  static double crossing(const Ray& ray, const EyeSphere& sp) {
    const glm::dvec3 oc = ray.origin - sp.center;
    const double a = glm::dot(ray.direction, ray.direction), b = glm::dot(oc, ray.direction);
    const double disc = b * b - a * (glm::dot(oc, oc) - sp.radius * sp.radius);
    if (disc < 0) return -1;
    const double s = std::sqrt(disc), t0 = (-b - s) / a, t1 = (-b + s) / a;
    const double t = t0 >= 0 ? t0 : t1;
    return t < 0 || t > 1 ? -1 : t;
  }

  // Each sphere goes to the tiles its screen box (plus a pixel, for the edge rays) overlaps.
  void binSpheres() {
    tiles_x_ = (scene_.width + kTile - 1) / kTile;
    const int tiles_y = (scene_.height + kTile - 1) / kTile;
    tiles_.assign(static_cast<size_t>(tiles_x_) * tiles_y, {});
    for (size_t i = 0; i < spheres_.size(); ++i) {
      int x0, y0, x1, y1;
      screenBox(spheres_[i], &x0, &y0, &x1, &y1);
      for (int ty = y0 / kTile; ty * kTile < y1; ++ty)
        for (int tx = x0 / kTile; tx * kTile < x1; ++tx)
          tiles_[static_cast<size_t>(ty) * tiles_x_ + tx].push_back(static_cast<uint32_t>(i));
    }
  }

  // Pixels [x0, x1) x [y0, y1) holding the sphere's image, with a pixel to spare, clamped to the
  // frame: the projection of the eye-space cube around it (convex, so its corners bound it) when
  // the whole cube is in front of the eye, else the whole frame.
  void screenBox(const EyeSphere& sp, int* x0, int* y0, int* x1, int* y1) const {
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    bool in_front = true;
    for (int c = 0; c < 8 && in_front; ++c) {
      const double r = sp.radius;
      const glm::dvec3 corner = sp.center + glm::dvec3(c & 1 ? r : -r, c & 2 ? r : -r, c & 4 ? r : -r);
      in_front = corner.z < 0;
      const glm::dvec4 clip = projection_ * glm::dvec4(corner, 1);
      const double w[2] = {(clip.x / clip.w * 0.5 + 0.5) * scene_.width, (clip.y / clip.w * 0.5 + 0.5) * scene_.height};
      for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], w[k]), hi[k] = std::max(hi[k], w[k]);
    }
    if (!in_front) lo[0] = lo[1] = 0, hi[0] = scene_.width, hi[1] = scene_.height;
    auto clampTo = [](double v, int n) { return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(n))); };
    *x0 = clampTo(std::floor(lo[0]) - 1, scene_.width), *y0 = clampTo(std::floor(lo[1]) - 1, scene_.height);
    *x1 = clampTo(std::ceil(hi[0]) + 1, scene_.width), *y1 = clampTo(std::ceil(hi[1]) + 1, scene_.height);
  }

  const SphereScene& scene_;
  glm::dmat4 projection_, inverse_projection_;
  std::vector<EyeSphere> spheres_;
  int tiles_x_ = 0;
  std::vector<std::vector<uint32_t>> tiles_;
};

uint8_t toByte(double c) { return static_cast<uint8_t>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0)); }

}  // namespace

ExactImage computeExactImage(const SphereScene& s, double edge_pixels) {
  const ExactCaster caster(s);
  ExactImage img;
  img.width = s.width, img.height = s.height;
  const size_t n = static_cast<size_t>(s.width) * s.height;
  img.id.assign(n, 0);
  img.depth.assign(n, 1.0);
  img.rgb.resize(n * 3);
  img.near_edge.assign(n, 0);
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const size_t at = static_cast<size_t>(y) * s.width + x;
      const Ray ray = caster.rayThrough(x + 0.5, y + 0.5);
      const Hit hit = caster.nearest(ray, x / kTile, y / kTile);
      for (int k = 0; k < 8 && !img.near_edge[at]; ++k) {
        const double a = k * (std::numbers::pi / 4);
        const Ray edge = caster.rayThrough(x + 0.5 + edge_pixels * std::cos(a), y + 0.5 + edge_pixels * std::sin(a));
        img.near_edge[at] = caster.nearest(edge, x / kTile, y / kTile).id != hit.id;
      }
      if (hit.id == 0) {
        for (int c = 0; c < 3; ++c) img.rgb[at * 3 + c] = s.clear_rgb[c];
        continue;
      }
      img.id[at] = hit.id;
      img.depth[at] = caster.windowDepth(ray.origin + ray.direction * hit.t);
      const glm::dvec3 c = caster.litColor(hit, ray);
      for (int k = 0; k < 3; ++k) img.rgb[at * 3 + k] = toByte(c[k]);
    }
  return img;
}

}  // namespace pfspheres
