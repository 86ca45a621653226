// SampledGrid (sampled_grid.h): trilinear and cubic B-spline interpolation of a voxel array, with
// sound bounds of the value and of its derivatives over boxes from min/max pyramids.
#include "compiler/field/sampled_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pf::field {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// The weights of the taps of one axis at fraction f of a cell, and their derivatives: linear (2
// taps, samples i and i + 1) or the uniform cubic B-spline (4 taps, samples i - 1 to i + 2).
int tapWeights(SampleInterpolation interpolation, double f, double w[4], double dw[4]) {
  if (interpolation == SampleInterpolation::Trilinear) {
    w[0] = 1.0 - f;
    w[1] = f;
    dw[0] = -1.0;
    dw[1] = 1.0;
    return 2;
  }
  const double g = 1.0 - f, f2 = f * f, f3 = f2 * f;
  w[0] = g * g * g / 6.0;
  w[1] = (3.0 * f3 - 6.0 * f2 + 4.0) / 6.0;
  w[2] = (-3.0 * f3 + 3.0 * f2 + 3.0 * f + 1.0) / 6.0;
  w[3] = f3 / 6.0;
  dw[0] = -g * g / 2.0;
  dw[1] = (3.0 * f2 - 4.0 * f) / 2.0;
  dw[2] = (-3.0 * f2 + 2.0 * f + 1.0) / 2.0;
  dw[3] = f2 / 2.0;
  return 4;
}

float below(double v) { return std::nextafter(static_cast<float>(v), -kInf); }
float above(double v) { return std::nextafter(static_cast<float>(v), kInf); }

}  // namespace

std::string SampledGrid::checkGrid(long long nx, long long ny, long long nz, const double lo[3], const double hi[3],
                                   const float* values, bool* too_large) {
  if (too_large) *too_large = false;
  if (nx < 2 || ny < 2 || nz < 2)
    return "a sampled field needs at least 2 samples along each axis (found " + std::to_string(nx) + " x " +
           std::to_string(ny) + " x " + std::to_string(nz) + ")";
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(lo[k]) || !std::isfinite(hi[k]) || !(lo[k] < hi[k]))
      return "the box of a sampled field must have finite corners with min < max on each axis";
  const double count = static_cast<double>(nx) * static_cast<double>(ny) * static_cast<double>(nz);
  if (count > static_cast<double>(kMaxGridSamples)) {
    if (too_large) *too_large = true;
    return "a sampled field of " + std::to_string(nx) + " x " + std::to_string(ny) + " x " + std::to_string(nz) +
           " samples is larger than the " + std::to_string(kMaxGridSamples) + " allowed";
  }
  if (!values) return "a sampled field needs its samples";
  const size_t n = static_cast<size_t>(nx) * static_cast<size_t>(ny) * static_cast<size_t>(nz);
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(values[i]))
      return "sample " + std::to_string(i) + " (x " + std::to_string(i % static_cast<size_t>(nx)) + ", y " +
             std::to_string(i / static_cast<size_t>(nx) % static_cast<size_t>(ny)) + ", z " +
             std::to_string(i / static_cast<size_t>(nx) / static_cast<size_t>(ny)) + ") is not a finite number";
  return {};
}

SampledGrid::SampledGrid(int nx, int ny, int nz, const double lo[3], const double hi[3],
                         SampleInterpolation interpolation, std::vector<float> values)
    : n_{nx, ny, nz}, interpolation_(interpolation), values_(std::move(values)) {
  for (int a = 0; a < 3; ++a) {
    lo_[a] = lo[a];
    hi_[a] = hi[a];
    scale_[a] = (n_[a] - 1) / (hi[a] - lo[a]);
  }
  values_pyramid_.build(values_, nx, ny, nz);
  double squares = 0.0;
  for (int a = 0; a < 3; ++a) {
    const int dx = a == 0, dy = a == 1, dz = a == 2;
    const int mx = nx - dx, my = ny - dy, mz = nz - dz;
    std::vector<float>& d = differences_[a];
    d.resize(static_cast<size_t>(mx) * static_cast<size_t>(my) * static_cast<size_t>(mz));
    double largest = 0.0;
    size_t at = 0;
    for (int k = 0; k < mz; ++k)
      for (int j = 0; j < my; ++j)
        for (int i = 0; i < mx; ++i, ++at) {
          const double diff = static_cast<double>(sample(i + dx, j + dy, k + dz)) - sample(i, j, k);
          d[at] = static_cast<float>(diff);
          largest = std::max(largest, std::fabs(diff));
        }
    difference_pyramids_[a].build(d, mx, my, mz);
    const double rate = largest * scale_[a];
    squares += rate * rate;
  }
  lipschitz_ = std::sqrt(squares) * (1.0 + 1e-6);
}

