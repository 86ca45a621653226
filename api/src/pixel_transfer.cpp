// Client images in GL 1.x's external formats and types (see pixel_transfer.h).
#include "api/src/pixel_transfer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "api/src/context_state.h"

namespace pf {
namespace {

// A packed type's fields in the order of the format's components: (shift, bits).
struct Field {
  int shift, bits;
};
struct Packed {
  GLenum type;
  int size;  // bytes
  int count;
  Field f[4];
};
constexpr Packed kPacked[] = {
    {GL_UNSIGNED_BYTE_3_3_2, 1, 3, {{5, 3}, {2, 3}, {0, 2}, {0, 0}}},
    {GL_UNSIGNED_BYTE_2_3_3_REV, 1, 3, {{0, 3}, {3, 3}, {6, 2}, {0, 0}}},
    {GL_UNSIGNED_SHORT_5_6_5, 2, 3, {{11, 5}, {5, 6}, {0, 5}, {0, 0}}},
    {GL_UNSIGNED_SHORT_5_6_5_REV, 2, 3, {{0, 5}, {5, 6}, {11, 5}, {0, 0}}},
    {GL_UNSIGNED_SHORT_4_4_4_4, 2, 4, {{12, 4}, {8, 4}, {4, 4}, {0, 4}}},
    {GL_UNSIGNED_SHORT_4_4_4_4_REV, 2, 4, {{0, 4}, {4, 4}, {8, 4}, {12, 4}}},
    {GL_UNSIGNED_SHORT_5_5_5_1, 2, 4, {{11, 5}, {6, 5}, {1, 5}, {0, 1}}},
    {GL_UNSIGNED_SHORT_1_5_5_5_REV, 2, 4, {{0, 5}, {5, 5}, {10, 5}, {15, 1}}},
    {GL_UNSIGNED_INT_8_8_8_8, 4, 4, {{24, 8}, {16, 8}, {8, 8}, {0, 8}}},
    {GL_UNSIGNED_INT_8_8_8_8_REV, 4, 4, {{0, 8}, {8, 8}, {16, 8}, {24, 8}}},
    {GL_UNSIGNED_INT_10_10_10_2, 4, 4, {{22, 10}, {12, 10}, {2, 10}, {0, 2}}},
    {GL_UNSIGNED_INT_2_10_10_10_REV, 4, 4, {{0, 10}, {10, 10}, {20, 10}, {30, 2}}},
};

const Packed* packedType(GLenum type) {
  for (const Packed& p : kPacked)
    if (p.type == type) return &p;
  return nullptr;
}

// Bytes of one component of a basic type; 0: not a basic type.
size_t basicBytes(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT: case GL_SHORT: return 2;
    case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: return 4;
    default: return 0;
  }
}

// The format's components, and which RGBA component each is (-1: luminance, which is all three
// colours when unpacked and red when packed).
int formatComponents(GLenum format, int which[4]) {
  switch (format) {
    case GL_RED: which[0] = 0; return 1;
    case GL_GREEN: which[0] = 1; return 1;
    case GL_BLUE: which[0] = 2; return 1;
    case GL_ALPHA: which[0] = 3; return 1;
    case GL_LUMINANCE: case GL_DEPTH_COMPONENT: case GL_STENCIL_INDEX: which[0] = -1; return 1;
    case GL_LUMINANCE_ALPHA: which[0] = -1, which[1] = 3; return 2;
    case GL_RGB: which[0] = 0, which[1] = 1, which[2] = 2; return 3;
    case GL_BGR: which[0] = 2, which[1] = 1, which[2] = 0; return 3;
    case GL_RGBA: which[0] = 0, which[1] = 1, which[2] = 2, which[3] = 3; return 4;
    case GL_BGRA: which[0] = 2, which[1] = 1, which[2] = 0, which[3] = 3; return 4;
    default: return 0;
  }
}

// One component of a basic type at `p` (its bytes already in the machine's order) as GL converts
// it: unsigned ones to [0, 1], signed ones to [-1, 1] (c / (2^(b-1) - 1), at least -1).
double loadComponent(GLenum type, const unsigned char* p) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return p[0] / 255.0;
    case GL_BYTE: return std::max(static_cast<int8_t>(p[0]) / 127.0, -1.0);
    case GL_UNSIGNED_SHORT: { uint16_t v; std::memcpy(&v, p, 2); return v / 65535.0; }
    case GL_SHORT: { int16_t v; std::memcpy(&v, p, 2); return std::max(v / 32767.0, -1.0); }
    case GL_UNSIGNED_INT: { uint32_t v; std::memcpy(&v, p, 4); return v / 4294967295.0; }
    case GL_INT: { int32_t v; std::memcpy(&v, p, 4); return std::max(v / 2147483647.0, -1.0); }
    default: { float v; std::memcpy(&v, p, 4); return v; }
  }
}

