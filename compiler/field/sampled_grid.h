// A sampled field (seed 000, section 3: "voxel array with the trilinear or higher order
// interpolation" among FRep's primitives): values on a regular grid over a box, interpolated
// trilinearly or by the uniform cubic B-spline whose control points are the samples. A tape
// reads it through its `sample` leaf (field_tape.h), so every evaluator -- float, interval,
// slope, gradient -- and every root-finding method works on it.
//
// Geometry: sample (i, j, k) sits at lo + (i, j, k) (hi - lo) / (n - 1); a point outside the box
// takes the value at the nearest point of the box (each coordinate clamped), so the field is
// defined everywhere and constant along each axis outside it.
//
// Tricubic is the B-spline (C2, not interpolating: it smooths the samples; it reproduces
// linear functions exactly), chosen because its value lies in the convex hull of its 4x4x4
// control points and its derivative in the hull of the control points' differences: the bounds
// below are sound for it by construction, where Catmull-Rom's negative weights would need more.
// Samples outside the grid (the B-spline's support at the edges) repeat the edge sample.
//
// Values are computed in double and rounded to float once, so the float, gradient and interval
// forms agree with each other and with a double reference to float rounding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pf::field {

enum class SampleInterpolation : uint8_t { Trilinear = 0, CubicBSpline = 1 };

// The most samples a grid may hold (256^3): past it a grid is refused as too large (the API's
// GL_OUT_OF_MEMORY), since it and its bounds pyramid would take over half a gigabyte.
constexpr size_t kMaxGridSamples = size_t(1) << 24;

class SampledGrid {
 public:
  // `values`: nx * ny * nz samples, x fastest, then y, then z. The caller has checked the
  // arguments (checkGrid); the constructor builds the bounds pyramid (throws std::bad_alloc).
  SampledGrid(int nx, int ny, int nz, const double lo[3], const double hi[3], SampleInterpolation interpolation,
              std::vector<float> values);
  SampledGrid(const SampledGrid&) = delete;  // its pyramids point into its arrays
  SampledGrid& operator=(const SampledGrid&) = delete;

  // What is wrong with a grid of these dimensions, box and samples (empty: nothing). `too_large`
  // is set when the only complaint is its size.
  static std::string checkGrid(long long nx, long long ny, long long nz, const double lo[3], const double hi[3],
                               const float* values, bool* too_large);

  float value(float x, float y, float z) const;
  // The value and its partial derivatives d/dx, d/dy, d/dz (0 along a clamped coordinate).
  void valueAndGradient(float x, float y, float z, float out[4]) const;
  // value() at n points into out[0, n), and valueAndGradient() into out[i], out[stride + i],
  // out[2 stride + i], out[3 stride + i] (the float and gradient forms' batches; a null
  // coordinate array reads 0).
  void values(const float* x, const float* y, const float* z, int n, float* out) const;
  void valuesAndGradients(const float* x, const float* y, const float* z, int n, float* out, size_t stride) const;
  // Sound bounds over the box [lo, hi] (lo <= hi, any floats, infinite ends too): of the value,
  // and of each partial derivative (out_lo[k], out_hi[k], k = x, y, z). Every float value()
  // and valueAndGradient() give at a point of the box lies within them.
  void valueBounds(const float lo[3], const float hi[3], float& out_lo, float& out_hi) const;
  void gradientBounds(const float lo[3], const float hi[3], float out_lo[3], float out_hi[3]) const;
  // A bound on |grad f| everywhere (for sphere tracing): from the largest sample differences.
  double lipschitz() const { return lipschitz_; }

  int size(int axis) const { return n_[axis]; }
  double boxMin(int axis) const { return lo_[axis]; }
  double boxMax(int axis) const { return hi_[axis]; }
  SampleInterpolation interpolation() const { return interpolation_; }
  float sample(int i, int j, int k) const { return values_[index(i, j, k)]; }
  const float* samples() const { return values_.data(); }  // x fastest, then y, then z

 private:
  size_t index(int i, int j, int k) const {
    return (static_cast<size_t>(k) * static_cast<size_t>(n_[1]) + static_cast<size_t>(j)) * static_cast<size_t>(n_[0]) +
           static_cast<size_t>(i);
  }
  float clampedSample(int i, int j, int k) const;
  // The grid coordinate of x along `axis`, clamped to [0, n - 1], and whether x was inside.
  double gridCoordinate(int axis, double x, bool* inside) const;
  // Value (and d/du, d/dv, d/dw in grid units when `grad`) at grid coordinates u.
  double interpolate(const double u[3], double* grad) const;
  // The range of sample indices (inclusive, unclamped) whose values can reach a point of the box
  // along `axis`: the cells it touches and, for the B-spline, their support.
  void sampleRange(int axis, float lo, float hi, int& first, int& last) const;

  // Min and max over blocks of 2^level samples per axis, level 0 being the samples: a box's
  // bound reads at most a few hundred entries at the level where its range is that small.
  // Level 0 is the base array itself (not copied: the grid never moves once built).
  struct Pyramid {
    const float* base = nullptr;
    std::vector<std::vector<float>> min, max;  // levels 1, 2, ... (index level - 1)
    std::vector<int> dims;                     // 3 per level, level 0 first
    void build(const std::vector<float>& base, int nx, int ny, int nz);
    // min and max over samples [first, last] per axis (clamped to the base's extent).
    void bound(const int first[3], const int last[3], float& lo, float& hi) const;
  };

  int n_[3];
  double lo_[3], hi_[3];
  double scale_[3];  // (n - 1) / (hi - lo): grid units per unit length
  SampleInterpolation interpolation_;
  std::vector<float> values_;
  std::vector<float> differences_[3];  // v[next along axis] - v: the derivative's control values
  Pyramid values_pyramid_;
  Pyramid difference_pyramids_[3];
  double lipschitz_ = 0.0;
};

}  // namespace pf::field