float SampledGrid::clampedSample(int i, int j, int k) const {
  return sample(std::clamp(i, 0, n_[0] - 1), std::clamp(j, 0, n_[1] - 1), std::clamp(k, 0, n_[2] - 1));
}

double SampledGrid::gridCoordinate(int axis, double x, bool* inside) const {
  const double u = (x - lo_[axis]) * scale_[axis];
  const double top = n_[axis] - 1;
  if (inside) *inside = u >= 0.0 && u <= top;
  return u < 0.0 ? 0.0 : u > top ? top : u;  // NaN stays NaN
}

double SampledGrid::interpolate(const double u[3], double* grad) const {
  double w[3][4], dw[3][4];
  int cell[3], taps = 2;
  for (int a = 0; a < 3; ++a) {
    if (std::isnan(u[a])) {
      if (grad) grad[0] = grad[1] = grad[2] = kNaN;
      return kNaN;
    }
    cell[a] = std::min(static_cast<int>(std::floor(u[a])), n_[a] - 2);
    taps = tapWeights(interpolation_, u[a] - cell[a], w[a], dw[a]);
  }
  const int first = interpolation_ == SampleInterpolation::Trilinear ? 0 : -1;
  double value = 0.0, gx = 0.0, gy = 0.0, gz = 0.0;
  for (int c = 0; c < taps; ++c)
    for (int b = 0; b < taps; ++b)
      for (int a = 0; a < taps; ++a) {
        const double v = clampedSample(cell[0] + first + a, cell[1] + first + b, cell[2] + first + c);
        value += w[0][a] * w[1][b] * w[2][c] * v;
        if (grad) {
          gx += dw[0][a] * w[1][b] * w[2][c] * v;
          gy += w[0][a] * dw[1][b] * w[2][c] * v;
          gz += w[0][a] * w[1][b] * dw[2][c] * v;
        }
      }
  if (grad) {
    grad[0] = gx;
    grad[1] = gy;
    grad[2] = gz;
  }
  return value;
}

float SampledGrid::value(float x, float y, float z) const {
  const double u[3] = {gridCoordinate(0, x, nullptr), gridCoordinate(1, y, nullptr), gridCoordinate(2, z, nullptr)};
  return static_cast<float>(interpolate(u, nullptr));
}

void SampledGrid::valueAndGradient(float x, float y, float z, float out[4]) const {
  bool inside[3];
  const double u[3] = {gridCoordinate(0, x, &inside[0]), gridCoordinate(1, y, &inside[1]),
                       gridCoordinate(2, z, &inside[2])};
  double g[3];
  out[0] = static_cast<float>(interpolate(u, g));
  for (int a = 0; a < 3; ++a) out[1 + a] = inside[a] ? static_cast<float>(g[a] * scale_[a]) : 0.0f;
}

void SampledGrid::values(const float* x, const float* y, const float* z, int n, float* out) const {
  for (int j = 0; j < n; ++j) out[j] = value(x ? x[j] : 0.0f, y ? y[j] : 0.0f, z ? z[j] : 0.0f);
}

void SampledGrid::valuesAndGradients(const float* x, const float* y, const float* z, int n, float* out,
                                     size_t stride) const {
  for (int j = 0; j < n; ++j) {
    float g[4];
    valueAndGradient(x ? x[j] : 0.0f, y ? y[j] : 0.0f, z ? z[j] : 0.0f, g);
    for (size_t c = 0; c < 4; ++c) out[c * stride + static_cast<size_t>(j)] = g[c];
  }
}

void SampledGrid::sampleRange(int axis, float lo, float hi, int& first, int& last) const {
  const double u0 = gridCoordinate(axis, lo, nullptr), u1 = gridCoordinate(axis, hi, nullptr);
  if (std::isnan(u0) || std::isnan(u1)) {
    first = -1;
    last = n_[axis] + 1;
    return;
  }
  const int c0 = std::min(static_cast<int>(std::floor(u0)), n_[axis] - 2);
  const int c1 = std::min(static_cast<int>(std::floor(u1)), n_[axis] - 2);
  if (interpolation_ == SampleInterpolation::Trilinear) {
    first = c0;
    last = c1 + 1;
  } else {
    first = c0 - 1;
    last = c1 + 2;
  }
}

void SampledGrid::valueBounds(const float lo[3], const float hi[3], float& out_lo, float& out_hi) const {
  int first[3], last[3];
  for (int a = 0; a < 3; ++a) sampleRange(a, lo[a], hi[a], first[a], last[a]);
  float mn, mx;
  values_pyramid_.bound(first, last, mn, mx);
  // (Every value is a convex combination of these samples computed in double: one float step
  // outward covers its rounding.)
  out_lo = below(mn);
  out_hi = above(mx);
}