// A value in [0, 1] (clamped; NaN as 0) as the type stores it, rounded to nearest.
void storeComponent(GLenum type, double v, unsigned char* p) {
  v = v > 0.0 ? std::min(v, 1.0) : 0.0;
  switch (type) {
    case GL_UNSIGNED_BYTE: p[0] = static_cast<unsigned char>(std::nearbyint(v * 255.0)); return;
    case GL_BYTE: p[0] = static_cast<unsigned char>(static_cast<int8_t>(std::nearbyint(v * 127.0))); return;
    case GL_UNSIGNED_SHORT: { const uint16_t s = static_cast<uint16_t>(std::nearbyint(v * 65535.0)); std::memcpy(p, &s, 2); return; }
    case GL_SHORT: { const int16_t s = static_cast<int16_t>(std::nearbyint(v * 32767.0)); std::memcpy(p, &s, 2); return; }
    case GL_UNSIGNED_INT: { const uint32_t s = static_cast<uint32_t>(std::nearbyint(v * 4294967295.0)); std::memcpy(p, &s, 4); return; }
    case GL_INT: { const int32_t s = static_cast<int32_t>(std::nearbyint(v * 2147483647.0)); std::memcpy(p, &s, 4); return; }
    default: { const float f = static_cast<float>(v); std::memcpy(p, &f, 4); return; }
  }
}

uint32_t loadWord(const unsigned char* p, int size) {
  if (size == 1) return p[0];
  if (size == 2) {
    uint16_t v;
    std::memcpy(&v, p, 2);
    return v;
  }
  uint32_t v;
  std::memcpy(&v, p, 4);
  return v;
}

void storeWord(unsigned char* p, int size, uint32_t v) {
  if (size == 1) {
    p[0] = static_cast<unsigned char>(v);
  } else if (size == 2) {
    const uint16_t s = static_cast<uint16_t>(v);
    std::memcpy(p, &s, 2);
  } else {
    std::memcpy(p, &v, 4);
  }
}

}  // namespace

GLenum checkColorFormatAndType(GLenum format, GLenum type) {
  if (type == GL_BITMAP) return GL_INVALID_ENUM;  // (colour indices and stencil only)
  if (const Packed* p = packedType(type)) {
    const bool rgb = format == GL_RGB;
    const bool rgba = format == GL_RGBA || format == GL_BGRA;
    return (p->count == 3 ? rgb : rgba) ? GL_NO_ERROR : GL_INVALID_OPERATION;
  }
  if (basicBytes(type) == 0) return GL_INVALID_ENUM;
  int which[4];
  if (formatComponents(format, which) == 0 || format == GL_DEPTH_COMPONENT || format == GL_STENCIL_INDEX)
    return GL_INVALID_ENUM;
  return GL_NO_ERROR;
}

ImageLayout imageLayout(const PixelStore& store, GLenum format, GLenum type, int width) {
  ImageLayout l;
  int which[4];
  const int components = formatComponents(format, which);
  if (const Packed* p = packedType(type)) {
    l.pixel_bytes = static_cast<size_t>(p->size);
    l.component_bytes = l.pixel_bytes;
  } else {
    l.component_bytes = basicBytes(type);
    l.pixel_bytes = static_cast<size_t>(components) * l.component_bytes;
  }
  const size_t align = static_cast<size_t>(store.alignment);
  const size_t row_pixels = static_cast<size_t>(store.row_length > 0 ? store.row_length : std::max(width, 0));
  // (GL 1.5 equation 3.13: rows padded to the alignment unless a component is larger than it.)
  const size_t unpadded = row_pixels * l.pixel_bytes;
  l.row_bytes = l.component_bytes >= align ? unpadded : (unpadded + align - 1) / align * align;
  l.offset = static_cast<size_t>(store.skip_rows) * l.row_bytes + static_cast<size_t>(store.skip_pixels) * l.pixel_bytes;
  return l;
}

