// Texturing's parts against hand-computed and double-precision references: GL's level of detail,
// texel fetch with every wrap mode and both filters (raster/texture_sampling.cpp), the choice and
// blend of mipmap levels, the environment's equations, the conversion of client images in and
// out (api/src/pixel_transfer.cpp); and through the API, a texture drawn texel for texel and the
// level a minified quad samples.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

#include "api/src/context_state.h"
#include "api/src/pixel_transfer.h"
#include "gl_context.h"
#include "raster/texture.h"

namespace {

// A w x h level whose texel (i, j) is (i * 40 + 10, j * 40 + 20, (i + j) * 15, 255 - i * 30).
std::shared_ptr<pf::TextureLevel> level(int w, int h) {
  auto l = std::make_shared<pf::TextureLevel>();
  l->width = w;
  l->height = h;
  l->texels.resize(size_t(w) * h * 4);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      uint8_t* p = &l->texels[(size_t(j) * w + i) * 4];
      p[0] = uint8_t(i * 40 + 10), p[1] = uint8_t(j * 40 + 20), p[2] = uint8_t((i + j) * 15), p[3] = uint8_t(255 - i * 30);
    }
  return l;
}

std::shared_ptr<pf::TextureLevel> flat(int w, int h, uint8_t r, uint8_t g, uint8_t b) {
  auto l = std::make_shared<pf::TextureLevel>();
  l->width = w, l->height = h;
  l->texels.resize(size_t(w) * h * 4, 255);
  for (size_t k = 0; k < l->texels.size(); k += 4) l->texels[k] = r, l->texels[k + 1] = g, l->texels[k + 2] = b;
  return l;
}

// The reference: GL 1.5 section 3.8.8 in double, written from the equations (3.19-3.21).
double refTexel(const pf::TextureUnit& u, int i, int j, int c) {
  const pf::TextureLevel& l = *u.levels[0];
  if (i < 0 || j < 0 || i >= l.width || j >= l.height) return u.border[c];
  return l.texels[(size_t(j) * l.width + i) * 4 + c] / 255.0;
}
int refWrap(GLenum wrap, long i, int size) {
  if (wrap == GL_REPEAT) return int(((i % size) + size) % size);
  if (wrap == GL_CLAMP_TO_EDGE) return int(std::min<long>(std::max<long>(i, 0), size - 1));
  return i < 0 || i >= size ? -1 : int(i);  // GL_CLAMP: the border
}
double refSample(const pf::TextureUnit& u, double s, double t, bool linear, int c) {
  const pf::TextureLevel& l = *u.levels[0];
  if (u.wrap_s == GL_CLAMP) s = std::min(std::max(s, 0.0), 1.0);
  if (u.wrap_t == GL_CLAMP) t = std::min(std::max(t, 0.0), 1.0);
  const double x = s * l.width, y = t * l.height;
  if (!linear) {
    long i = long(std::floor(x)), j = long(std::floor(y));
    if (u.wrap_s != GL_REPEAT) i = std::min<long>(std::max<long>(i, 0), l.width - 1);
    if (u.wrap_t != GL_REPEAT) j = std::min<long>(std::max<long>(j, 0), l.height - 1);
    return refTexel(u, refWrap(u.wrap_s, i, l.width), refWrap(u.wrap_t, j, l.height), c);
  }
  const long i0 = long(std::floor(x - 0.5)), j0 = long(std::floor(y - 0.5));
  const double a = (x - 0.5) - std::floor(x - 0.5), b = (y - 0.5) - std::floor(y - 0.5);
  auto T = [&](long i, long j) { return refTexel(u, refWrap(u.wrap_s, i, l.width), refWrap(u.wrap_t, j, l.height), c); };
  return (1 - a) * (1 - b) * T(i0, j0) + a * (1 - b) * T(i0 + 1, j0) + (1 - a) * b * T(i0, j0 + 1) + a * b * T(i0 + 1, j0 + 1);
}

}  // namespace