void SampledGrid::gradientBounds(const float lo[3], const float hi[3], float out_lo[3], float out_hi[3]) const {
  int first[3], last[3];
  bool outside[3];
  for (int a = 0; a < 3; ++a) {
    sampleRange(a, lo[a], hi[a], first[a], last[a]);
    bool in_lo = false, in_hi = false;
    gridCoordinate(a, lo[a], &in_lo);
    gridCoordinate(a, hi[a], &in_hi);
    outside[a] = !in_lo || !in_hi;
  }
  for (int a = 0; a < 3; ++a) {
    // Along `a` the derivative's control values are the differences between consecutive samples
    // of the range (difference i: samples i and i + 1); a difference past an edge, between
    // repeated edge samples, is 0, as is the derivative where a coordinate is clamped.
    int df[3] = {first[0], first[1], first[2]}, dl[3] = {last[0], last[1], last[2]};
    dl[a] = last[a] - 1;
    bool zero = outside[a] || df[a] < 0 || dl[a] > n_[a] - 2;
    float mn, mx;
    difference_pyramids_[a].bound(df, dl, mn, mx);
    if (zero) {
      mn = std::min(mn, 0.0f);
      mx = std::max(mx, 0.0f);
    }
    // The differences were rounded to float (relative 2^-24) and the result is a convex
    // combination of the exact ones computed in double, times the scale: 2^-20 of the largest
    // magnitude, and a float step, cover the roundings.
    const double pad = std::max(std::fabs(static_cast<double>(mn)), std::fabs(static_cast<double>(mx))) * 0x1p-20;
    out_lo[a] = below((mn - pad) * scale_[a]);
    out_hi[a] = above((mx + pad) * scale_[a]);
  }
}

void SampledGrid::Pyramid::build(const std::vector<float>& level0, int nx, int ny, int nz) {
  base = level0.data();
  min.clear();
  max.clear();
  dims = {nx, ny, nz};
  for (size_t level = 0; dims[3 * level] > 1 || dims[3 * level + 1] > 1 || dims[3 * level + 2] > 1; ++level) {
    const int px = dims[3 * level], py = dims[3 * level + 1], pz = dims[3 * level + 2];
    const int qx = (px + 1) / 2, qy = (py + 1) / 2, qz = (pz + 1) / 2;
    const float* src_lo = level == 0 ? base : min[level - 1].data();
    const float* src_hi = level == 0 ? base : max[level - 1].data();
    std::vector<float> lo(static_cast<size_t>(qx) * qy * qz), hi(lo.size());
    size_t at = 0;
    for (int k = 0; k < qz; ++k)
      for (int j = 0; j < qy; ++j)
        for (int i = 0; i < qx; ++i, ++at) {
          float a = kInf, b = -kInf;
          for (int c = 2 * k; c < std::min(2 * k + 2, pz); ++c)
            for (int r = 2 * j; r < std::min(2 * j + 2, py); ++r)
              for (int q = 2 * i; q < std::min(2 * i + 2, px); ++q) {
                const size_t from = (static_cast<size_t>(c) * py + r) * px + q;
                a = std::min(a, src_lo[from]);
                b = std::max(b, src_hi[from]);
              }
          lo[at] = a;
          hi[at] = b;
        }
    min.push_back(std::move(lo));
    max.push_back(std::move(hi));
    dims.insert(dims.end(), {qx, qy, qz});
  }
}

void SampledGrid::Pyramid::bound(const int first[3], const int last[3], float& lo, float& hi) const {
  int f[3], l[3];
  for (int a = 0; a < 3; ++a) {
    f[a] = std::clamp(first[a], 0, dims[a] - 1);
    l[a] = std::clamp(last[a], 0, dims[a] - 1);
  }
  // The finest level where the range covers at most 512 entries.
  const size_t levels = min.size() + 1;
  auto entries = [&](size_t level) {
    double count = 1.0;
    for (int a = 0; a < 3; ++a) count *= (l[a] >> level) - (f[a] >> level) + 1;
    return count;
  };
  size_t level = 0;
  while (level + 1 < levels && entries(level) > 512.0) ++level;
  const int px = dims[3 * level], py = dims[3 * level + 1];
  const float* lo_values = level == 0 ? base : min[level - 1].data();
  const float* hi_values = level == 0 ? base : max[level - 1].data();
  lo = kInf;
  hi = -kInf;
  for (int k = f[2] >> level; k <= l[2] >> level; ++k)
    for (int j = f[1] >> level; j <= l[1] >> level; ++j)
      for (int i = f[0] >> level; i <= l[0] >> level; ++i) {
        const size_t at = (static_cast<size_t>(k) * py + j) * px + i;
        lo = std::min(lo, lo_values[at]);
        hi = std::max(hi, hi_values[at]);
      }
}

}  // namespace pf::field