void unpackColors(const PixelStore& store, GLenum format, GLenum type, int width, int height, const void* data,
                  float* rgba) {
  const ImageLayout l = imageLayout(store, format, type, width);
  int which[4];
  const int components = formatComponents(format, which);
  const Packed* packed = packedType(type);
  const auto* base = static_cast<const unsigned char*>(data) + l.offset;
  unsigned char swapped[4];
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const unsigned char* src = base + static_cast<size_t>(y) * l.row_bytes + static_cast<size_t>(x) * l.pixel_bytes;
      double v[4] = {0, 0, 0, 1};
      double comp[4] = {0, 0, 0, 0};
      if (packed) {
        const unsigned char* w = src;
        if (store.swap_bytes && packed->size > 1) {
          std::reverse_copy(src, src + packed->size, swapped);
          w = swapped;
        }
        const uint32_t word = loadWord(w, packed->size);
        for (int k = 0; k < packed->count; ++k) {
          const uint32_t max = (1u << packed->f[k].bits) - 1u;
          comp[k] = static_cast<double>((word >> packed->f[k].shift) & max) / max;
        }
      } else {
        for (int k = 0; k < components; ++k) {
          const unsigned char* c = src + static_cast<size_t>(k) * l.component_bytes;
          if (store.swap_bytes && l.component_bytes > 1) {
            std::reverse_copy(c, c + l.component_bytes, swapped);
            c = swapped;
          }
          comp[k] = loadComponent(type, c);
        }
      }
      for (int k = 0; k < components; ++k) {
        if (which[k] < 0) v[0] = v[1] = v[2] = comp[k];
        else v[which[k]] = comp[k];
      }
      float* out = rgba + (static_cast<size_t>(y) * width + static_cast<size_t>(x)) * 4;
      for (int k = 0; k < 4; ++k) out[k] = static_cast<float>(v[k]);
    }
}

void packColors(const PixelStore& store, GLenum format, GLenum type, int width, int height, const float* rgba,
                void* data) {
  const ImageLayout l = imageLayout(store, format, type, width);
  int which[4];
  const int components = formatComponents(format, which);
  const Packed* packed = packedType(type);
  auto* base = static_cast<unsigned char*>(data) + l.offset;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      unsigned char* dst = base + static_cast<size_t>(y) * l.row_bytes + static_cast<size_t>(x) * l.pixel_bytes;
      const float* in = rgba + (static_cast<size_t>(y) * width + static_cast<size_t>(x)) * 4;
      double comp[4];
      for (int k = 0; k < components; ++k) comp[k] = in[which[k] < 0 ? 0 : which[k]];
      if (packed) {
        uint32_t word = 0;
        for (int k = 0; k < packed->count; ++k) {
          const uint32_t max = (1u << packed->f[k].bits) - 1u;
          const double c = comp[k] > 0.0 ? std::min(comp[k], 1.0) : 0.0;
          word |= static_cast<uint32_t>(std::nearbyint(c * max)) << packed->f[k].shift;
        }
        storeWord(dst, packed->size, word);
        if (store.swap_bytes) std::reverse(dst, dst + packed->size);
        continue;
      }
      for (int k = 0; k < components; ++k) {
        unsigned char* c = dst + static_cast<size_t>(k) * l.component_bytes;
        storeComponent(type, comp[k], c);
        if (store.swap_bytes) std::reverse(c, c + l.component_bytes);
      }
    }
}