TEST(TextureLod, IsLog2OfTheLongerDerivativeVector) {
  EXPECT_FLOAT_EQ(pf::textureLod(2, 0, 0, 2), 1.0f);
  EXPECT_FLOAT_EQ(pf::textureLod(3, 4, 0, 1), static_cast<float>(std::log2(5.0)));
  EXPECT_FLOAT_EQ(pf::textureLod(0.5f, 0, 0, 0.25f), -1.0f);
  EXPECT_FLOAT_EQ(pf::textureLod(0, 0, 6, 8), static_cast<float>(std::log2(10.0)));
  EXPECT_LT(pf::textureLod(0, 0, 0, 0), -100.0f);  // no footprint: magnified
  EXPECT_LT(pf::textureLod(NAN, 0, 0, 0), -100.0f);
}

TEST(TextureSampling, EveryWrapAndFilterMatchesTheDoubleReference) {
  pf::TextureUnit u;
  u.levels = {level(5, 4)};  // not a power of two: llvmpipe's textures need not be
  u.min_filter = GL_LINEAR;
  const float border[4] = {0.25f, 0.5f, 0.75f, 1.0f};
  std::copy(border, border + 4, u.border);
  int checked = 0;
  for (GLenum ws : {GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE})
    for (GLenum wt : {GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE})
      for (bool linear : {false, true}) {
        u.wrap_s = ws, u.wrap_t = wt;
        u.mag_filter = linear ? GL_LINEAR : GL_NEAREST;
        for (int k = 0; k < 400; ++k) {
          // Coordinates from -1.6 to 2.4, off the texel boundaries and centres.
          const float s = -1.6f + 4.0f * ((k * 37) % 400) / 400.0f + 0.0013f;
          const float t = -1.6f + 4.0f * ((k * 91) % 400) / 400.0f + 0.0029f;
          float got[4];
          pf::sampleTexture(u, s, t, -5.0f, got);  // magnified
          for (int c = 0; c < 4; ++c) {
            EXPECT_NEAR(got[c], refSample(u, s, t, linear, c), 2e-6) << s << ", " << t << " wraps " << ws << " " << wt;
            ++checked;
          }
        }
      }
  EXPECT_EQ(checked, 9 * 2 * 400 * 4);
}

// Coordinates that are not numbers, infinite or past any texel sample something, never outside
// the level: every wrap, both filters, any level of detail.
TEST(TextureSampling, ExtremeCoordinatesStayInsideTheLevel) {
  pf::TextureUnit u;
  u.levels = {level(5, 3), level(2, 1), level(1, 1)};
  const float extremes[] = {NAN, INFINITY, -INFINITY, 3e38f, -3e38f, 1e30f, 16777217.0f, -0.0f};
  for (GLenum wrap : {GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT})
    for (GLenum filter : {GL_NEAREST, GL_LINEAR_MIPMAP_LINEAR})
      for (float s : extremes)
        for (float lod : {NAN, -INFINITY, 0.3f, 7.0f, INFINITY}) {
          u.wrap_s = u.wrap_t = wrap;
          u.min_filter = filter;
          float c[4] = {-1, -1, -1, -1};
          pf::sampleTexture(u, s, -s, lod, c);
          for (float v : c) EXPECT_TRUE(v >= 0.0f && v <= 1.0f) << s << " " << lod << " wrap " << wrap;
        }
}

