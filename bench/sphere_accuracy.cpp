// A rendering against the exact image, pixel by pixel (see sphere_accuracy.h).
#include "bench/sphere_accuracy.h"

#include <algorithm>
#include <cmath>

namespace pfspheres {

namespace {

// The peak signal-to-noise ratio of two 8-bit images: 10 log10(255^2 / mean squared error).
double psnr(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    const double d = static_cast<double>(a[i]) - static_cast<double>(b[i]);
    sum += d * d;
  }
  if (sum == 0) return std::numeric_limits<double>::infinity();
  return 10 * std::log10(255.0 * 255.0 / (sum / static_cast<double>(a.size())));
}

}  // namespace

Accuracy measureAccuracy(const ExactImage& exact, const Rendering& r) {
  Accuracy acc;
  double depth_error_sum = 0;
  for (size_t i = 0; i < exact.id.size(); ++i) {
    const uint32_t want = exact.id[i], got = r.id[i];
    if (want != got) {
      if (got == 0) ++acc.missing;
      else if (want == 0) ++acc.extra;
      else ++acc.wrong_surface;
      if (!exact.near_edge[i]) ++acc.off_edge;
    }
    if (want != 0 && want == got) {
      const double e = std::abs(static_cast<double>(r.depth[i]) - exact.depth[i]);
      acc.max_depth_error = std::max(acc.max_depth_error, e);
      depth_error_sum += e;
      for (size_t c = i * 3; c < i * 3 + 3; ++c)
        acc.max_color_error = std::max(acc.max_color_error, std::abs(exact.rgb[c] - r.rgb[c]));
      ++acc.same_surface;
    }
  }
  if (acc.same_surface) acc.mean_depth_error = depth_error_sum / static_cast<double>(acc.same_surface);
  acc.psnr_db = psnr(exact.rgb, r.rgb);
  return acc;
}

}  // namespace pfspheres
