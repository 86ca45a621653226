// Test helpers for the field ray caster: ray families (orthographic from above a box, a
// perspective camera), simple tapes, and a comparison of a whole image of casts with the
// double-precision reference hit (field_reference.h) per pixel.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "compiler/field/fidget_reader.h"
#include "field/field_reference.h"
#include "raster/field/ray_caster.h"

namespace pf::field {

using Mat4 = std::array<double, 16>;  // column-major

inline Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int c = 0; c < 4; ++c)
    for (int rr = 0; rr < 4; ++rr)
      for (int k = 0; k < 4; ++k) r[c * 4 + rr] += a[k * 4 + rr] * b[c * 4 + k];
  return r;
}

inline Mat4 invert(Mat4 m) {  // Gauss-Jordan with partial pivoting on rows of the row-major view
  double a[4][8];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      a[r][c] = m[c * 4 + r];
      a[r][c + 4] = r == c ? 1.0 : 0.0;
    }
  for (int c = 0; c < 4; ++c) {
    int piv = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::fabs(a[r][c]) > std::fabs(a[piv][c])) piv = r;
    std::swap(a[c], a[piv]);
    const double d = a[c][c];
    for (double& v : a[c]) v /= d;
    for (int r = 0; r < 4; ++r) {
      if (r == c) continue;
      const double k = a[r][c];
      for (int j = 0; j < 8; ++j) a[r][j] -= k * a[c][j];
    }
  }
  Mat4 inv{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) inv[c * 4 + r] = a[r][c + 4];
  return inv;
}

// Looking down -z at the box from above it; the image covers the box's x and y extent.
inline FieldRays orthoRays(int w, int h, const Vec3d& lo, const Vec3d& hi) {
  FieldRays r;
  r.window_to_object = {};
  r.window_to_object[0] = (hi[0] - lo[0]) / w;
  r.window_to_object[12] = lo[0];
  r.window_to_object[5] = (hi[1] - lo[1]) / h;
  r.window_to_object[13] = lo[1];
  r.window_to_object[10] = -(hi[2] - lo[2]);
  r.window_to_object[14] = hi[2];
  r.window_to_object[15] = 1.0;
  r.box_min = lo;
  r.box_max = hi;
  return r;
}

// A camera at (0.3, 0.2, eye_z) looking down -z, 40 degree field of view.
inline FieldRays perspectiveRays(int w, int h, double eye_z, const Vec3d& lo, const Vec3d& hi) {
  const double n = 0.5, f = 20.0, t = 1.0 / std::tan(20.0 * 3.14159265358979 / 180.0);
  const Mat4 view = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -0.3, -0.2, -eye_z, 1};
  const Mat4 proj = {t * h / w, 0, 0, 0, 0, t, 0, 0, 0, 0, (f + n) / (n - f), -1, 0, 0, 2 * f * n / (n - f), 0};
  const Mat4 viewport = {w / 2.0, 0, 0, 0, 0, h / 2.0, 0, 0, 0, 0, 0.5, 0, w / 2.0, h / 2.0, 0.5, 1};
  FieldRays r;
  r.window_to_object = invert(multiply(viewport, multiply(proj, view)));
  r.box_min = lo;
  r.box_max = hi;
  return r;
}

inline FieldTape sphereTape(float radius) {
  FieldTapeBuilder b;
  uint32_t r2 = b.binary(FieldOp::Add, b.unary(FieldOp::Square, b.x()), b.unary(FieldOp::Square, b.y()));
  r2 = b.binary(FieldOp::Add, r2, b.unary(FieldOp::Square, b.z()));
  return b.finish(b.binary(FieldOp::Sub, b.constant(radius * radius), r2));
}

inline FieldTape model(const std::string& name) {
  DiagnosticLog log;
  return *readFidgetModel(name, testing::readModelText(name), log);
}

struct Comparison {
  int judged = 0, coverage_mismatches = 0;
  double max_depth_error = 0.0;  // in object units along the ray
  FieldCounters counters;
};

// Casts the blocks of the window [x0, x0 + w) x [y0, y0 + h) of an image (x0, y0 multiples of 8)
// and compares with the reference per pixel.
inline Comparison compareWindow(const ImplicitField& field, const FieldRays& rays, int x0, int y0, int w, int h,
                                RootMethod method, float param, int reference_steps) {
  FieldRayCaster caster;
  CastRequest req;
  req.field = &field;
  req.rays = rays;
  req.method = method;
  req.param = param;
  Comparison cmp;
  for (int by = y0; by < y0 + h; by += 8)
    for (int bx = x0; bx < x0 + w; bx += 8) {
      uint64_t mask = 0;
      for (int i = 0; i < 64; ++i)
        if (bx + i % 8 < x0 + w && by + i / 8 < y0 + h) mask |= uint64_t(1) << i;
      float t[64];
      caster.castBlock(req, bx, by, mask, t, cmp.counters);
      for (int i = 0; i < 64; ++i) {
        if (!(mask >> i & 1)) continue;
        const PixelRay ray = rays.ray(bx + i % 8 + 0.5, by + i / 8 + 0.5);
        const double want = testing::referenceHit(field.tape, ray.origin, ray.direction, ray.entry, ray.exit, reference_steps);
        ++cmp.judged;
        if (std::isinf(want) != std::isinf(t[i])) {
          ++cmp.coverage_mismatches;
          continue;
        }
        if (std::isinf(want)) continue;
        const double len = std::sqrt(ray.direction[0] * ray.direction[0] + ray.direction[1] * ray.direction[1] +
                                     ray.direction[2] * ray.direction[2]);
        cmp.max_depth_error = std::max(cmp.max_depth_error, std::fabs(t[i] - want) * len);
      }
    }
  return cmp;
}

// The whole w x h image.
inline Comparison compare(const ImplicitField& field, const FieldRays& rays, int w, int h, RootMethod method, float param,
                          int reference_steps) {
  return compareWindow(field, rays, 0, 0, w, h, method, param, reference_steps);
}

}  // namespace pf::field