TEST(TextureSampling, MipmapLevelsAreChosenAndBlendedAsGlSays) {
  pf::TextureUnit u;
  u.levels = {flat(8, 8, 200, 0, 0), flat(4, 4, 0, 100, 0), flat(2, 2, 0, 0, 50), flat(1, 1, 10, 10, 10)};
  u.mag_filter = GL_LINEAR;
  float c[4];
  // NEAREST_MIPMAP_NEAREST: level ceil(lambda + 1/2) - 1; magnified up to lambda = 1/2 (c = 0.5
  // with a linear magnification filter).
  u.min_filter = GL_NEAREST_MIPMAP_NEAREST;
  pf::sampleTexture(u, 0.3f, 0.3f, 0.4f, c);
  EXPECT_FLOAT_EQ(c[0], 200 / 255.0f);
  pf::sampleTexture(u, 0.3f, 0.3f, 1.4f, c);
  EXPECT_FLOAT_EQ(c[1], 100 / 255.0f);
  pf::sampleTexture(u, 0.3f, 0.3f, 1.6f, c);
  EXPECT_FLOAT_EQ(c[2], 50 / 255.0f);
  pf::sampleTexture(u, 0.3f, 0.3f, 9.0f, c);  // past the last level: the last
  EXPECT_FLOAT_EQ(c[0], 10 / 255.0f);
  // LINEAR_MIPMAP_LINEAR: levels floor(lambda) and the next, weighted by the fraction.
  u.min_filter = GL_LINEAR_MIPMAP_LINEAR;
  pf::sampleTexture(u, 0.3f, 0.3f, 1.25f, c);
  EXPECT_NEAR(c[1], 0.75 * 100 / 255.0, 1e-6);
  EXPECT_NEAR(c[2], 0.25 * 50 / 255.0, 1e-6);
  pf::sampleTexture(u, 0.3f, 0.3f, 0.25f, c);  // minified (c = 0): levels 0 and 1
  EXPECT_NEAR(c[0], 0.75 * 200 / 255.0, 1e-6);
  EXPECT_NEAR(c[1], 0.25 * 100 / 255.0, 1e-6);
  // GL_TEXTURE_MIN_LOD / MAX_LOD clamp lambda.
  u.max_lod = 1.0f;
  pf::sampleTexture(u, 0.3f, 0.3f, 3.0f, c);
  EXPECT_FLOAT_EQ(c[1], 100 / 255.0f);
  // Without mipmaps the base level, whatever lambda is.
  u.max_lod = 1000.0f;
  u.min_filter = GL_NEAREST;
  pf::sampleTexture(u, 0.3f, 0.3f, 3.0f, c);
  EXPECT_FLOAT_EQ(c[0], 200 / 255.0f);
}

TEST(TextureEnvironment, FollowsGlTables) {
  pf::TextureUnit u;
  const float f[4] = {0.5f, 0.25f, 1.0f, 0.5f}, t[4] = {0.2f, 0.4f, 0.8f, 0.6f};
  const float cc[4] = {1.0f, 0.0f, 0.5f, 0.25f};
  std::copy(cc, cc + 4, u.env_color);
  float o[4];
  auto check = [&](pf::TextureBase base, GLenum mode, std::initializer_list<float> want) {
    u.base = base;
    u.env_mode = mode;
    pf::textureEnvironment(u, f, t, o);
    int k = 0;
    for (float w : want) EXPECT_NEAR(o[k++], w, 1e-6) << int(base) << " " << mode << " component " << k - 1;
  };
  check(pf::TextureBase::Rgba, GL_MODULATE, {0.1f, 0.1f, 0.8f, 0.3f});
  check(pf::TextureBase::Rgb, GL_MODULATE, {0.1f, 0.1f, 0.8f, 0.5f});
  check(pf::TextureBase::Alpha, GL_MODULATE, {0.5f, 0.25f, 1.0f, 0.3f});
  check(pf::TextureBase::Rgba, GL_DECAL, {0.5f * 0.4f + 0.2f * 0.6f, 0.25f * 0.4f + 0.4f * 0.6f, 0.4f + 0.8f * 0.6f, 0.5f});
  check(pf::TextureBase::Rgb, GL_REPLACE, {0.2f, 0.4f, 0.8f, 0.5f});
  check(pf::TextureBase::LuminanceAlpha, GL_REPLACE, {0.2f, 0.4f, 0.8f, 0.6f});  // (luminance stored in r, g, b)
  check(pf::TextureBase::Rgb, GL_BLEND, {0.5f * 0.8f + 0.2f, 0.25f * 0.6f, 1.0f * 0.2f + 0.5f * 0.8f, 0.5f});
  check(pf::TextureBase::Intensity, GL_BLEND, {0.5f * 0.8f + 0.2f, 0.25f * 0.6f, 1.0f * 0.2f + 0.5f * 0.8f, 0.5f * 0.4f + 0.25f * 0.6f});
  check(pf::TextureBase::Rgba, GL_ADD, {0.7f, 0.65f, 1.0f, 0.3f});  // clamped to 1
  check(pf::TextureBase::Intensity, GL_ADD, {0.7f, 0.65f, 1.0f, 1.0f});
}

