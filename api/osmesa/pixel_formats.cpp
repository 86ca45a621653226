// libprimflow-osmesa: copying primflow's frame into the caller's buffer in the layout OSMesa
// (Mesa 22.3) writes for each format and type (measured by calling it: tests/osmesa).
#include "api/osmesa/pixel_formats.h"

#include <algorithm>
#include <cstring>

#include <primflow/osmesa.h>

namespace pf::osmesa {

namespace {

// Channel order in memory, as indices into R G B A; `channels` 3 or 4.
struct Layout {
  int channels;
  int order[4];
};

Layout layoutOf(GLenum format, GLenum type) {
  // Wider types keep RGBA order whatever the format asked (Mesa 22.3's PIPE_FORMAT choice).
  const bool bytes = type == GL_UNSIGNED_BYTE;
  switch (format) {
    case OSMESA_BGRA: return bytes ? Layout{4, {2, 1, 0, 3}} : Layout{4, {0, 1, 2, 3}};
    case OSMESA_ARGB: return bytes ? Layout{4, {3, 0, 1, 2}} : Layout{4, {0, 1, 2, 3}};
    case OSMESA_RGB: return Layout{3, {0, 1, 2, 0}};
    default: return Layout{4, {0, 1, 2, 3}};
  }
}

uint16_t pack565(const uint8_t* p) {
  // Each channel rounded to nearest from its 8-bit value: R in the high 5 bits.
  const unsigned r = (p[0] * 31u + 127u) / 255u, g = (p[1] * 63u + 127u) / 255u, b = (p[2] * 31u + 127u) / 255u;
  return static_cast<uint16_t>((r << 11) | (g << 5) | b);
}

}  // namespace

int colorPixelBytes(GLenum format, GLenum type) {
  switch (format) {
    case OSMESA_RGBA:
    case OSMESA_BGRA:
    case OSMESA_ARGB:
      return type == GL_UNSIGNED_BYTE ? 4 : type == GL_UNSIGNED_SHORT ? 8 : type == GL_FLOAT ? 16 : 0;
    case OSMESA_RGB:
      return type == GL_UNSIGNED_BYTE ? 3 : type == GL_UNSIGNED_SHORT ? 6 : type == GL_FLOAT ? 12 : 0;
    case OSMESA_RGB_565: return type == GL_UNSIGNED_SHORT_5_6_5 ? 2 : 0;
    default: return 0;  // OSMESA_BGR, OSMESA_COLOR_INDEX: no layout in Mesa 22.3
  }
}

void writeColor(const uint8_t* frame, int width, int height, GLenum format, GLenum type, void* dst,
                int row_pixels, bool y_up) {
  const int pixel_bytes = colorPixelBytes(format, type);
  if (pixel_bytes == 0 || !dst) return;
  const size_t stride = static_cast<size_t>(row_pixels) * pixel_bytes;
  const Layout layout = layoutOf(format, type);
  for (int y = 0; y < height; ++y) {
    const uint8_t* src = frame + static_cast<size_t>(y) * width * 4;
    uint8_t* row = static_cast<uint8_t*>(dst) + static_cast<size_t>(y_up ? y : height - 1 - y) * stride;
    if (format == OSMESA_RGBA && type == GL_UNSIGNED_BYTE) {
      std::memcpy(row, src, static_cast<size_t>(width) * 4);
      continue;
    }
    for (int x = 0; x < width; ++x, src += 4) {
      if (type == GL_UNSIGNED_SHORT_5_6_5) {
        const uint16_t v = pack565(src);
        std::memcpy(row + x * 2, &v, 2);
        continue;
      }
      for (int c = 0; c < layout.channels; ++c) {
        const uint8_t v = src[layout.order[c]];
        if (type == GL_UNSIGNED_BYTE) {
          row[x * layout.channels + c] = v;
        } else if (type == GL_UNSIGNED_SHORT) {
          const uint16_t s = static_cast<uint16_t>(v * 257u);  // v / 255 in 16 bits, exactly
          std::memcpy(row + (x * layout.channels + c) * 2, &s, 2);
        } else {
          const float f = v / 255.0f;
          std::memcpy(row + (x * layout.channels + c) * 4, &f, 4);
        }
      }
    }
  }
}

int depthValueBytes(int depth_bits) { return depth_bits >= 24 ? 4 : depth_bits >= 16 ? 2 : 0; }

void writeDepth(const float* depth, int width, int height, int depth_bits, void* dst) {
  if (!depth || !dst) return;
  const size_t n = static_cast<size_t>(width) * height;
  auto unit = [](float z) { return z > 0.0f ? std::min(static_cast<double>(z), 1.0) : 0.0; };  // NaN: 0
  if (depth_bits >= 24) {
    auto* out = static_cast<uint32_t*>(dst);
    for (size_t i = 0; i < n; ++i) out[i] = static_cast<uint32_t>(unit(depth[i]) * 16777215.0 + 0.5);
  } else {
    auto* out = static_cast<uint16_t*>(dst);
    for (size_t i = 0; i < n; ++i) out[i] = static_cast<uint16_t>(unit(depth[i]) * 65535.0 + 0.5);
  }
}

}  // namespace pf::osmesa