void unpackBitmap(const PixelStore& store, int width, int height, const void* data, unsigned char* bits) {
  if (width <= 0 || height <= 0) return;
  const auto* in = static_cast<const unsigned char*>(data);
  const size_t align = static_cast<size_t>(store.alignment);
  const size_t row_bits = static_cast<size_t>(store.row_length > 0 ? store.row_length : width);
  const size_t row_bytes = ((row_bits + 7) / 8 + align - 1) / align * align;
  const size_t w = static_cast<size_t>(width);
  for (size_t y = 0; y < static_cast<size_t>(height); ++y) {
    const unsigned char* row = in + (static_cast<size_t>(store.skip_rows) + y) * row_bytes;
    for (size_t x = 0; x < w; ++x) {
      const size_t bit = static_cast<size_t>(store.skip_pixels) + x;
      const int shift = store.lsb_first ? static_cast<int>(bit % 8) : 7 - static_cast<int>(bit % 8);
      bits[y * w + x] = static_cast<unsigned char>((row[bit / 8] >> shift) & 1);
    }
  }
}

void packBitmap(const PixelStore& store, int width, int height, const unsigned char* bits, void* data) {
  if (width <= 0 || height <= 0) return;
  auto* out = static_cast<unsigned char*>(data);
  const size_t align = static_cast<size_t>(store.alignment);
  const size_t row_bits = static_cast<size_t>(store.row_length > 0 ? store.row_length : width);
  const size_t row_bytes = ((row_bits + 7) / 8 + align - 1) / align * align;
  const size_t w = static_cast<size_t>(width), skip = static_cast<size_t>(store.skip_pixels);
  for (size_t y = 0; y < static_cast<size_t>(height); ++y) {
    unsigned char* row = out + (static_cast<size_t>(store.skip_rows) + y) * row_bytes;
    std::fill(row + skip / 8, row + (skip + w + 7) / 8, static_cast<unsigned char>(0));
    for (size_t x = 0; x < w; ++x) {
      if (!bits[y * w + x]) continue;
      const size_t bit = skip + x;
      const int shift = store.lsb_first ? static_cast<int>(bit % 8) : 7 - static_cast<int>(bit % 8);
      row[bit / 8] = static_cast<unsigned char>(row[bit / 8] | (1u << shift));
    }
  }
}

GLenum checkDrawFormatAndType(GLenum format, GLenum type) {
  if (type == GL_BITMAP)
    return format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX ? GL_NO_ERROR : GL_INVALID_ENUM;
  const bool index = format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX || format == GL_DEPTH_COMPONENT;
  if (packedType(type) || !index) return checkColorFormatAndType(format, type);
  return basicBytes(type) != 0 ? GL_NO_ERROR : GL_INVALID_ENUM;
}

void unpackIndices(const PixelStore& store, GLenum type, int width, int height, const void* data, uint32_t* out) {
  if (width <= 0 || height <= 0) return;
  const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height);
  if (type == GL_BITMAP) {
    std::vector<unsigned char> bits(n);
    unpackBitmap(store, width, height, data, bits.data());
    for (size_t i = 0; i < n; ++i) out[i] = bits[i];
    return;
  }
  const ImageLayout l = imageLayout(store, GL_STENCIL_INDEX, type, width);
  const auto* base = static_cast<const unsigned char*>(data) + l.offset;
  unsigned char c[4];
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const unsigned char* src = base + static_cast<size_t>(y) * l.row_bytes + static_cast<size_t>(x) * l.pixel_bytes;
      std::memcpy(c, src, l.component_bytes);
      if (store.swap_bytes) std::reverse(c, c + l.component_bytes);
      uint32_t v = 0;
      switch (type) {
        case GL_UNSIGNED_BYTE: v = c[0]; break;
        case GL_BYTE: v = static_cast<uint32_t>(static_cast<int8_t>(c[0])); break;
        case GL_UNSIGNED_SHORT: { uint16_t u; std::memcpy(&u, c, 2); v = u; break; }
        case GL_SHORT: { int16_t u; std::memcpy(&u, c, 2); v = static_cast<uint32_t>(u); break; }
        case GL_FLOAT: {
          float f;
          std::memcpy(&f, c, 4);
          v = f >= 0.0f && f < 4294967296.0f ? static_cast<uint32_t>(f) : 0u;
          break;
        }
        default: std::memcpy(&v, c, 4); break;  // GL_UNSIGNED_INT, GL_INT
      }
      out[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)] = v;
    }
}

}  // namespace pf
