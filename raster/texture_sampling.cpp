// Texture sampling in the shading pass (see texture.h): the level of detail from screen-space
// derivatives, GL's minification and magnification filters with every wrap mode, and the
// texture environment.
//
// Derivatives. A pixel's derivative along x is the difference of its (s/q, t/q), scaled to
// texels, with its partner in its 2x2 quad (x xor 1) -- the pair llvmpipe's quads difference --
// when the G-buffer holds the same shading state there, else with its other horizontal
// neighbour, and likewise along y (y xor 1, then the other side). Quads are aligned to even
// pixels, so they never straddle a tile. A pixel with neither neighbour along one axis takes the
// other axis' derivative for it; with none at all (a primitive one pixel across) it is
// magnified. Everything here is scalar IEEE arithmetic in one translation unit: the same bits for
// any thread count and either executor (the G-buffer they fill is the same).
#include "raster/texture.h"

#include <algorithm>
#include <cmath>

namespace pf {
namespace {

// A coordinate that is not a number, or too large to index a texel, samples as 0 (GL leaves it
// undefined).
float finite(float v) { return std::fabs(v) < 1e30f ? v : 0.0f; }

// floor(x) of a finite float, exactly, without a library call (the baseline x86-64 has no
// rounding instruction): by truncation below 2^30; a float past 2^23 is an integer already.
double floorOf(float x) {
  if (!(std::fabs(x) < 1073741824.0f)) return static_cast<double>(x);
  const int i = static_cast<int>(x);
  return static_cast<double>(x < static_cast<float>(i) ? i - 1 : i);
}

// f (a whole number) modulo size, in [0, size): exact integer arithmetic where f fits, else in
// double, clamped (coordinates that large have lost every texel anyway).
int repeatIndex(double f, int size) {
  if (std::fabs(f) < 1073741824.0) {
    int m = static_cast<int>(f) % size;
    return m < 0 ? m + size : m;
  }
  const double m = f - static_cast<double>(size) * std::floor(f / size);
  return static_cast<int>(std::clamp(m, 0.0, static_cast<double>(size - 1)));
}

// A coordinate's texel index along an axis of `size` texels under `wrap`, for a nearest sample
// at u (in texels; s already clamped to [0, 1] for GL_CLAMP, mirrored for GL_MIRRORED_REPEAT);
// -1: the border (GL_CLAMP_TO_BORDER past the edge).
int wrapNearest(GLenum wrap, float u, int size) {
  u = finite(u);
  const double f = floorOf(u);
  if (wrap == GL_REPEAT) return repeatIndex(f, size);
  if (wrap == GL_CLAMP_TO_BORDER) return f < 0 || f >= size ? -1 : static_cast<int>(f);
  return static_cast<int>(std::clamp(f, 0.0, static_cast<double>(size - 1)));
}

// The two texel indices of a linear sample at u and the weight of the second; an index -1
// stands for the border (GL_CLAMP and GL_CLAMP_TO_BORDER reaching past the edge).
void wrapLinear(GLenum wrap, float u, int size, int& i0, int& i1, float& a) {
  u = finite(u);
  const float shifted = u - 0.5f;
  const double f = floorOf(shifted);
  a = static_cast<float>(static_cast<double>(shifted) - f);  // (exact: a float's fraction is a float)
  if (wrap == GL_REPEAT) {
    i0 = repeatIndex(f, size);
    i1 = i0 + 1 == size ? 0 : i0 + 1;
    return;
  }
  const double lo = std::clamp(f, -1.0, static_cast<double>(size));
  const double hi = std::clamp(f + 1.0, -1.0, static_cast<double>(size));
  if (wrap == GL_CLAMP_TO_EDGE || wrap == GL_MIRRORED_REPEAT) {
    i0 = static_cast<int>(std::clamp(lo, 0.0, static_cast<double>(size - 1)));
    i1 = static_cast<int>(std::clamp(hi, 0.0, static_cast<double>(size - 1)));
    return;
  }
  i0 = lo < 0 || lo >= size ? -1 : static_cast<int>(lo);
  i1 = hi < 0 || hi >= size ? -1 : static_cast<int>(hi);
}

// s as GL_CLAMP and GL_MIRRORED_REPEAT take it before it is scaled to texels.
float wrapCoordinate(GLenum wrap, float s) {
  if (wrap == GL_CLAMP) return std::clamp(s, 0.0f, 1.0f);
  if (wrap == GL_MIRRORED_REPEAT) {
    const double f = std::floor(static_cast<double>(s));
    const double r = static_cast<double>(s) - f;
    return static_cast<float>(std::fmod(f, 2.0) == 0.0 ? r : 1.0 - r);
  }
  return s;
}

// Texel (i, j) of `level` into rgba; -1 in either: the border colour.
void texel(const TextureUnit& unit, const TextureLevel& level, int i, int j, float rgba[4]) {
  if (i < 0 || j < 0) {
    for (int k = 0; k < 4; ++k) rgba[k] = unit.border[k];
    return;
  }
  const uint8_t* p = level.texels.data() + (static_cast<size_t>(j) * level.width + static_cast<size_t>(i)) * 4;
  for (int k = 0; k < 4; ++k) rgba[k] = static_cast<float>(p[k]) * (1.0f / 255.0f);
}


// One sample of `level` with GL_NEAREST (linear false) or GL_LINEAR.
void sampleLevel(const TextureUnit& unit, const TextureLevel& level, float s, float t, bool linear, float rgba[4]) {
  s = wrapCoordinate(unit.wrap_s, s);
  t = wrapCoordinate(unit.wrap_t, t);
  const float u = s * static_cast<float>(level.width);
  const float v = t * static_cast<float>(level.height);
  const bool two = unit.dims == 2;
  if (!linear) {
    const int i = wrapNearest(unit.wrap_s, u, level.width);
    const int j = two ? wrapNearest(unit.wrap_t, v, level.height) : 0;
    texel(unit, level, i, j, rgba);
    return;
  }
  int i0, i1, j0 = 0, j1 = 0;
  float a, b = 0.0f;
  wrapLinear(unit.wrap_s, u, level.width, i0, i1, a);
  if (two) wrapLinear(unit.wrap_t, v, level.height, j0, j1, b);
  float t00[4], t10[4], t01[4], t11[4];
  texel(unit, level, i0, j0, t00);
  texel(unit, level, i1, j0, t10);
  if (!two) {
    for (int k = 0; k < 4; ++k) rgba[k] = (1.0f - a) * t00[k] + a * t10[k];
    return;
  }
  texel(unit, level, i0, j1, t01);
  texel(unit, level, i1, j1, t11);
  for (int k = 0; k < 4; ++k)
    rgba[k] = (1.0f - a) * (1.0f - b) * t00[k] + a * (1.0f - b) * t10[k] + (1.0f - a) * b * t01[k] + a * b * t11[k];
}

bool mipmapped(GLenum filter) { return filter != GL_NEAREST && filter != GL_LINEAR; }

// GL divides s and t by q. A q of exactly 0 -- undefined in GL -- is what a shared interpolator
// leaves when it returns a vector (u, v, w) for the texture coordinates: taken as 1.
float divisor(float q) { return q == 0.0f ? 1.0f : q; }

}  // namespace

float textureLod(float dudx, float dvdx, float dudy, float dvdy) {
  const double x = std::sqrt(static_cast<double>(dudx) * dudx + static_cast<double>(dvdx) * dvdx);
  const double y = std::sqrt(static_cast<double>(dudy) * dudy + static_cast<double>(dvdy) * dvdy);
  const double rho = std::max(x, y);
  if (!(rho > 0.0)) return -1000.0f;  // no footprint (or NaN): magnified
  return static_cast<float>(std::log2(rho));
}

void sampleTexture(const TextureUnit& unit, float s, float t, float lod, float rgba[4]) {
  s = finite(s);
  t = finite(t);
  const float lambda = std::min(std::max(lod, unit.min_lod), unit.max_lod);  // (min_lod may exceed max_lod)
  // GL 1.5 section 3.8.8: magnified when lambda <= c.
  const bool nearest_mip = unit.min_filter == GL_NEAREST_MIPMAP_NEAREST || unit.min_filter == GL_NEAREST_MIPMAP_LINEAR;
  const float c = unit.mag_filter == GL_LINEAR && nearest_mip ? 0.5f : 0.0f;
  const TextureLevel& base = *unit.levels[0];
  if (!(lambda > c)) {
    sampleLevel(unit, base, s, t, unit.mag_filter == GL_LINEAR, rgba);
    return;
  }
  const GLenum f = unit.min_filter;
  if (!mipmapped(f) || unit.levels.size() == 1) {
    const bool linear = f == GL_LINEAR || f == GL_LINEAR_MIPMAP_NEAREST || f == GL_LINEAR_MIPMAP_LINEAR;
    sampleLevel(unit, base, s, t, linear, rgba);
    return;
  }
  const int q = static_cast<int>(unit.levels.size()) - 1;
  const bool linear_in_level = f == GL_LINEAR_MIPMAP_NEAREST || f == GL_LINEAR_MIPMAP_LINEAR;
  if (f == GL_NEAREST_MIPMAP_NEAREST || f == GL_LINEAR_MIPMAP_NEAREST) {
    // d = ceil(lambda + 1/2) - 1 for lambda > 1/2, else the base level; at most q.
    const double d = lambda <= 0.5f ? 0.0 : std::ceil(static_cast<double>(lambda) + 0.5) - 1.0;
    const int level = static_cast<int>(std::min(d, static_cast<double>(q)));
    sampleLevel(unit, *unit.levels[static_cast<size_t>(level)], s, t, linear_in_level, rgba);
    return;
  }
  if (lambda >= static_cast<float>(q)) {
    sampleLevel(unit, *unit.levels[static_cast<size_t>(q)], s, t, linear_in_level, rgba);
    return;
  }
  const double d1 = std::floor(static_cast<double>(lambda));
  const float frac = static_cast<float>(static_cast<double>(lambda) - d1);
  const size_t level = static_cast<size_t>(d1);
  float a[4], b[4];
  sampleLevel(unit, *unit.levels[level], s, t, linear_in_level, a);
  sampleLevel(unit, *unit.levels[level + 1], s, t, linear_in_level, b);
  for (int k = 0; k < 4; ++k) rgba[k] = (1.0f - frac) * a[k] + frac * b[k];
}

void textureEnvironment(const TextureUnit& unit, const float f[4], const float tex[4], float out[4]) {
  const TextureBase base = unit.base;
  // The texture's colour and alpha as the base format has them: luminance and intensity are
  // stored in red (and alpha, for intensity).
  const bool has_colour = base != TextureBase::Alpha;
  const bool has_alpha = base == TextureBase::Alpha || base == TextureBase::LuminanceAlpha ||
                         base == TextureBase::Intensity || base == TextureBase::Rgba;
  const float ct[3] = {tex[0], tex[1], tex[2]};
  const float at = tex[3];
  const float* cc = unit.env_color;
  for (int k = 0; k < 4; ++k) out[k] = f[k];
  switch (unit.env_mode) {
    case GL_REPLACE:
      if (has_colour)
        for (int k = 0; k < 3; ++k) out[k] = ct[k];
      if (has_alpha) out[3] = at;
      break;
    case GL_MODULATE:
      if (has_colour)
        for (int k = 0; k < 3; ++k) out[k] = f[k] * ct[k];
      if (has_alpha) out[3] = f[3] * at;
      break;
    case GL_DECAL:  // defined for RGB and RGBA; the fragment unchanged for the others (as Mesa)
      if (base == TextureBase::Rgb)
        for (int k = 0; k < 3; ++k) out[k] = ct[k];
      else if (base == TextureBase::Rgba)
        for (int k = 0; k < 3; ++k) out[k] = f[k] * (1.0f - at) + ct[k] * at;
      break;
    case GL_BLEND:
      if (has_colour)
        for (int k = 0; k < 3; ++k) out[k] = f[k] * (1.0f - ct[k]) + cc[k] * ct[k];
      if (base == TextureBase::Intensity) out[3] = f[3] * (1.0f - at) + cc[3] * at;
      else if (has_alpha) out[3] = f[3] * at;
      break;
    case GL_ADD:
      if (has_colour)
        for (int k = 0; k < 3; ++k) out[k] = f[k] + ct[k];
      if (base == TextureBase::Intensity) out[3] = f[3] + at;
      else if (has_alpha) out[3] = f[3] * at;
      break;
    default: break;
  }
  for (int k = 0; k < 4; ++k) out[k] = out[k] > 0.0f ? (out[k] < 1.0f ? out[k] : 1.0f) : 0.0f;  // (NaN: 0)
}

void textureSpan(const TextureUnit& unit, const TextureSpan& span, float (*c)[kTileSize], int skip) {
  const TextureLevel& base = *unit.levels[0];
  const float width = static_cast<float>(base.width);
  const float height = unit.dims == 2 ? static_cast<float>(base.height) : 0.0f;
  auto at = [&](int x, int y) { return static_cast<size_t>(y) * kTileSize + static_cast<size_t>(x); };
  // The pixel's coordinates in texels of the base level (s/q, t/q scaled).
  auto texels = [&](size_t i, float& u, float& v) {
    const float q = divisor(span.coord[3][i]);
    u = span.coord[0][i] / q * width;
    v = span.coord[1][i] / q * height;
  };
  // The derivative along one axis from the pixel at `here`: with the neighbour at `first`
  // (its quad partner) or, failing that, `second`; false if neither holds the span's state.
  auto derivative = [&](float u, float v, int x1, int y1, int x2, int y2, float& du, float& dv, int sign1) {
    const int xs[2] = {x1, x2}, ys[2] = {y1, y2};
    for (int k = 0; k < 2; ++k) {
      if (xs[k] < 0 || ys[k] < 0 || xs[k] >= span.tile_w || ys[k] >= span.tile_h) continue;
      const size_t i = at(xs[k], ys[k]);
      if (span.ids[i] != span.id) continue;
      float un, vn;
      texels(i, un, vn);
      const float sign = static_cast<float>(k == 0 ? sign1 : -sign1);
      du = (un - u) * sign;
      dv = (vn - v) * sign;
      return true;
    }
    return false;
  };
  // Without mipmaps and with one filter both ways, the level of detail decides nothing.
  const bool needs_lod = mipmapped(unit.min_filter) || unit.min_filter != unit.mag_filter;
  const int y = span.y;
  for (int i = 0; i < span.n; ++i) {
    const int x = span.x + i;
    const size_t here = at(x, y);
    if (span.ids[here] != span.id) continue;
    float u = 0, v = 0;
    if (needs_lod) texels(here, u, v);
    const int px = x ^ 1, py = y ^ 1;
    const int sx = px > x ? 1 : -1, sy = py > y ? 1 : -1;
    float dudx = 0, dvdx = 0, dudy = 0, dvdy = 0;
    const bool hx = needs_lod && derivative(u, v, px, y, x - sx, y, dudx, dvdx, sx);
    const bool hy = needs_lod && derivative(u, v, x, py, x, y - sy, dudy, dvdy, sy);
    if (!hx && hy) dudx = dudy, dvdx = dvdy;
    if (!hy && hx) dudy = dudx, dvdy = dvdx;
    const float lod = hx || hy ? textureLod(dudx, dvdx, dudy, dvdy) : -1000.0f;
    const float q = divisor(span.coord[3][here]);
    float tex[4];
    sampleTexture(unit, span.coord[0][here] / q, span.coord[1][here] / q, lod, tex);
    float f[4], out[4];
    for (int k = 0; k < 4; ++k) f[k] = std::clamp(c[k][skip + i], 0.0f, 1.0f);
    textureEnvironment(unit, f, tex, out);
    for (int k = 0; k < 4; ++k) c[k][skip + i] = out[k];
  }
}

}  // namespace pf