TEST(PixelTransfer, UnpacksPackedAndSignedTypesUnderTheStoreModes) {
  pf::PixelStore store;
  store.alignment = 1;
  float rgba[8];
  const uint16_t rgb565 = 0xF81F;  // red 31, green 0, blue 31
  pf::unpackColors(store, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 1, 1, &rgb565, rgba);
  EXPECT_FLOAT_EQ(rgba[0], 1.0f);
  EXPECT_FLOAT_EQ(rgba[1], 0.0f);
  EXPECT_FLOAT_EQ(rgba[2], 1.0f);
  EXPECT_FLOAT_EQ(rgba[3], 1.0f);
  const uint16_t rgba4444 = 0x1234;
  pf::unpackColors(store, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, 1, 1, &rgba4444, rgba);
  for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(rgba[k], float((k + 1) / 15.0));
  store.swap_bytes = true;  // the short's bytes reversed first: 0x3412
  pf::unpackColors(store, GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4, 1, 1, &rgba4444, rgba);
  EXPECT_FLOAT_EQ(rgba[2], 3 / 15.0f);  // BGRA: the first field is blue
  EXPECT_FLOAT_EQ(rgba[0], 1 / 15.0f);
  store.swap_bytes = false;
  const int8_t signed_la[2] = {-128, 127};
  pf::unpackColors(store, GL_LUMINANCE_ALPHA, GL_BYTE, 1, 1, signed_la, rgba);
  EXPECT_FLOAT_EQ(rgba[0], -1.0f);
  EXPECT_FLOAT_EQ(rgba[1], -1.0f);
  EXPECT_FLOAT_EQ(rgba[3], 1.0f);
  // Row length, skips and alignment: a 2 x 2 image inside 3-pixel rows padded to 4 bytes.
  store.alignment = 4;
  store.row_length = 3;
  store.skip_rows = 1;
  store.skip_pixels = 1;
  const uint8_t lum[16] = {0, 1, 2, 0, 3, 4, 5, 0, 6, 7, 8, 0, 9, 10, 11, 0};
  float four[16];
  pf::unpackColors(store, GL_LUMINANCE, GL_UNSIGNED_BYTE, 2, 2, lum, four);
  EXPECT_FLOAT_EQ(four[0], 4 / 255.0f);
  EXPECT_FLOAT_EQ(four[4], 5 / 255.0f);
  EXPECT_FLOAT_EQ(four[8], 7 / 255.0f);
  EXPECT_FLOAT_EQ(four[12], 8 / 255.0f);
  const pf::ImageLayout layout = pf::imageLayout(store, GL_LUMINANCE, GL_UNSIGNED_BYTE, 2);
  EXPECT_EQ(layout.row_bytes, 4u);
  EXPECT_EQ(layout.offset, 5u);
  // Formats and types GL refuses.
  EXPECT_EQ(pf::checkColorFormatAndType(GL_RGBA, GL_UNSIGNED_SHORT_5_6_5), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(pf::checkColorFormatAndType(GL_RGB, GL_UNSIGNED_INT_8_8_8_8), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(pf::checkColorFormatAndType(GL_RGBA, GL_BITMAP), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(pf::checkColorFormatAndType(0x1234, GL_UNSIGNED_BYTE), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(pf::checkColorFormatAndType(GL_BGR, GL_FLOAT), GLenum(GL_NO_ERROR));
}

TEST(PixelTransfer, PacksWhatItUnpacks) {
  pf::PixelStore store;
  const float in[8] = {1.0f, 0.5f, 0.0f, 0.25f, 0.2f, 0.4f, 0.6f, 0.8f};
  for (GLenum type : {GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT, GL_FLOAT, GL_UNSIGNED_INT_10_10_10_2}) {
    uint8_t bytes[64] = {};
    pf::packColors(store, GL_RGBA, type, 2, 1, in, bytes);
    float back[8];
    pf::unpackColors(store, GL_RGBA, type, 2, 1, bytes, back);
    const double step = type == GL_UNSIGNED_BYTE ? 1 / 255.0 : type == GL_UNSIGNED_INT_10_10_10_2 ? 1 / 3.0 : 1 / 65535.0;
    for (int k = 0; k < 8; ++k) EXPECT_NEAR(back[k], in[k], step / 2 + 1e-7) << "type " << type << " " << k;
  }
}

// Through the API: a 2 x 2 texture over a 16 x 16 quad with GL_NEAREST and GL_REPLACE shows each
// texel on its quarter, exactly; a quad whose texture is minified 4 times samples level 2.
TEST(TexturedDraw, NearestTexelsAndTheMinifiedLevel) {
  pf::test::GlContext c(16, 16);
  pfglMatrixMode(GL_PROJECTION);
  pfglOrtho(0, 16, 0, 16, -1, 1);
  pfglMatrixMode(GL_MODELVIEW);
  const GLubyte texels[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 0, 255};
  GLuint t;
  pfglGenTextures(1, &t);
  pfglBindTexture(GL_TEXTURE_2D, t);
  pfglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  pfglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  pfglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  pfglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  pfglEnable(GL_TEXTURE_2D);
  pfglBegin(GL_QUADS);
  pfglTexCoord2f(0, 0); pfglVertex2f(0, 0);
  pfglTexCoord2f(1, 0); pfglVertex2f(16, 0);
  pfglTexCoord2f(1, 1); pfglVertex2f(16, 16);
  pfglTexCoord2f(0, 1); pfglVertex2f(0, 16);
  pfglEnd();
  pfglFinish();
  EXPECT_EQ(pfglGetError(), GLenum(GL_NO_ERROR));
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const GLubyte* want = texels + ((y / 8) * 2 + x / 8) * 4;
      ASSERT_EQ(0, std::memcmp(c.at(x, y), want, 4)) << x << ", " << y;
    }
  // Levels of a 64 x 64 texture, one colour each; the quad shows it 16 pixels wide: lambda = 2.
  std::vector<GLubyte> img;
  for (int lvl = 0, size = 64; size >= 1; ++lvl, size /= 2) {
    img.assign(size_t(size) * size * 4, 0);
    for (int k = 0; k < size * size; ++k) img[size_t(k) * 4] = GLubyte(lvl * 40), img[size_t(k) * 4 + 3] = 255;
    pfglTexImage2D(GL_TEXTURE_2D, lvl, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  }
  pfglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  pfglBegin(GL_QUADS);
  pfglTexCoord2f(0, 0); pfglVertex2f(0, 0);
  pfglTexCoord2f(1, 0); pfglVertex2f(16, 0);
  pfglTexCoord2f(1, 1); pfglVertex2f(16, 16);
  pfglTexCoord2f(0, 1); pfglVertex2f(0, 16);
  pfglEnd();
  pfglFinish();
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) ASSERT_EQ(c.at(x, y)[0], 80) << x << ", " << y;
  pfglDeleteTextures(1, &t);
}

// An incomplete mipmap chain turns texturing off for the draw (GL 1.5 section 3.8.10).
TEST(TexturedDraw, IncompleteTextureDrawsUntextured) {
  pf::test::GlContext c(8, 8);
  pfglMatrixMode(GL_PROJECTION);
  pfglOrtho(0, 8, 0, 8, -1, 1);
  pfglMatrixMode(GL_MODELVIEW);
  const GLubyte texel[4] = {10, 20, 30, 255};
  pfglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  pfglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);  // level 1 missing
  pfglEnable(GL_TEXTURE_2D);
  pfglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  pfglColor3f(0.0f, 1.0f, 0.0f);
  pfglRectf(0, 0, 8, 8);
  pfglFinish();
  EXPECT_EQ(c.at(4, 4)[1], 255);
  pfglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // now complete: zeros
  pfglRectf(0, 0, 8, 8);
  pfglFinish();
  EXPECT_EQ(c.at(4, 4)[1], 0);
}

// The exact sphere, textured by its own spherical coordinates (the `spherical` interpolator bound
// to "texcoord"): each pixel shows the texel a double-precision ray cast says -- the ray through
// the pixel centre, its first hit, u = atan2(y, x) / 2 pi + 1/2, v = acos(z / r) / pi about the
// centre. Pixels within 1/500 texel of a texel edge (either side may round there) and grazing
// rays are left out; every other covered pixel must match exactly.
TEST(TexturedDraw, ExactSphereShowsTheTexelsOfItsSphericalCoordinates) {
  constexpr int kN = 128, kT = 8;
  pf::test::GlContext c(kN, kN);
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-1, 1, -1, 1, 2, 10);
  pfglMatrixMode(GL_MODELVIEW);
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  std::vector<GLubyte> img(kT * kT * 4);
  for (int j = 0; j < kT; ++j)
    for (int i = 0; i < kT; ++i) {
      GLubyte* p = &img[size_t(j * kT + i) * 4];
      p[0] = GLubyte(16 + i * 30), p[1] = GLubyte(16 + j * 30), p[2] = GLubyte(((i + j) & 1) * 200 + 20), p[3] = 255;
    }
  pfglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  pfglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  pfglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, kT, kT, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  pfglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  pfglEnable(GL_TEXTURE_2D);
  const GLenum sphere = pfglGetPrimitiveEXT("sphere");
  pfglMaterialInterpEXT(pfglGetParamNameEXT("texcoord"), sphere, pfglGetInterpolatorEXT("spherical"));
  const double cz = -5.0, r = 1.5;
  pfglBegin(sphere);
  pfglRastParam3fEXT(pfglGetParamNameEXT("center"), 0.0f, 0.0f, float(cz));
  pfglRastParamfEXT(pfglGetParamNameEXT("radius"), float(r));
  pfglRastParam3fEXT(pfglGetParamNameEXT("texture_origin"), 0.0f, 0.0f, 0.0f);  // (the interpolator's; the
  pfglRastParamfEXT(pfglGetParamNameEXT("texture_scale"), 1.0f);               // sphere's own ignores them)
  pfglSequencePointEXT();
  pfglEnd();
  pfglFinish();
  ASSERT_EQ(pfglGetError(), GLenum(GL_NO_ERROR));
  const double pi = 3.14159265358979323846;
  int checked = 0, wrong = 0;
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      // The ray from the eye through the pixel centre on the near plane (z = -2).
      const double dx = (x + 0.5) / (kN / 2.0) - 1.0, dy = (y + 0.5) / (kN / 2.0) - 1.0, dz = -2.0;
      const double a = dx * dx + dy * dy + dz * dz, b = -2.0 * dz * cz, cc = cz * cz - r * r;
      const double disc = b * b - 4 * a * cc;
      if (disc < 0.02 * b * b) continue;  // off the sphere, or grazing it
      const double t = (-b - std::sqrt(disc)) / (2 * a);
      const double qx = t * dx, qy = t * dy, qz = t * dz - cz;
      const double u = (std::atan2(qy, qx) / (2 * pi) + 0.5) * kT, v = std::acos(qz / r) / pi * kT;
      const double fu = u - std::floor(u), fv = v - std::floor(v);
      if (fu < 0.002 || fu > 0.998 || fv < 0.002 || fv > 0.998) continue;
      const int i = int(std::floor(u)) % kT, j = std::min(int(std::floor(v)), kT - 1);
      ++checked;
      if (std::memcmp(c.at(x, y), &img[size_t(j * kT + i) * 4], 4) != 0) ++wrong;
    }
  EXPECT_GT(checked, 3000);
  EXPECT_EQ(wrong, 0) << "of " << checked;
}
